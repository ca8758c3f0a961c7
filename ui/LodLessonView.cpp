#include "LodLessonView.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

#include "LessonView.h"

namespace conescope {

LodLessonView::LodLessonView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("lodLessonView"));
    title_ = makeLessonTitle(this);
    progress_ = new QLabel(this);
    text_ = makeLessonText(this);
    const auto button = [this](const QString& text, const QString& tip) {
        auto* made = new QToolButton(this);
        made->setText(text);
        made->setToolTip(tip);
        made->setToolButtonStyle(Qt::ToolButtonTextOnly);
        return made;
    };
    back_ = button(tr("\u25c0 Back"), tr("The step before"));
    next_ = button(tr("Next \u25b6"), tr("The next step"));
    setWhatsThis(tr("Why coarse clusters cull less, in %1 steps with the numbers of the hierarchy built: how much surface a "
                    "cluster covers at level 0 and at a coarser level, how wide their cones open, what the cones predict "
                    "and what the test culled, and what the cut an engine draws keeps of cone culling.")
                     .arg(kLodLessonStepCount));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(back_);
    buttons->addWidget(next_);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(title_);
    layout->addWidget(progress_);
    layout->addWidget(text_, 1);
    layout->addLayout(buttons);
    connect(back_, &QToolButton::clicked, this, [this]() { showStep(step_ - 1); });
    connect(next_, &QToolButton::clicked, this, [this]() { showStep(step_ + 1); });
    showLesson(nullptr);
}

void LodLessonView::showLesson(const LodLesson* lesson) {
    if (lesson) lesson_ = *lesson;
    else lesson_.reset();
    step_ = 0;
    if (lesson_ && showStep(1)) return;
    title_->setText(tr("Why coarse clusters cull less"));
    progress_->clear();
    text_->setPlainText(tr("Build the LOD hierarchy to see, with its own numbers, why the clusters of its coarser levels "
                           "cull less than level 0's."));
    back_->setEnabled(false);
    next_->setEnabled(false);
}

void LodLessonView::showStatistics(const LodStatistics* statistics, const std::string& meshName) {
    if (statistics && statistics->levels.size() >= 2) {
        const LodLesson lesson = makeLodLesson(*statistics, meshName);
        showLesson(&lesson);
        return;
    }
    showLesson(nullptr);
    if (statistics)
        text_->setPlainText(tr("This hierarchy has a single level: simplification stopped before making a coarser one, so there "
                               "is nothing to compare level 0 with."));
}

bool LodLessonView::showStep(int step) {
    if (!lesson_ || step < 1 || step > int(lesson_->steps.size())) return false;
    step_ = step;
    const LessonStep& shown = lesson_->steps[size_t(step - 1)];
    title_->setText(tr("%1. %2").arg(step).arg(QString::fromStdString(shown.title)));
    QString dots;
    for (int i = 1; i <= int(lesson_->steps.size()); ++i) dots += i == step ? QStringLiteral("\u25cf") : QStringLiteral("\u25cb");
    progress_->setText(tr("Level 0 and level %1 of %2  \u2014  step %3 of %4  %5")
                           .arg(lesson_->coarse.level)
                           .arg(QString::fromStdString(lesson_->meshName))
                           .arg(step)
                           .arg(lesson_->steps.size())
                           .arg(dots));
    text_->setPlainText(QString::fromStdString(shown.text));
    back_->setEnabled(step > 1);
    next_->setEnabled(step < int(lesson_->steps.size()));
    return true;
}

QString LodLessonView::title() const { return title_->text(); }
QString LodLessonView::text() const { return text_->toPlainText(); }

}  // namespace conescope
