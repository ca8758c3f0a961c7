#include "TaskRunner.h"

#include <algorithm>
#include <exception>

#include <QEventLoop>
#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

namespace conescope {

struct TaskRunner::Task {
    QString group;
    QString title;
    std::shared_ptr<std::atomic<bool>> cancelled = std::make_shared<std::atomic<bool>>(false);
    std::function<void(const ProgressCallback&)> work;
    std::function<void()> done;
    std::function<void(const QString&)> failed;
    // Written by the worker, read on the UI thread after the future finished.
    bool succeeded = false;
    QString error;
};

TaskRunner::TaskRunner(QObject* parent) : QObject(parent) {
    // One worker: tasks run in the order they were asked for, and a cancelled task that is still
    // inside a stage without a callback does not compete with its replacement for the two cores.
    pool_.setMaxThreadCount(1);
}

TaskRunner::~TaskRunner() {
    cancelAll();
    pool_.waitForDone();
}

void TaskRunner::submit(const QString& group, const QString& title, std::function<void(const ProgressCallback&)> work,
                        std::function<void()> done, std::function<void(const QString&)> failed) {
    auto task = std::make_shared<Task>();
    task->group = group;
    task->title = title;
    task->work = std::move(work);
    task->done = std::move(done);
    task->failed = std::move(failed);
    queued_.push_back(task);
    ++pending_;

    auto* watcher = new QFutureWatcher<void>(this);
    connect(watcher, &QFutureWatcher<void>::finished, this, [this, watcher, task]() {
        watcher->deleteLater();
        finish(task);
    });
    watcher->setFuture(QtConcurrent::run(&pool_, [this, task]() {
        const auto cancelled = task->cancelled;
        if (*cancelled) return;
        QMetaObject::invokeMethod(this, [this, title = task->title]() { emit taskStarted(title); }, Qt::QueuedConnection);
        if (cancelledAt(task->title, *cancelled)) return;
        const ProgressCallback progress = [this, cancelled](double fraction, const std::string& stage) {
            if (*cancelled) return false;
            const QString shown = QString::fromStdString(stage);
            QMetaObject::invokeMethod(this, [this, fraction, shown]() { emit progressChanged(fraction, shown); }, Qt::QueuedConnection);
            return !cancelledAt(shown, *cancelled);
        };
        try {
            task->work(progress);
            task->succeeded = true;
        } catch (const OperationCancelled&) {
            // Neither succeeded nor failed: finish() delivers nothing.
        } catch (const std::exception& error) {
            task->error = QString::fromStdString(error.what());
        } catch (...) {
            task->error = tr("unknown error");
        }
    }));
}

void TaskRunner::finish(const std::shared_ptr<Task>& task) {
    // No longer running while it delivers: busy() then says whether other work is left (a Cancel
    // pressed meanwhile has nothing of this task's to cancel).
    queued_.erase(std::remove(queued_.begin(), queued_.end(), task), queued_.end());
    --pending_;
    // A cancelled task (flag set, or OperationCancelled thrown) delivers nothing.
    if (!*task->cancelled) {
        if (task->succeeded)
            task->done();
        else if (!task->error.isEmpty())
            task->failed(task->error);
    }
    if (pending_ == 0) emit idle();
}

void TaskRunner::cancelAtStage(const QString& stage, std::function<bool(const QString&)> matches) {
    std::lock_guard<std::mutex> lock(stageMutex_);
    cancelStage_ = stage;
    stageMatches_ = std::move(matches);
}

bool TaskRunner::cancelledAt(const QString& stage, std::atomic<bool>& cancelled) {
    {
        std::lock_guard<std::mutex> lock(stageMutex_);
        if (cancelStage_.isEmpty() || !stageMatches_(stage)) return false;
        cancelStage_.clear();
    }
    cancelled = true;
    QMetaObject::invokeMethod(this, [this, stage]() { emit stageCancelled(stage); }, Qt::QueuedConnection);
    return true;
}

void TaskRunner::cancel(const QString& group) {
    for (const auto& task : queued_)
        if (task->group == group) *task->cancelled = true;
}

void TaskRunner::cancelAll() {
    for (const auto& task : queued_) *task->cancelled = true;
}

bool TaskRunner::busy(const QString& group) const {
    return std::any_of(queued_.begin(), queued_.end(),
                       [&](const auto& task) { return task->group == group && !*task->cancelled; });
}

void TaskRunner::waitUntilIdle() {
    if (!busy()) return;
    QEventLoop loop;
    connect(this, &TaskRunner::idle, &loop, &QEventLoop::quit);
    loop.exec();
}

}  // namespace conescope
