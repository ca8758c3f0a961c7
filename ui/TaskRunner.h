// Runs the slow stages (reading, clustering, orbit statistics) off the UI thread, one at a time in
// the order asked, with progress and cancellation. A task's work gets the core's ProgressCallback;
// once the task is cancelled that callback returns false, so the core (or the pipeline between its
// stages) throws OperationCancelled and the task ends without delivering anything.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>

#include <QObject>
#include <QString>
#include <QThreadPool>

#include "core/Statistics.h"

namespace conescope {

class TaskRunner : public QObject {
    Q_OBJECT
public:
    explicit TaskRunner(QObject* parent = nullptr);
    ~TaskRunner() override;

    // Queues work in a group ("load", "clusters", ...); `done` gets its result on the UI thread
    // unless the task was cancelled, `failed` gets the exception message. Both run before idle().
    template <typename Result>
    void run(const QString& group, const QString& title, std::function<Result(const ProgressCallback&)> work,
             std::function<void(Result&)> done, std::function<void(const QString&)> failed) {
        auto result = std::make_shared<std::optional<Result>>();
        submit(
            group, title, [work, result](const ProgressCallback& progress) { *result = work(progress); },
            [done, result]() { done(**result); }, failed);
    }

    // Cancels the running and queued tasks of one group, or of all groups.
    void cancel(const QString& group);
    void cancelAll();
    // The task that next shows this stage (its title, or a stage its work reports: `matches` says)
    // is cancelled right there, on its own thread, as if Cancel were pressed that instant; then
    // stageCancelled(). An empty stage disarms.
    void cancelAtStage(const QString& stage, std::function<bool(const QString&)> matches);
    bool busy() const { return pending_ > 0; }
    bool busy(const QString& group) const;
    // Blocks (running the event loop) until no task is queued or running.
    void waitUntilIdle();

signals:
    void taskStarted(const QString& title);
    void progressChanged(double fraction, const QString& stage);
    void stageCancelled(const QString& stage);
    void idle();

private:
    struct Task;
    // On the worker: whether `stage` is the armed one (then disarmed, the task cancelled and
    // stageCancelled() on its way).
    bool cancelledAt(const QString& stage, std::atomic<bool>& cancelled);
    void submit(const QString& group, const QString& title, std::function<void(const ProgressCallback&)> work,
                std::function<void()> done, std::function<void(const QString&)> failed);
    void finish(const std::shared_ptr<Task>& task);

    QThreadPool pool_;
    std::vector<std::shared_ptr<Task>> queued_;
    int pending_ = 0;
    std::mutex stageMutex_;
    QString cancelStage_;
    std::function<bool(const QString&)> stageMatches_;
};

}  // namespace conescope
