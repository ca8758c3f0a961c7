// The lesson dock: the picked cluster's lesson (core makeLesson, through the session), one step at a
// time, its title and its sentences with the live numbers, Back and Next. Without a pick it says how
// to get one and offers the cluster that loses most to the test. It only shows the session's lesson
// and asks for steps; the session and the window do the rest.
#pragma once

#include <QWidget>

class QLabel;
class QPushButton;
class QTextBrowser;

namespace conescope {

class Session;

class LessonView : public QWidget {
    Q_OBJECT
public:
    explicit LessonView(QWidget* parent = nullptr);

    // The session's lesson step and lesson (or what to do to have one).
    void showLesson(const Session& session);
    // What the dock says now (its title and text), for tests.
    QString title() const;
    QString text() const;

signals:
    // A step to show: 1 to kLessonStepCount, 0 ends the lesson.
    void stepRequested(int step);
    // Pick the cluster the orbit's test loses most, and put the eye where it loses it.
    void costliestClusterRequested();

private:
    QLabel* title_ = nullptr;
    QLabel* progress_ = nullptr;
    QTextBrowser* text_ = nullptr;
    QPushButton* back_ = nullptr;
    QPushButton* next_ = nullptr;
    QPushButton* startOrEnd_ = nullptr;
    QPushButton* costliest_ = nullptr;
    int step_ = 0;
};

}  // namespace conescope
