#include "LessonView.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "Session.h"
#include "core/Lesson.h"

namespace conescope {

namespace {

struct ExampleButton {
    LessonOutcome outcome;
    const char* text;
    const char* tip;
};

const ExampleButton exampleButtons[] = {
    {LessonOutcome::Culled, QT_TRANSLATE_NOOP("LessonView", "Culled"),
     QT_TRANSLATE_NOOP("LessonView", "Picks the cluster culled from the most orbit views and puts the eye where the test culls it "
                                     "with the most to spare: a cull to explain")},
    {LessonOutcome::Visible, QT_TRANSLATE_NOOP("LessonView", "Drawn"),
     QT_TRANSLATE_NOOP("LessonView", "Picks the same well-culled cluster and puts the eye in front of it, where every face turns "
                                     "to the eye: drawn, and nothing lost")},
    {LessonOutcome::LostToTest, QT_TRANSLATE_NOOP("LessonView", "Lost: test"),
     QT_TRANSLATE_NOOP("LessonView", "Picks the cluster whose back faces the test draws most often over the orbit, and puts the "
                                     "eye where every face turns away yet the test draws it: lost by the test (M)")},
    {LessonOutcome::LostToPartition, QT_TRANSLATE_NOOP("LessonView", "Lost: partition"),
     QT_TRANSLATE_NOOP("LessonView", "Picks the cluster that loses the most back faces to the partition, and puts the eye where "
                                     "it holds faces turned away and one turned to the eye: lost by the partition")},
};

}  // namespace

QLabel* makeLessonTitle(QWidget* parent) {
    auto* title = new QLabel(parent);
    title->setWordWrap(true);
    QFont bold = title->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.15);
    title->setFont(bold);
    return title;
}

QTextBrowser* makeLessonText(QWidget* parent) {
    auto* text = new QTextBrowser(parent);
    text->setOpenLinks(false);
    text->setMinimumHeight(60);
    return text;
}

LessonView::LessonView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("lessonView"));
    title_ = makeLessonTitle(this);
    progress_ = new QLabel(this);
    text_ = makeLessonText(this);
    text_->setObjectName(QStringLiteral("lessonText"));
    // Tool buttons: as wide as their words, so the dock leaves the 3D view its width on a small screen.
    const auto button = [this](const QString& text) {
        auto* made = new QToolButton(this);
        made->setText(text);
        made->setToolButtonStyle(Qt::ToolButtonTextOnly);
        made->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
        return made;
    };
    back_ = button(tr("\u25c0 Back"));
    next_ = button(tr("Next \u25b6"));
    startOrEnd_ = button(tr("End lesson"));
    sweep_ = button(tr("Sweep eye"));
    back_->setToolTip(tr("The step before (Page Up)"));
    next_->setToolTip(tr("The next step (Page Down)"));
    sweep_->setToolTip(tr("Moves the cull eye around the picked cluster, across the edge of the views its test culls from, "
                          "while the test's inequality (step 5) follows it: watch it flip"));
    const QString about = tr("The lesson walks through how the cull test decides on the picked cluster, in seven steps: its "
                             "faces and normals, the Gauss sphere, the cone, the bound, the eye and the test, the verdict, and "
                             "the cluster beside one the same eye sees decided the other way. Each step shows only what it talks "
                             "about; the numbers follow the eye.");
    for (QWidget* control : std::initializer_list<QWidget*>{back_, next_, startOrEnd_, text_}) control->setWhatsThis(about);
    sweep_->setWhatsThis(sweep_->toolTip() + tr(". The eye keeps its distance from the cluster and turns in the plane of the "
                                                "cone's axis V1 and the view vector; where the decision flips is the test's own."));
    auto* examples = new QHBoxLayout;
    examples->setSpacing(4);
    examples->addWidget(new QLabel(tr("Show:"), this));
    for (const ExampleButton& example : exampleButtons) {
        QToolButton* choice = button(tr(example.text));
        choice->setToolTip(tr(example.tip));
        choice->setWhatsThis(tr(example.tip) + tr(". One click picks the cluster, moves the eye and starts the lesson on it."));
        connect(choice, &QToolButton::clicked, this, [this, outcome = example.outcome]() { emit exampleRequested(outcome); });
        examples->addWidget(choice);
        examples_.emplace_back(example.outcome, choice);
    }
    examples->addStretch(1);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(back_);
    buttons->addWidget(next_);
    buttons->addWidget(sweep_);
    buttons->addStretch(1);
    buttons->addWidget(startOrEnd_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(title_);
    layout->addWidget(progress_);
    layout->addWidget(text_, 1);
    layout->addLayout(examples);
    layout->addLayout(buttons);
    connect(back_, &QToolButton::clicked, this, [this]() { emit stepRequested(step_ - 1); });
    connect(next_, &QToolButton::clicked, this, [this]() { emit stepRequested(step_ + 1); });
    connect(startOrEnd_, &QToolButton::clicked, this, [this]() { emit stepRequested(step_ > 0 ? 0 : 1); });
    connect(sweep_, &QToolButton::clicked, this, &LessonView::sweepRequested);
}

QToolButton* LessonView::exampleButton(LessonOutcome outcome) const {
    for (const auto& [shown, button] : examples_)
        if (shown == outcome) return button;
    return nullptr;
}

void LessonView::showSweeping(bool sweeping) {
    sweeping_ = sweeping;
    sweep_->setText(sweeping ? tr("Stop") : tr("Sweep eye"));
    if (sweeping) sweep_->setEnabled(true);
}

void LessonView::showLesson(const Session& session) {
    step_ = session.lessonStep();
    const Lesson* lesson = session.lesson();
    startOrEnd_->setText(step_ > 0 ? tr("End lesson") : tr("Start lesson"));
    startOrEnd_->setToolTip(step_ > 0 ? tr("Back to the layers and colours shown before the lesson (L)")
                                      : tr("Walk through the picked cluster's cull decision step by step (L)"));
    back_->setEnabled(step_ > 1);
    next_->setEnabled(step_ > 0 && step_ < kLessonStepCount);
    // Only a cluster with a cone has a boundary to sweep across.
    sweep_->setEnabled(sweeping_ || (lesson && lesson->why.cullable));
    for (const auto& [outcome, button] : examples_) button->setEnabled(session.orbitStatistics() != nullptr);
    if (!lesson) {
        title_->setText(tr("A lesson on one cluster"));
        progress_->clear();
        text_->setPlainText(tr("A lesson explains, in seven steps, how the cull test decides whether one cluster of faces can be "
                               "skipped from the cull eye. Click a cluster in the 3D view (without dragging) to choose it, or let "
                               "ConeScope show one: Culled, Drawn, or lost by the test or by the partition."));
        return;
    }
    if (step_ == 0) {
        title_->setText(tr("A lesson on cluster %1").arg(lesson->cluster));
        progress_->clear();
        text_->setPlainText(tr("Start the lesson (L) to see, in seven steps, why %1 %2 cluster %3 from the cull eye: its faces "
                               "and normals, the Gauss sphere, the cone, the bound, the eye and the test, the verdict, and the "
                               "cluster beside one decided the other way.")
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
