// The lesson dock: the picked cluster's lesson (core makeLesson, through the session), one step at a
// time, its title and its sentences with the live numbers; one-click examples (a culled cluster, a
// drawn one, one lost to the test, one lost to the partition), the eye swept across the cull boundary,
// Back and Next. Every control stays where it is from step to step (nothing appears or goes), so
// Next never moves under the pointer. It only shows the session's lesson and asks for things; the
// session and the window do the rest.
#pragma once

#include <vector>

#include <QWidget>

#include "core/LessonData.h"

class QLabel;
class QToolButton;
class QTextBrowser;

namespace conescope {

class Session;

// What the lesson docks share: a bold, slightly larger title that wraps, and a text pane that follows no link.
QLabel* makeLessonTitle(QWidget* parent);
QTextBrowser* makeLessonText(QWidget* parent);

class LessonView : public QWidget {
    Q_OBJECT
public:
    explicit LessonView(QWidget* parent = nullptr);

    // The session's lesson step and lesson (or what to do to have one).
    void showLesson(const Session& session);
    // The sweep button says Stop while the eye is being swept.
    void showSweeping(bool sweeping);
    // What the dock says now (its title and text), for tests.
    QString title() const;
    QString text() const;
    QToolButton* nextButton() const { return next_; }
    QToolButton* backButton() const { return back_; }
    QToolButton* sweepButton() const { return sweep_; }
    // The button that chooses an example of `outcome` (culled, visible, lost to the test or the partition).
    QToolButton* exampleButton(LessonOutcome outcome) const;

signals:
    // A step to show: 1 to kLessonStepCount, 0 ends the lesson.
    void stepRequested(int step);
    // Pick a cluster that shows `outcome` and put the eye where it does.
    void exampleRequested(conescope::LessonOutcome outcome);
    // Sweep the eye across the picked cluster's cull boundary (or stop the sweep).
    void sweepRequested();

private:
    QLabel* title_ = nullptr;
    QLabel* progress_ = nullptr;
    QTextBrowser* text_ = nullptr;
    QToolButton* back_ = nullptr;
    QToolButton* next_ = nullptr;
    QToolButton* startOrEnd_ = nullptr;
    QToolButton* sweep_ = nullptr;
    std::vector<std::pair<LessonOutcome, QToolButton*>> examples_;
    bool sweeping_ = false;
    int step_ = 0;
};

}  // namespace conescope
