// The lesson on why more cones per cluster cull more and what they cost (core makeGranularityLesson),
// one step at a time with Back and Next, with the numbers of the granularity report measured; the
// same text `conescope-cli granularity --write-lesson` writes.
#pragma once

#include <optional>

#include <QWidget>

#include "core/GranularityLesson.h"

class QLabel;
class QTextBrowser;
class QToolButton;

namespace conescope {

class GranularityLessonView : public QWidget {
    Q_OBJECT
public:
    explicit GranularityLessonView(QWidget* parent = nullptr);
    // The lesson of a report from its first step; null says how to get one.
    void showReport(const GranularityReport* report);
    // Step 1 to kGranularityLessonStepCount; false (and nothing changes) outside them or without a lesson.
    bool showStep(int step);
    int step() const { return step_; }
    const GranularityLesson* lesson() const { return lesson_ ? &*lesson_ : nullptr; }
    QString title() const;
    QString text() const;
    QToolButton* nextButton() const { return next_; }

private:
    std::optional<GranularityLesson> lesson_;
    int step_ = 0;
    QLabel* title_ = nullptr;
    QLabel* progress_ = nullptr;
    QTextBrowser* text_ = nullptr;
    QToolButton* back_ = nullptr;
    QToolButton* next_ = nullptr;
};

}  // namespace conescope
