// The session's cull eye, its measurement, the picked cluster and how the scene is drawn.
#include "Session.h"

#include <chrono>

#include "SceneBinding.h"
#include "io/LessonIO.h"

namespace conescope {

const OrbitMeasurement* Session::orbitMultiCones() const {
    return shown_.orbitStatistics() && shown_.orbit->multi ? shown_.orbit.get() : nullptr;
}

std::optional<SubGroupsFromEye> Session::subGroupsFromEye() const {
    const OrbitMeasurement* orbit = orbitMultiCones();
    if (!orbit || !measurement_) return std::nullopt;
    const PreparedMesh& prepared = *shown_.prepared;
    SubGroupsFromEye fromEye;
    fromEye.multi = orbit->multi;
    fromEye.culled = cullSubGroups(shown_.clusters->bounds, *orbit->multi, measurement_->eye);
    fromEye.facing = classifyFaces(prepared.mesh(), prepared.world, prepared.faces, measurement_->eye);
    fromEye.counts = countCulledSubGroups(*orbit->multi, fromEye.culled, fromEye.facing);
    return fromEye;
}

void Session::showSubGroups() {
    if (!scene_) return;
    const std::optional<SubGroupsFromEye> fromEye = subGroupsFromEye();
    if (!fromEye) {
        scene_->setSubGroups({}, {}, 0);
        return;
    }
    scene_->setSubGroups(subGroupOfFace(*fromEye->multi, shown_.prepared->mesh().faceCount()), fromEye->culled,
                         fromEye->multi->conesPerCluster);
}

void Session::setInitialEye(const glm::dvec3& position) {
    eyePosition_ = position;
    eyeGiven_ = true;
}

void Session::moveEye(const glm::dvec3& position, long orbitStep) {
    eyePosition_ = position;
    orbitStep_ = orbitStep;
    updateEye();
    emit orbitChanged();
}

bool Session::moveEyeToOrbitView(long view) {
    if (!shown_.prepared) return false;
    const std::vector<Eye> views = orbitOf(shown_.settings, shown_.prepared->box);
    if (view < 0 || size_t(view) >= views.size()) return false;
    moveEye(views[size_t(view)].position, view);
    return true;
}

void Session::moveEyeSoon(const glm::dvec3& position) {
    // Called from VTK's event callbacks, where no view may render: the eye is measured and shown
    // once the event loop is free. The efficiency plot marks the last orbit view until a moveEye.
    eyePosition_ = position;
    orbitStep_ = -1;
    if (eyeUpdateScheduled_) return;
    eyeUpdateScheduled_ = true;
    QTimer::singleShot(0, this, [this]() {
        eyeUpdateScheduled_ = false;
        updateEye();
    });
}

void Session::followCamera(const glm::dvec3& position) {
    // Rendering touches the camera too (clipping range): only a new position moves the eye.
    if (!shown_.prepared || position == eyePosition_) return;
    moveEyeSoon(position);
}

void Session::moveEyeToStart() {
    if (shown_.prepared) moveEye(startingEyePosition(shown_.prepared->box, shown_.settings), -1);
}

void Session::stepOrbit(int step) {
    if (!shown_.prepared) return;
    const std::vector<Eye> views = orbitOf(shown_.settings, shown_.prepared->box);
    if (views.empty()) return;
    const long count = long(views.size());
    // Moved off the orbit (dragged, typed, following the camera): on from the view nearest the eye.
    const long from = orbitStep_ >= 0 && orbitStep_ < count
                          ? orbitStep_
                          : long(nearestOrbitView(shown_.settings, shown_.prepared->box, eyePosition_));
    const long next = ((from + step) % count + count) % count;
    moveEye(views[size_t(next)].position, next);
}

void Session::setAnimating(bool animate) {
    if (animate)
        animationTimer_.start();
    else
        animationTimer_.stop();
}

void Session::updateEye() {
    emit eyeMoved();
    if (!shown_.clusters || !scene_) return;
    measureCurrentEye();
    emit eyeMeasured();
    updateLod();
}

void Session::measureCurrentEye() {
    const auto start = std::chrono::steady_clock::now();
    const PreparedMesh& prepared = *shown_.prepared;
    const ClusterSet& clusters = *shown_.clusters;
    try {
        const Eye eye = eyeAt(shown_.settings, eyePosition_, prepared.box);
        measurement_ = measureEye(prepared, clusters, eye, displayedTest(shown_.settings));
    } catch (const std::exception& error) {
        // An orthographic eye at the mesh centre has no direction: say so and show no decision.
        measurement_.reset();
        eyeError_ = QString::fromStdString(error.what());
        scene_->clearClusterDecisions();
        scene_->setTestDrawing({});
        measurePinnedEye();
        updateLesson();
        return;
    }
    eyeError_.clear();
    showMeasurement(*scene_, prepared, clusters, *measurement_);
    showEyeColouring(*scene_, prepared, clusters, *measurement_, coloring_);
    showSubGroups();
    showTestDrawing(*scene_, prepared, clusters, picked_, *measurement_);
    measurePinnedEye();
    updateLesson();
    eyeSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --- Scene display and picking -----------------------------------------------------------------------

void Session::setLayerVisible(Layer layer, bool visible) {
    layers_[layer] = visible;
    if (scene_) scene_->setLayerVisible(layer, visible);
    if (lod_->scene) lod_->scene->setLayerVisible(layer, visible);
}

void Session::fitLegend(int viewHeight, double pixelRatio) {
    legendViewHeight_ = viewHeight;
    legendPixelRatio_ = pixelRatio;
    if (scene_ && viewHeight > 0) scene_->fitLegend(viewHeight, pixelRatio);
}

void Session::setFaceColoring(FaceColoring coloring) {
    coloring_ = coloring;
    if (scene_) {
        scene_->setFaceColoring(coloring);
        if (measurement_) showEyeColouring(*scene_, *shown_.prepared, *shown_.clusters, *measurement_, coloring);
    }
    if (lod_->scene) updateLod();
    emit faceColoringChanged(coloring);
}

void Session::pickCluster(int cluster) {
    if (!scene_ || cluster < -1 || cluster >= int(scene_->clusterCount())) cluster = -1;
    picked_ = cluster;
    if (scene_) scene_->setHighlightedCluster(cluster);
    if (scene_ && measurement_) showTestDrawing(*scene_, *shown_.prepared, *shown_.clusters, cluster, *measurement_);
    updateLesson();
    emit pickChanged(cluster);
}

// --- The lesson ----------------------------------------------------------------------------------------

bool Session::setLessonStep(int step) {
    if (step < 0 || step > kLessonStepCount) return false;
    const bool changed = step != lessonStep_;
    lessonStep_ = step;
    updateLesson();
    if (changed) emit lessonStepChanged(step);
    return true;
}

void Session::updateLesson() {
    lesson_.reset();
    if (scene_ && measurement_ && picked_ >= 0)
        lesson_ = makeLesson(*shown_.prepared, *shown_.clusters, uint32_t(picked_), measurement_->eye, measurement_->statistics.test);
    if (scene_) scene_->setLessonDrawing(lessonStep_ > 0 && lesson_ ? LessonDrawing{lessonStep_, *lesson_} : LessonDrawing{});
    emit lessonChanged();
}

bool Session::exportExplanation(const QString& path) {
    if (!lesson_) {
        emit errorOccurred(tr("Cannot export the explanation"), tr("Pick a cluster first: the explanation is about the picked cluster."));
        return false;
    }
    return writeExport(tr("Cannot export the explanation"), path, [&] { writeLessonJson(*lesson_, path.toStdString()); });
}

const std::vector<ViewStatistics>& Session::orbitRows() const {
    static const std::vector<ViewStatistics> none;
    const CullTestStatistics* orbit = orbitStatistics();
    return orbit ? orbit->views : none;
}

void Session::showClusterWhereItIsLost(int cluster) {
    pickCluster(cluster);
    if (!shown_.clusters || picked_ < 0) return;
    const long view = viewMissingCluster(*shown_.prepared, *shown_.clusters, shown_.settings, uint32_t(picked_));
    if (view >= 0) {
        moveEyeToOrbitView(view);
    } else {
        emit notice(tr("Cluster %1 is never drawn with back faces over the orbit").arg(picked_), 6000);
    }
}

}  // namespace conescope
