#include "GranularityLessonView.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

#include "LessonView.h"

namespace conescope {

GranularityLessonView::GranularityLessonView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("granularityLessonView"));
    title_ = makeLessonTitle(this);
    progress_ = new QLabel(this);
    text_ = makeLessonText(this);
    back_ = new QToolButton(this);
    back_->setText(tr("\u25c0 Back"));
    next_ = new QToolButton(this);
    next_->setText(tr("Next \u25b6"));
    setWhatsThis(tr("Why more cones per cluster cull more and what they cost, in %1 steps with the numbers of the granularity "
                    "measured: what one cone loses to the partition, how 2, 4 and 8 cones narrow the cones, the culled share "
                    "against the bytes of each record, and per-triangle culling as the ceiling.")
                     .arg(kGranularityLessonStepCount));
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
    showReport(nullptr);
}

void GranularityLessonView::showReport(const GranularityReport* report) {
    if (report) lesson_ = makeGranularityLesson(*report);
    else lesson_.reset();
    step_ = 0;
    if (lesson_ && showStep(1)) return;
    title_->setText(tr("Why more cones cull more, and what they cost"));
    progress_->clear();
    text_->setPlainText(tr("Measure the granularity (Granularity dock) to see, with this mesh's own numbers, what 2, 4 and 8 "
                           "cones per cluster and per-triangle culling cull, and what they cost."));
    back_->setEnabled(false);
    next_->setEnabled(false);
}

bool GranularityLessonView::showStep(int step) {
    if (!lesson_ || step < 1 || step > int(lesson_->steps.size())) return false;
    step_ = step;
    const LessonStep& shown = lesson_->steps[size_t(step - 1)];
    title_->setText(tr("%1. %2").arg(step).arg(QString::fromStdString(shown.title)));
    QString dots;
    for (int i = 1; i <= int(lesson_->steps.size()); ++i) dots += i == step ? QStringLiteral("\u25cf") : QStringLiteral("\u25cb");
    progress_->setText(tr("%1  \u2014  step %2 of %3  %4")
                           .arg(QString::fromStdString(lesson_->meshName))
                           .arg(step)
                           .arg(lesson_->steps.size())
                           .arg(dots));
    text_->setPlainText(QString::fromStdString(shown.text));
    back_->setEnabled(step > 1);
    next_->setEnabled(step < int(lesson_->steps.size()));
    return true;
}

QString GranularityLessonView::title() const { return title_->text(); }
QString GranularityLessonView::text() const { return text_->toPlainText(); }

}  // namespace conescope
