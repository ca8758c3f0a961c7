// A lesson told one step at a time with Back and Next: each step's title and text, and a progress line
// (what the lesson is about, the step, a dot per step). The LOD lesson (why coarse clusters cull less,
// core makeLodLesson) and the granularity lesson (what more cones per cluster cull and cost, core
// makeGranularityLesson) are both shown in one; what differs between them is data. The view keeps its
// own copy of the steps; the window gives it a lesson whenever the numbers behind it change, or none.
#pragma once

#include <string>
#include <vector>

#include <QWidget>

#include "core/LessonData.h"

class QLabel;
class QTextBrowser;
class QToolButton;

namespace conescope {

struct GranularityReport;
struct LodLesson;
struct LodStatistics;

class StepLessonView : public QWidget {
    Q_OBJECT
public:
    // What the view says with no lesson (`emptyTitle`, `emptyText`) and what it is for (its What's This).
    StepLessonView(const QString& objectName, const QString& whatsThis, const QString& emptyTitle, const QString& emptyText,
                   QWidget* parent = nullptr);

    // `steps` from the first; `subject` opens the progress line (the mesh, the levels compared).
    void showSteps(const std::vector<LessonStep>& steps, const QString& subject);
    // No lesson: the empty title, and `why` (the empty text when none).
    void showNone(const QString& why = {});
    // Step 1 to the number of steps; false (and nothing changes) outside them or without a lesson.
    bool showStep(int step);
    int step() const { return step_; }
    const std::vector<LessonStep>& steps() const { return steps_; }
    // What it says now, for tests.
    QString title() const;
    QString text() const;
    QToolButton* nextButton() const { return next_; }
    QToolButton* backButton() const { return back_; }

private:
    std::vector<LessonStep> steps_;
    QString subject_;
    QString emptyTitle_, emptyText_;
    int step_ = 0;
    QLabel* title_ = nullptr;
    QLabel* progress_ = nullptr;
    QTextBrowser* text_ = nullptr;
    QToolButton* back_ = nullptr;
    QToolButton* next_ = nullptr;
};

// The LOD lesson's view (object name lodLessonView), with no lesson yet.
StepLessonView* makeLodLessonView(QWidget* parent = nullptr);
// `lesson` from its first step; null: what to do to have one.
void showLodLesson(StepLessonView& view, const LodLesson* lesson);
// The lesson of a hierarchy's statistics (makeLodLesson, level 0 beside its default coarser level);
// null, or a single level, says what it needs instead.
void showLodStatistics(StepLessonView& view, const LodStatistics* statistics, const std::string& meshName);

// The granularity lesson's view (object name granularityLessonView), with no lesson yet.
StepLessonView* makeGranularityLessonView(QWidget* parent = nullptr);
// The lesson of `report` (makeGranularityLesson) from its first step; null says how to get one.
void showGranularityLesson(StepLessonView& view, const GranularityReport* report);

}  // namespace conescope
