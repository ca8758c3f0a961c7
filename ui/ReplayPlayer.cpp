#include "ReplayPlayer.h"

#include <QEventLoop>
#include <QTimer>

#include <memory>

#include "MainWindow.h"

namespace conescope {

ReplayPlayer::ReplayPlayer(MainWindow& window, QObject* parent) : QObject(parent), window_(window) {
    connect(&window_, &MainWindow::errorShown, this, [this](const QString& message) {
        if (playing_ && stepError_.isEmpty()) stepError_ = message;
    });
}

void ReplayPlayer::play(std::vector<ReplayStep> steps) {
    steps_ = std::move(steps);
    next_ = 0;
    playing_ = true;
    stepError_.clear();
    // A mesh given on the command line is shown before the first step.
    whenIdle([this]() { playNext(); });
}

QString ReplayPlayer::playBlocking(std::vector<ReplayStep> steps) {
    QString error;
    QEventLoop loop;
    const auto done = connect(this, &ReplayPlayer::finished, &loop, &QEventLoop::quit);
    const auto broken = connect(this, &ReplayPlayer::failed, &loop, [&](const QString& message) {
        error = message;
        loop.quit();
    });
    play(std::move(steps));
    loop.exec();
    disconnect(done);
    disconnect(broken);
    return error;
}

void ReplayPlayer::playNext() {
    if (next_ == steps_.size()) {
        playing_ = false;
        emit finished();
        return;
    }
    stepError_.clear();
    // A step after "cancel-at-stage" must show that stage.
    const bool cancelArmed = window_.session().cancelStageArmed();
    try {
        steps_[next_].play(window_);
    } catch (const std::exception& error) {
        fail(error.what());
        return;
    }
    whenIdle([this, cancelArmed]() {
        if (!stepError_.isEmpty()) {
            fail(stepError_.toStdString());
            return;
        }
        if (cancelArmed && window_.session().cancelStageArmed()) {
            const QString seen = window_.session().stagesSeen().join(QStringLiteral("\", \""));
            window_.session().cancelAtStage({});
            fail("the progress never showed the stage to cancel at" +
                 (seen.isEmpty() ? std::string(" (it showed none)") : " (it showed \"" + seen.toStdString() + "\")"));
            return;
        }
        emit stepFinished(steps_[next_].number);
        ++next_;
        playNext();
    });
}

void ReplayPlayer::whenIdle(const std::function<void()>& then) {
    // Through the event loop first: queued work (an eye moved while dragging, a render) comes in.
    QTimer::singleShot(0, this, [this, then]() {
        if (!window_.session().busy()) {
            then();
            return;
        }
        // Once, when the session's last background task has ended; then through the loop again.
        auto connection = std::make_shared<QMetaObject::Connection>();
        *connection = connect(&window_.session(), &Session::idle, this, [this, then, connection]() {
            disconnect(*connection);
            whenIdle(then);
        });
    });
}

void ReplayPlayer::fail(const std::string& what) {
    playing_ = false;
    emit failed(QString::fromStdString(describeStep(steps_[next_], what)));
}

}  // namespace conescope
