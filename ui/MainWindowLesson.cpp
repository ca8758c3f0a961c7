// The window's lesson: what each step shows (scene/LessonLayer.h says which layers, colours and
// camera), the docks it raises, and the layers and colours put back when it ends.
#include <algorithm>

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QStatusBar>

#include "CrossSectionView.h"
#include "LessonView.h"
#include "MainWindow.h"
#include "ObserverView.h"
#include "ReplayPlayer.h"
#include "Slides.h"

namespace conescope {

bool MainWindow::showLessonStep(int step) {
    if (step < 0 || step > kLessonStepCount) return false;
    // A lesson needs a cluster: the one the test loses most, when none is picked.
    if (step > 0 && session_.pickedCluster() < 0) chooseWorstCluster(ClusterSortKey::TestLoss);
    return session_.setLessonStep(step);
}

void MainWindow::toggleLesson() { showLessonStep(session_.lessonStep() > 0 ? 0 : 1); }

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
            for (QDockWidget* dock : docksHiddenByLesson_) dock->show();
            if (!docksHiddenByLesson_.empty()) plotsDock_->raise();
            docksHiddenByLesson_.clear();
            layersBeforeLesson_.reset();
        }
        showCaption({});
        render();
        return;
    }
    if (!layersBeforeLesson_) {
        // The plots and the eye's view make room for the lesson's words and figures (a small screen has
        // none to spare); they come back when it ends.
        for (QDockWidget* dock : findChildren<QDockWidget*>())
            if (dockWidgetArea(dock) == Qt::BottomDockWidgetArea && !dock->isHidden()) {
                docksHiddenByLesson_.push_back(dock);
                dock->hide();
            }
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
    // The right column shares its height between the words and the figure: the cone's steps have the
    // most words, the cross-section's figure the most labels.
    const int column = lessonDock_->height() + sideDocks_[3]->height();
    const int words = figure == crossSectionDock_ ? column * 9 / 20 : column * 11 / 20;
    resizeDocks({lessonDock_, sideDocks_[3]}, {words, column - words}, Qt::Vertical);
    if (const Lesson* lesson = session_.lesson()) {
        view_->placeCamera(lessonCamera(*lesson, step, view_->fittingViewAngle()));
        showCaption(tr("Lesson %1/%2: %3").arg(step).arg(kLessonStepCount).arg(QString::fromStdString(lesson->steps[size_t(step - 1)].title)));
    }
    render();
}

bool MainWindow::exportLessonSlides(const QString& folder) {
    const QString title = tr("Cannot export the lesson slides");
    if (!QDir().mkpath(folder)) {
        showError(title, tr("%1: cannot make the folder").arg(folder));
        return false;
    }
    const int before = session_.lessonStep();
    bool written = true;
    for (int step = 1; step <= kLessonStepCount && written; ++step) {
        const Lesson* lesson = showLessonStep(step) ? session_.lesson() : nullptr;
        if (!lesson) {
            showError(title, tr("Pick a cluster first (or open a mesh): a lesson is about one cluster."));
            return false;
        }
        // The band below says the title: the view's own caption would say it twice.
        showCaption({});
        QApplication::processEvents();
        const LessonStep& words = lesson->steps[size_t(step - 1)];
        const QImage slide = captionedSlide(view_->grabFramebuffer(),
                                            tr("%1/%2  %3").arg(step).arg(kLessonStepCount).arg(QString::fromStdString(words.title)),
                                            QString::fromStdString(words.text));
        const QString path = QDir(folder).filePath(slideFileName(step));
        written = slide.save(path, "PNG");
        if (!written) showError(title, tr("%1: cannot write the PNG").arg(path));
    }
    showLessonStep(before);
    stageLessonStep(session_.lessonStep());
    if (written) statusBar()->showMessage(tr("Wrote %1 slides to %2").arg(kLessonStepCount).arg(folder), 6000);
    return written;
}

bool MainWindow::exportOrbitSlides(const QString& folder) {
    const QString title = tr("Cannot export the orbit slides");
    if (!session_.clusters() || !session_.preparedMesh()) {
        showError(title, tr("Open a mesh first."));
        return false;
    }
    if (!QDir().mkpath(folder)) {
        showError(title, tr("%1: cannot make the folder").arg(folder));
        return false;
    }
    const glm::dvec3 eyeBefore = session_.eyePosition();
    const long stepBefore = session_.orbitStep();
    const long views = long(session_.settings().views);
    const long slides = std::min(views, 8L);
    const Aabb meshBox = session_.preparedMesh()->box;
    bool written = true;
    for (long i = 0; i < slides && written; ++i) {
        const long view = i * views / slides;
        session_.moveEyeToOrbitView(view);
        waitUntilIdle();
        const EyeMeasurement* measured = session_.measurement();
        if (!measured) {
            showError(title, session_.eyeError());
            written = false;
            break;
        }
        // The camera takes in the mesh and this eye, so the eye shows on its slide.
        if (!measured->eye.orthographic)
            view_->frameBox(computeAabb({meshBox.min, meshBox.max, glm::vec3(measured->eye.position)}), view_->cameraPosition());
        view_->render();
        QApplication::processEvents();
        const QImage slide = captionedSlide(view_->grabFramebuffer(), tr("Orbit view %1 of %2").arg(view + 1).arg(views),
                                            QString::fromStdString(viewInWords(measured->statistics, session_.clusters()->bounds.count())));
        const QString path = QDir(folder).filePath(slideFileName(int(i + 1)));
        written = slide.save(path, "PNG");
        if (!written) showError(title, tr("%1: cannot write the PNG").arg(path));
    }
    session_.moveEye(eyeBefore, stepBefore);
    if (written) statusBar()->showMessage(tr("Wrote %1 slides to %2").arg(slides).arg(folder), 6000);
    return written;
}

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
