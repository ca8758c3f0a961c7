// The window's lesson: what each step shows (scene/LessonLayer.h says which layers, colours and
// camera), the docks it raises, and the layers and colours put back when it ends; its examples of each
// outcome and the eye's sweep across the cull boundary.
#include <algorithm>
#include <stdexcept>

#include <QApplication>
#include <QDockWidget>
#include <QStatusBar>
#include <QTimer>

#include "CrossSectionView.h"
#include "LessonView.h"
#include "MainWindow.h"
#include "ObserverView.h"
#include "ReplayPlayer.h"
#include "core/EyeSweep.h"
#include "core/LessonExamples.h"

namespace conescope {

bool MainWindow::showLessonStep(int step) {
    if (step < 0 || step > kLessonStepCount) return false;
    // A lesson needs a cluster: the one the test loses most, when none is picked.
    if (step > 0 && session_.pickedCluster() < 0) chooseWorstCluster(ClusterSortKey::TestLoss);
    return session_.setLessonStep(step);
}

void MainWindow::toggleLesson() { showLessonStep(session_.lessonStep() > 0 ? 0 : 1); }

void MainWindow::framePickedCluster() {
    if (session_.pickedCluster() < 0) return;
    // Seen from where its normals point (the cone's axis), the cluster shows its faces, not its back.
    const size_t picked = size_t(session_.pickedCluster());
    const ClusterBounds& bounds = session_.clusters()->bounds;
    const glm::dvec3 center(bounds.boxes[picked].center());
    view_->frameBox(bounds.boxes[picked], bounds.cones[picked].cullable ? center + bounds.cones[picked].axis : session_.eyePosition());
}

int MainWindow::chooseWorstCluster(ClusterSortKey key) {
    const CullTestStatistics* orbit = session_.orbitStatistics();
    if (!orbit) return -1;
    const std::vector<uint32_t> worst = rankClusters(*orbit, key, 1);
    if (worst.empty()) return -1;
    chooseCluster(int(worst.front()));
    return int(worst.front());
}

void MainWindow::stageLessonStep(int step) {
    if (step == 0) {
        if (layersBeforeLesson_) {
            for (const auto& [layer, shown] : *layersBeforeLesson_) setLayerVisible(layer, shown);
            session_.setFaceColoring(coloringBeforeLesson_);
            // The docks where they were, as large as they were.
            restoreState(docksBeforeLesson_);
            layersBeforeLesson_.reset();
        }
        showCaption({});
        render();
        return;
    }
    if (!layersBeforeLesson_) {
        // The plots and the eye's view make room for the lesson's words and figures (a small screen has
        // none to spare); on a window narrower than a full-HD screen the settings and the eye panel too,
        // and the words get a wider column. All come back when it ends.
        docksBeforeLesson_ = saveState();
        const bool narrow = width() < 1600;
        for (QDockWidget* dock : findChildren<QDockWidget*>()) {
            const Qt::DockWidgetArea area = dockWidgetArea(dock);
            if (area == Qt::BottomDockWidgetArea || (narrow && area == Qt::LeftDockWidgetArea)) dock->hide();
        }
        if (narrow) resizeDocks({lessonDock_}, {std::max(400, width() * 2 / 5)}, Qt::Horizontal);
        layersBeforeLesson_.emplace();
        for (Layer layer : allLayers()) (*layersBeforeLesson_)[layer] = layerVisible(layer);
        coloringBeforeLesson_ = session_.faceColoring();
    }
    for (const auto& [layer, shown] : lessonLayers(step)) setLayerVisible(layer, shown);
    session_.setFaceColoring(lessonColouring(step));
    lessonDock_->show();
    lessonDock_->raise();
    // Beside the words, the figure the step talks about: the cluster's numbers, its Gauss map, the
    // cross-section of the cone and the view vector.
    QDockWidget* figure = step == 2 || step == 3 ? gaussMapDock_ : step >= 5 ? crossSectionDock_ : sideDocks_[3];
    figure->show();
    figure->raise();
    // The right column shares its height between the words and the figure the same way at every step,
    // so the buttons under the words (Next, Back) never move.
    const int column = lessonDock_->height() + sideDocks_[3]->height();
    const int words = column * 14 / 25;
    if (lessonDock_->height() != words) resizeDocks({lessonDock_, sideDocks_[3]}, {words, column - words}, Qt::Vertical);
    if (const Lesson* lesson = session_.lesson()) {
        view_->placeCamera(lessonCamera(*lesson, step, view_->fittingViewAngle()));
        showCaption(tr("Lesson %1/%2: %3").arg(step).arg(kLessonStepCount).arg(QString::fromStdString(lesson->steps[size_t(step - 1)].title)));
    }
    render();
}

// --- Examples and the sweep ------------------------------------------------------------------------

int MainWindow::chooseExample(LessonOutcome outcome) {
    const CullTestStatistics* orbit = session_.orbitStatistics();
    if (!orbit || !session_.clusters()) return -1;
    const ClusterExample example = findExample(*session_.preparedMesh(), *session_.clusters(), session_.settings(), *orbit, outcome);
    if (example.cluster < 0) {
        statusBar()->showMessage(tr("No cluster is %1 from any orbit view with these settings")
                                     .arg(QString::fromStdString(toString(outcome))),
                                 8000);
        return -1;
    }
    session_.pickCluster(int(example.cluster));
    session_.moveEyeToOrbitView(example.view);
    // In a lesson the step frames it again; else the view turns to the cluster, as a row of the table does.
    if (session_.lessonStep() > 0) stageLessonStep(session_.lessonStep());
    else framePickedCluster();
    return int(example.cluster);
}

namespace {

// The sweep of the picked cluster from the eye, or the reason there is none.
EyeSweep sweepOf(const Session& session, size_t frames) {
    const Lesson* lesson = session.lesson();
    if (!lesson) throw std::runtime_error("Pick a cluster first: the eye sweeps across the picked cluster's cull boundary.");
    return sweepAcrossCull(*session.preparedMesh(), *session.clusters(), session.settings(), lesson->cluster, session.eyePosition(), frames);
}

}  // namespace

bool MainWindow::sweepEye(size_t frames, const std::function<void(size_t)>& eachFrame) {
    EyeSweep sweep;
    try {
        sweep = sweepOf(session_, frames);
    } catch (const std::exception& error) {
        showError(tr("Cannot sweep the eye"), QString::fromStdString(error.what()));
        return false;
    }
    // The step whose words hold the inequality, unless one that also follows the eye is shown.
    if (session_.lessonStep() < 5) showLessonStep(5);
    for (size_t k = 0; k < sweep.positions.size(); ++k) {
        session_.moveEye(sweep.positions[k], -1);
        QApplication::processEvents();
        if (eachFrame) eachFrame(k);
    }
    return true;
}

void MainWindow::toggleEyeSweep(size_t frames, int milliseconds) {
    if (!sweepTimer_) {
        sweepTimer_ = new QTimer(this);
        connect(sweepTimer_, &QTimer::timeout, this, [this]() {
            // Another cluster or another scene: the sweep's eyes were for the one before.
            if (session_.pickedCluster() != sweptCluster_ || session_.scene() != sweptScene_) sweepFrames_.clear();
            if (sweepFrames_.empty()) {
                sweepTimer_->stop();
                lessonView_->showSweeping(false);
                lessonView_->showLesson(session_);
                return;
            }
            const glm::dvec3 next = sweepFrames_.front();
            sweepFrames_.erase(sweepFrames_.begin());
            session_.moveEye(next, -1);
        });
    }
    if (sweepTimer_->isActive()) {
        sweepTimer_->stop();
        sweepFrames_.clear();
        lessonView_->showSweeping(false);
        lessonView_->showLesson(session_);
        return;
    }
    try {
        sweepFrames_ = sweepOf(session_, frames).positions;
    } catch (const std::exception& error) {
        showError(tr("Cannot sweep the eye"), QString::fromStdString(error.what()));
        return;
    }
    if (session_.lessonStep() < 5) showLessonStep(5);
    sweptCluster_ = session_.pickedCluster();
    sweptScene_ = session_.scene();
    lessonView_->showSweeping(true);
    sweepTimer_->start(milliseconds);
}

bool MainWindow::eyeSweepRunning() const { return sweepTimer_ && sweepTimer_->isActive(); }

bool MainWindow::playReplayFile(const QString& path) {
    std::vector<ReplayStep> steps;
    try {
        steps = readReplayFile(path);
    } catch (const ReplayError& error) {
        showError(tr("Cannot play the lesson"), QString::fromStdString(error.what()));
        return false;
    }
    auto* player = new ReplayPlayer(*this, this);
    connect(player, &ReplayPlayer::finished, player, &QObject::deleteLater);
    connect(player, &ReplayPlayer::failed, this, [this, player](const QString& message) {
        showError(tr("Cannot play the lesson"), message);
        player->deleteLater();
    });
    player->play(std::move(steps));
    return true;
}

}  // namespace conescope
