#include "StepLessonView.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>

#include "LessonView.h"
#include "core/GranularityLesson.h"
#include "core/lod/LodLesson.h"

namespace conescope {

StepLessonView::StepLessonView(const QString& objectName, const QString& whatsThis, const QString& emptyTitle,
                               const QString& emptyText, QWidget* parent)
    : QWidget(parent), emptyTitle_(emptyTitle), emptyText_(emptyText) {
    setObjectName(objectName);
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
    setWhatsThis(whatsThis);
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
    showNone();
}

void StepLessonView::showSteps(const std::vector<LessonStep>& steps, const QString& subject) {
    steps_ = steps;
    subject_ = subject;
    step_ = 0;
    if (!showStep(1)) showNone();
}

void StepLessonView::showNone(const QString& why) {
    steps_.clear();
    step_ = 0;
    title_->setText(emptyTitle_);
    progress_->clear();
    text_->setPlainText(why.isEmpty() ? emptyText_ : why);
    back_->setEnabled(false);
    next_->setEnabled(false);
}

bool StepLessonView::showStep(int step) {
    if (step < 1 || step > int(steps_.size())) return false;
    step_ = step;
    const LessonStep& shown = steps_[size_t(step - 1)];
    title_->setText(tr("%1. %2").arg(step).arg(QString::fromStdString(shown.title)));
    QString dots;
    for (int i = 1; i <= int(steps_.size()); ++i) dots += i == step ? QStringLiteral("\u25cf") : QStringLiteral("\u25cb");
    progress_->setText(tr("%1  \u2014  step %2 of %3  %4").arg(subject_).arg(step).arg(steps_.size()).arg(dots));
    text_->setPlainText(QString::fromStdString(shown.text));
    back_->setEnabled(step > 1);
    next_->setEnabled(step < int(steps_.size()));
    return true;
}

QString StepLessonView::title() const { return title_->text(); }
QString StepLessonView::text() const { return text_->toPlainText(); }

StepLessonView* makeLodLessonView(QWidget* parent) {
    return new StepLessonView(
        QStringLiteral("lodLessonView"),
        StepLessonView::tr("Why coarse clusters cull less, in %1 steps with the numbers of the hierarchy built: how much surface a "
                           "cluster covers at level 0 and at a coarser level, how wide their cones open, what the cones predict "
                           "and what the test culled, and what the cut an engine draws keeps of cone culling.")
            .arg(kLodLessonStepCount),
        StepLessonView::tr("Why coarse clusters cull less"),
        StepLessonView::tr("Build the LOD hierarchy to see, with its own numbers, why the clusters of its coarser levels "
                           "cull less than level 0's."),
        parent);
}

void showLodLesson(StepLessonView& view, const LodLesson* lesson) {
    if (!lesson) return view.showNone();
    view.showSteps(lesson->steps, StepLessonView::tr("Level 0 and level %1 of %2")
                                      .arg(lesson->coarse.level)
                                      .arg(QString::fromStdString(lesson->meshName)));
}

void showLodStatistics(StepLessonView& view, const LodStatistics* statistics, const std::string& meshName) {
    if (statistics && statistics->levels.size() >= 2) {
        const LodLesson lesson = makeLodLesson(*statistics, meshName);
        return showLodLesson(view, &lesson);
    }
    if (statistics)
        return view.showNone(StepLessonView::tr("This hierarchy has a single level: simplification stopped before making a "
                                                "coarser one, so there is nothing to compare level 0 with."));
    view.showNone();
}

StepLessonView* makeGranularityLessonView(QWidget* parent) {
    return new StepLessonView(
        QStringLiteral("granularityLessonView"),
        StepLessonView::tr("Why more cones per cluster cull more and what they cost, in %1 steps with the numbers of the "
                           "granularity measured: what one cone loses to the partition, how 2, 4 and 8 cones narrow the "
                           "cones, the culled share against the bytes of each record, and per-triangle culling as the ceiling.")
            .arg(kGranularityLessonStepCount),
        StepLessonView::tr("Why more cones cull more, and what they cost"),
        StepLessonView::tr("Measure the granularity (Granularity dock) to see, with this mesh's own numbers, what 2, 4 and 8 "
                           "cones per cluster and per-triangle culling cull, and what they cost."),
        parent);
}

void showGranularityLesson(StepLessonView& view, const GranularityReport* report) {
    if (!report) return view.showNone();
    const GranularityLesson lesson = makeGranularityLesson(*report);
    view.showSteps(lesson.steps, QString::fromStdString(lesson.meshName));
}

}  // namespace conescope
