// The session's cluster LOD hierarchy: built on request from the shown snapshot, measured from the
// cull eye with the shown settings (as `conescope-cli lod --eye` measures it), and one level or the
// cut drawn in a scene of its own.
#include "Session.h"

#include "SceneBinding.h"
#include "TaskGroups.h"
#include "io/ClusterIdFile.h"

namespace conescope {

namespace {

// Per cluster of the scene (`origin`: what each is in the hierarchy) its level, group and cut class.
ClusterLodClasses lodClassesOf(const ClusterHierarchy& hierarchy, const std::vector<LodClusterId>& origin,
                               const std::vector<std::vector<uint8_t>>& cutClasses) {
    ClusterLodClasses classes;
    classes.levelCount = hierarchy.levels.size();
    for (const LodClusterId& id : origin) {
        const LodCluster& place = hierarchy.levels[id.level].place[id.cluster];
        classes.level.push_back(uint32_t(id.level));
        // The top's clusters are in no group: each its own colour.
        classes.group.push_back(place.group != kNoGroup ? place.group : id.cluster);
        classes.cut.push_back(cutClasses[id.level][id.cluster]);
    }
    return classes;
}

}  // namespace

void Session::buildLodHierarchy() {
    if (!shown_.clusters) {
        emit errorOccurred(tr("Cannot build the LOD hierarchy"), tr("No mesh is loaded."));
        return;
    }
    const Snapshot from = shown_;
    using Built = std::shared_ptr<const ClusterHierarchy>;
    runner_.run<Built>(
        taskgroups::lod, tr("Building LOD hierarchy"),
        [from](const ProgressCallback& progress) -> Built {
            return std::make_shared<ClusterHierarchy>(buildClusterHierarchy(*from.prepared, withClusterIds(from.settings), {}, progress));
        },
        [this, from](Built& hierarchy) {
            // Other clusters shown meanwhile: the hierarchy is of a partition no longer shown.
            if (from.clusters != shown_.clusters) return;
            lod_->hierarchy = hierarchy;
            lod_->madeFrom = from.clusters;
            lod_->picked = -1;
            emit notice(tr("Built %1 LOD levels in %2 s").arg(hierarchy->levels.size()).arg(hierarchy->buildSeconds, 0, 'f', 2), 6000);
            updateLod();
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot build the LOD hierarchy"), error); });
}

bool Session::showLodLevel(int level) {
    if (level != kLodNone && (!lod_->hierarchy || (level != kLodCut && (level < 0 || size_t(level) >= lod_->hierarchy->levels.size()))))
        return false;
    if (level == lod_->shown) return true;
    lod_->shown = level;
    lod_->picked = -1;
    updateLod();
    return true;
}

void Session::setLodThreshold(const LodThreshold& threshold) {
    lod_->threshold = threshold;
    updateLod();
}

void Session::updateLod() {
    std::unique_ptr<ClusterScene> previous;
    if (lod_->hierarchy && lod_->madeFrom != shown_.clusters) {
        // New clusters: the hierarchy was made from others.
        previous = std::move(lod_->scene);
        const LodThreshold threshold = lod_->threshold;
        *lod_ = SessionLod{};
        lod_->threshold = threshold;
    }
    lod_->statistics.reset();
    lod_->cut.clear();
    lod_->cutLevel.reset();
    lod_->measurement.reset();
    if (lod_->hierarchy && measurement_) {
        const Settings settings = exportSettings(shown_.settings, eyePosition_);
        lod_->statistics = measureHierarchy(*lod_->hierarchy, settings, lod_->threshold);
        lod_->cut = cutFrom(*lod_->hierarchy, lod_->statistics->cut.views.front().eye.position, lod_->threshold);
        if (lod_->shown != kLodNone) makeLodScene(previous);
    }
    if (!lod_->measurement && lod_->scene) previous = std::move(lod_->scene);
    emit lodChanged(previous.get());
}

void Session::makeLodScene(std::unique_ptr<ClusterScene>& previous) {
    const ClusterHierarchy& hierarchy = *lod_->hierarchy;
    const LodLevel* level = nullptr;
    if (lod_->shown == kLodCut) {
        lod_->cutLevel = levelOfCut(hierarchy, lod_->cut, hierarchy.settings, lod_->cutOrigin);
        level = &*lod_->cutLevel;
    } else {
        level = &hierarchy.levels[size_t(lod_->shown)];
    }
    const Eye& eye = lod_->statistics->cut.views.front().eye;
    lod_->measurement = measureEye(level->prepared, level->clusters, eye, displayedTest(shown_.settings));
    // A level keeps its scene while the eye moves; a cut is other clusters.
    if (!lod_->scene || lod_->shown == kLodCut || lod_->sceneShows != lod_->shown) {
        previous = std::move(lod_->scene);
        lod_->scene = makeScene(level->prepared, level->clusters);
        lod_->sceneShows = lod_->shown;
        for (const auto& [layer, visible] : layers_) lod_->scene->setLayerVisible(layer, visible);
        if (legendViewHeight_ > 0) lod_->scene->fitLegend(legendViewHeight_, legendPixelRatio_);
    }
    ClusterScene& scene = *lod_->scene;
    std::vector<LodClusterId> origin = lod_->cutOrigin;
    if (lod_->shown != kLodCut) {
        origin.clear();
        for (uint32_t c = 0; c < level->place.size(); ++c) origin.push_back({size_t(lod_->shown), c});
    }
    scene.setClusterLod(lodClassesOf(hierarchy, origin, cutClassesFrom(hierarchy, eye.position, lod_->threshold)));
    showMeasurement(scene, level->prepared, level->clusters, *lod_->measurement);
    scene.setFaceColoring(coloring_);
    showEyeColouring(scene, level->prepared, level->clusters, *lod_->measurement, coloring_);
    if (lod_->picked >= int(scene.clusterCount())) lod_->picked = -1;
    scene.setHighlightedCluster(lod_->picked);
}

void Session::pickLodCluster(int cluster) {
    if (!lod_->scene || cluster < -1 || cluster >= int(lod_->scene->clusterCount())) cluster = -1;
    lod_->picked = cluster;
    if (lod_->scene) lod_->scene->setHighlightedCluster(cluster);
    emit lodChanged(nullptr);
}

bool Session::exportLodStatistics(const QString& path, StatisticsFormat format) {
    if (!lod_->statistics) {
        emit errorOccurred(tr("Cannot export the LOD statistics"), tr("Build the LOD hierarchy first (LOD hierarchy dock)."));
        return false;
    }
    return writeExport(tr("Cannot export the LOD statistics"), path, [&] {
        conescope::exportLodStatistics(*lod_->statistics, exportSettings(shown_.settings, eyePosition_), path.toStdString(), format);
    });
}

const ClusterHierarchy* Session::lodHierarchy() const { return lod_->hierarchy.get(); }
const LodStatistics* Session::lodStatistics() const { return lod_->statistics ? &*lod_->statistics : nullptr; }
const LodThreshold& Session::lodThreshold() const { return lod_->threshold; }
int Session::lodLevelShown() const { return lod_->shown; }
const std::vector<std::vector<uint8_t>>& Session::lodCut() const { return lod_->cut; }
const ClusterScene* Session::lodScene() const { return lod_->scene.get(); }
const EyeMeasurement* Session::lodMeasurement() const { return lod_->scene && lod_->measurement ? &*lod_->measurement : nullptr; }
int Session::lodPickedCluster() const { return lod_->picked; }

const LodLevel* Session::lodLevelOnShow() const {
    if (!lod_->scene) return nullptr;
    if (lod_->shown == kLodCut) return lod_->cutLevel ? &*lod_->cutLevel : nullptr;
    return &lod_->hierarchy->levels[size_t(lod_->shown)];
}

std::optional<LodClusterId> Session::lodClusterOf(int cluster) const {
    if (!lod_->scene || cluster < 0 || cluster >= int(lod_->scene->clusterCount())) return std::nullopt;
    if (lod_->shown == kLodCut) return lod_->cutOrigin[size_t(cluster)];
    return LodClusterId{size_t(lod_->shown), uint32_t(cluster)};
}

std::optional<LodFamily> Session::lodPick() const {
    const std::optional<LodClusterId> id = lodClusterOf(lod_->picked);
    if (!id) return std::nullopt;
    return lodFamilyOf(*lod_->hierarchy, *id);
}

}  // namespace conescope
