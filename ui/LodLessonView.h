// The lesson on why coarse clusters cull less (core makeLodLesson), one step at a time with Back and
// Next: the numbers of the hierarchy it was made from, level 0 beside a coarser level and the cut. It
// keeps its own copy of the lesson and its step; the window gives it a lesson whenever the hierarchy's
// statistics change, or none.
#pragma once

#include <optional>
#include <string>

#include <QWidget>

#include "core/lod/LodLesson.h"

class QLabel;
class QTextBrowser;
class QToolButton;

namespace conescope {

class LodLessonView : public QWidget {
    Q_OBJECT
public:
    explicit LodLessonView(QWidget* parent = nullptr);

    // The lesson to show from its first step; null: what to do to have one.
    void showLesson(const LodLesson* lesson);
    // The lesson of a hierarchy's statistics (makeLodLesson, level 0 beside its default coarser level)
    // from its first step; null, or a single level, says what it needs instead.
    void showStatistics(const LodStatistics* statistics, const std::string& meshName);
    // Step 1 to kLodLessonStepCount; false (and nothing changes) outside them or without a lesson.
    bool showStep(int step);
    int step() const { return step_; }
    // What it says now, for tests.
    QString title() const;
    QString text() const;
    QToolButton* nextButton() const { return next_; }
    QToolButton* backButton() const { return back_; }

private:
    std::optional<LodLesson> lesson_;
    int step_ = 0;
    QLabel* title_ = nullptr;
    QLabel* progress_ = nullptr;
    QTextBrowser* text_ = nullptr;
    QToolButton* back_ = nullptr;
    QToolButton* next_ = nullptr;
};

}  // namespace conescope
