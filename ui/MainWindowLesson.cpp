// The window's lesson: what each step shows (scene/LessonLayer.h says which layers, colours and
// camera), the docks it raises, and the layers and colours put back when it ends.
#include <QDockWidget>

#include "CrossSectionView.h"
#include "LessonView.h"
#include "MainWindow.h"
#include "ObserverView.h"

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
        // The right column shares its height between the words and the figure beside them.
        const int column = lessonDock_->height() + sideDocks_[3]->height();
        resizeDocks({lessonDock_, sideDocks_[3]}, {column / 2, column / 2}, Qt::Vertical);
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
    if (const Lesson* lesson = session_.lesson()) {
        view_->placeCamera(lessonCamera(*lesson, step, view_->viewAngle()));
        showCaption(tr("Lesson %1/%2: %3").arg(step).arg(kLessonStepCount).arg(QString::fromStdString(lesson->steps[size_t(step - 1)].title)));
    }
    render();
}

}  // namespace conescope
