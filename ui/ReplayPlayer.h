// Plays replay steps (ReplaySteps.h) in a window, one after the other: each step's action, then a
// wait until the session is idle (loads, builds, orbit statistics, comparisons, exports) before the
// next. A step fails when its action throws or the window reports an error while it runs.
#pragma once

#include <vector>

#include <QObject>
#include <QString>

#include "ReplaySteps.h"

namespace conescope {

class MainWindow;

class ReplayPlayer : public QObject {
    Q_OBJECT
public:
    explicit ReplayPlayer(MainWindow& window, QObject* parent = nullptr);

    // Starts playing once the window is idle and returns; finished() or failed() tell the end.
    void play(std::vector<ReplayStep> steps);
    // Plays and returns when done: empty, or the failure's message.
    QString playBlocking(std::vector<ReplayStep> steps);

signals:
    void stepFinished(size_t number);
    void finished();
    // "step N {TEXT}: what went wrong".
    void failed(const QString& message);

private:
    void playNext();
    // Calls `then` once the session has no background work left.
    void whenIdle(const std::function<void()>& then);
    void fail(const std::string& what);

    MainWindow& window_;
    std::vector<ReplayStep> steps_;
    size_t next_ = 0;
    bool playing_ = false;
    QString stepError_;  // what the window reported while the current step ran
};

}  // namespace conescope
