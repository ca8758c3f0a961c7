#include "LessonView.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "Session.h"

namespace conescope {

LessonView::LessonView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("lessonView"));
    title_ = new QLabel(this);
    title_->setWordWrap(true);
    QFont bold = title_->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.15);
    title_->setFont(bold);
    progress_ = new QLabel(this);
    text_ = new QTextBrowser(this);
    text_->setObjectName(QStringLiteral("lessonText"));
    text_->setOpenLinks(false);
    text_->setMinimumHeight(60);
    back_ = new QPushButton(tr("\u25c0 Back"), this);
    next_ = new QPushButton(tr("Next \u25b6"), this);
    startOrEnd_ = new QPushButton(this);
    costliest_ = new QPushButton(tr("Pick the cluster the test loses most"), this);
    back_->setToolTip(tr("The step before (Page Up)"));
    next_->setToolTip(tr("The next step (Page Down)"));
    costliest_->setToolTip(tr("Picks the cluster whose back faces the test draws most often over the orbit, and puts the "
                              "cull eye where it draws them: the most instructive miss"));
    for (QWidget* control : std::initializer_list<QWidget*>{back_, next_, startOrEnd_, costliest_})
        control->setWhatsThis(tr("The lesson walks through how the cull test decides on the picked cluster, in six steps: "
                                 "its faces and normals, the Gauss sphere, the cone, the bound, the eye and the test, and "
                                 "the verdict. Each step shows only what it talks about; the numbers follow the eye."));
    text_->setWhatsThis(back_->whatsThis());
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(back_);
    buttons->addWidget(next_);
    buttons->addStretch(1);
    buttons->addWidget(startOrEnd_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(title_);
    layout->addWidget(progress_);
    layout->addWidget(text_, 1);
    layout->addWidget(costliest_);
    layout->addLayout(buttons);
    connect(back_, &QPushButton::clicked, this, [this]() { emit stepRequested(step_ - 1); });
    connect(next_, &QPushButton::clicked, this, [this]() { emit stepRequested(step_ + 1); });
    connect(startOrEnd_, &QPushButton::clicked, this, [this]() { emit stepRequested(step_ > 0 ? 0 : 1); });
    connect(costliest_, &QPushButton::clicked, this, &LessonView::costliestClusterRequested);
}

void LessonView::showLesson(const Session& session) {
    step_ = session.lessonStep();
    const Lesson* lesson = session.lesson();
    startOrEnd_->setText(step_ > 0 ? tr("End lesson") : tr("Start lesson"));
    startOrEnd_->setToolTip(step_ > 0 ? tr("Back to the layers and colours shown before the lesson (L)")
                                      : tr("Walk through the picked cluster's cull decision step by step (L)"));
    back_->setEnabled(step_ > 1);
    next_->setEnabled(step_ > 0 && step_ < kLessonStepCount);
    costliest_->setVisible(!lesson);
    costliest_->setEnabled(session.orbitStatistics() != nullptr);
    if (!lesson) {
        title_->setText(tr("A lesson on one cluster"));
        progress_->clear();
        text_->setPlainText(tr("A lesson explains, in six steps, how the cull test decides whether one cluster of faces can be "
                               "skipped from the cull eye. Click a cluster in the 3D view (without dragging) to choose it, or "
                               "let ConeScope pick the one the test loses most."));
        return;
    }
    if (step_ == 0) {
        title_->setText(tr("A lesson on cluster %1").arg(lesson->cluster));
        progress_->clear();
        text_->setPlainText(tr("Start the lesson (L) to see, in six steps, why %1 %2 cluster %3 from the cull eye: its faces "
                               "and normals, the Gauss sphere, the cone, the bound, the eye and the test, and the verdict.")
                                .arg(QString::fromStdString(testInWords(lesson->test)),
                                     lesson->why.culled ? tr("culls") : tr("draws"))
                                .arg(lesson->cluster));
        return;
    }
    const LessonStep& step = lesson->steps[size_t(step_ - 1)];
    title_->setText(tr("%1. %2").arg(step_).arg(QString::fromStdString(step.title)));
    QString dots;
    for (int i = 1; i <= kLessonStepCount; ++i) dots += i == step_ ? QStringLiteral("\u25cf") : QStringLiteral("\u25cb");
    progress_->setText(tr("Step %1 of %2  %3").arg(step_).arg(kLessonStepCount).arg(dots));
    text_->setPlainText(QString::fromStdString(step.text));
}

QString LessonView::title() const { return title_->text(); }
QString LessonView::text() const { return text_->toPlainText(); }

}  // namespace conescope
