#include "Session.h"

#include <algorithm>
#include <chrono>

#include <QFileInfo>

#include "MeshLoading.h"
#include "SceneBinding.h"
#include "TaskGroups.h"

namespace conescope {

namespace {

constexpr int animationIntervalMs = 150;


// Maps a stage's progress into [from, to] of the whole task.
ProgressCallback scaled(const ProgressCallback& progress, double from, double to) {
    return [progress, from, to](double fraction, const std::string& stage) {
        return progress(from + (to - from) * fraction, stage);
    };
}

}  // namespace

namespace {

// The settings with the default builder instead of a file builder whose ids could not be used, so
// a bad id file does not stick and raise its error again at every change.
Settings withoutClusterFile(Settings settings) {
    settings.builder = Settings{}.builder;
    settings.clusterFile.clear();
    return settings;
}

}  // namespace

Session::Session(QObject* parent) : QObject(parent), layers_(firstLookLayers()) {
    animationTimer_.setInterval(animationIntervalMs);
    connect(&animationTimer_, &QTimer::timeout, this, [this]() { stepOrbit(1); });
    connect(&runner_, &TaskRunner::taskStarted, this, &Session::taskStarted);
    connect(&runner_, &TaskRunner::progressChanged, this, &Session::progressChanged);
    connect(&runner_, &TaskRunner::idle, this, &Session::idle);
}

Session::~Session() {
    animationTimer_.stop();
    runner_.cancelAll();
}

// --- Loading and recomputing ---------------------------------------------------------------------

void Session::openMesh(const QString& path) {
    // A new mesh replaces whatever was being computed for the old one.
    runner_.cancelAll();
    const std::string file = path.toStdString();
    const Settings settings = settings_;
    runner_.run<SceneResult>(
        taskgroups::load, tr("Loading %1").arg(QFileInfo(path).fileName()),
        [file, settings](const ProgressCallback& progress) {
            SceneResult result;
            std::shared_ptr<MeshletStream> meshlets;  // built while the mesh is prepared, when the builder starts there
            auto prepared = std::make_shared<PreparedMesh>(loadMesh(file, settings, scaled(progress, 0.0, 0.4), &meshlets));
            Settings chosen = builderForMesh(settings, prepared->mesh(), result.builderNote);
            std::shared_ptr<ClusterSet> clusters;
            try {
                clusters = std::make_shared<ClusterSet>(
                    buildClusters(*prepared, chosen, nullptr, scaled(progress, 0.4, 0.9), meshlets.get()));
            } catch (const std::exception& error) {
                if (chosen.builder != Builder::File) throw;
                // A mesh that cannot be read by the file builder can still be looked at.
                result.builderNote = std::string(error.what()) + ": clusters from the " + toString(Settings{}.builder) + " builder instead";
                clusters = std::make_shared<ClusterSet>(
                    buildClusters(*prepared, withoutClusterFile(chosen), nullptr, scaled(progress, 0.4, 0.9)));
            }
            progress(0.9, "scene");
            result.scene = makeScene(*prepared, *clusters);
            result.prepared = prepared;
            result.clusters = clusters;
            return result;
        },
        [this, path](SceneResult& result) {
            const std::string builderNote = result.builderNote;
            adoptBuilderOf(*result.clusters);
            showSceneResult(result, true);
            std::string message = loadMessage(*prepared_);
            for (const std::string& note : {builderNote, budgetMissed(clusters_->settings, clusters_->partition.clusterCount)})
                if (!note.empty()) message += (message.empty() ? "" : "; ") + note;
            emit meshShown(path, QString::fromStdString(message));
        },
        [this, path](const QString& error) {
            emit errorOccurred(tr("Cannot open %1").arg(QFileInfo(path).fileName()),
                               prepared_ ? error + tr("\n\nThe mesh shown before stays loaded.") : error);
        });
}

void Session::requestClusters(bool reprepare) {
    // A mesh still loading picks the current settings up when it arrives.
    if (!prepared_ || runner_.busy(taskgroups::load)) return;
    runner_.cancel(taskgroups::clusters);
    runner_.cancel(taskgroups::orbit);
    const std::shared_ptr<const PreparedMesh> prepared = prepared_;
    const std::shared_ptr<const ClusterSet> previous = reprepare ? nullptr : clusters_;
    const Settings settings = settings_;
    runner_.run<SceneResult>(
        taskgroups::clusters, tr("Building clusters"),
        [prepared, previous, settings, reprepare](const ProgressCallback& progress) {
            SceneResult result;
            result.prepared = prepared;
            if (reprepare) result.prepared = std::make_shared<PreparedMesh>(reprepareMesh(*prepared, settings, scaled(progress, 0.0, 0.3)));
            auto clusters = std::make_shared<ClusterSet>(
                buildClusters(*result.prepared, settings, previous.get(), scaled(progress, reprepare ? 0.3 : 0.0, 0.9)));
            progress(0.9, "scene");
            result.scene = makeScene(*result.prepared, *clusters);
            result.clusters = clusters;
            return result;
        },
        [this](SceneResult& result) {
            showSceneResult(result, false);
            const std::string missed = budgetMissed(clusters_->settings, clusters_->partition.clusterCount);
            if (!missed.empty()) emit notice(QString::fromStdString(missed), 8000);
        },
        [this](const QString& error) {
            if (settings_.builder == Builder::File) {
                // Back to the default builder: the id file's error is said once, not at every change.
                emit errorOccurred(tr("Cannot use the cluster ids"),
                                   error + tr("\n\nThe clusters come from the %1 builder instead.")
                                               .arg(QString::fromStdString(toString(Settings{}.builder))));
                settings_ = withoutClusterFile(settings_);
                emit settingsAdjusted(settings_);
                requestClusters(false);
                return;
            }
            emit errorOccurred(tr("Cannot build the clusters"), error);
        });
}

void Session::requestOrbit() {
    if (!prepared_ || !clusters_) return;
    runner_.cancel(taskgroups::orbit);
    const std::shared_ptr<const PreparedMesh> prepared = prepared_;
    const std::shared_ptr<const ClusterSet> clusters = clusters_;
    const Settings settings = settings_;
    runner_.run<TestStatistics>(
        taskgroups::orbit, tr("Orbit statistics"),
        [prepared, clusters, settings](const ProgressCallback& progress) {
            return measureOrbit(*prepared, *clusters, settings, progress);
        },
        [this, clusters](TestStatistics& orbit) {
            if (clusters != clusters_) return;  // the clusters changed meanwhile; their own orbit follows
            orbit_ = std::move(orbit);
            emit orbitChanged();
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot measure the orbit"), error); });
    requestOrbitComparison();
}

void Session::showSceneResult(SceneResult& result, bool newMesh) {
    const bool samePartition = !newMesh && clusters_ && result.prepared == prepared_ &&
                               !partitionChanged(clusters_->settings, result.clusters->settings);
    // The views take the previous scene's actors out when they hear of the new one.
    const std::unique_ptr<ClusterScene> previous = std::move(scene_);
    prepared_ = result.prepared;
    clusters_ = result.clusters;
    scene_ = std::move(result.scene);
    for (const auto& [layer, visible] : layers_) scene_->setLayerVisible(layer, visible);
    scene_->setFaceColoring(coloring_);
    if (!samePartition || picked_ >= int(clusters_->partition.clusterCount)) picked_ = -1;
    scene_->setHighlightedCluster(picked_);
    orbit_.reset();
    orbitComparison_.reset();
    if (newMesh) clearPin();
    else dropStalePin();
    if (newMesh) {
        if (!eyeGiven_) eyePosition_ = startingEyePosition(prepared_->box, settings_);
        eyeGiven_ = false;
        orbitStep_ = -1;
    }
    measureCurrentEye();
    emit sceneReplaced(previous.get(), newMesh);
    emit eyeMoved();
    emit eyeMeasured();
    // The settings may have moved on while this was computed.
    const bool reprepare = prepared_->fixWindingAsked != settings_.fixWinding || needsClusterFile(*prepared_, settings_);
    if (reprepare || boundsChanged(clusters_->settings, settings_))
        requestClusters(reprepare);
    else
        requestOrbit();
}

void Session::applySettings(const Settings& settings) {
    const Settings before = settings_;
    settings_ = settings;
    if (!prepared_ || !clusters_) return;
    const bool reprepare = prepared_->fixWindingAsked != settings.fixWinding || needsClusterFile(*prepared_, settings);
    if (reprepare || boundsChanged(clusters_->settings, settings)) {
        requestClusters(reprepare);
        return;
    }
    // Back to what is built: nothing queued is needed any more.
    runner_.cancel(taskgroups::clusters);
    const bool eyeChanged = displayedTest(before) != displayedTest(settings) || before.orthographic != settings.orthographic;
    const bool orbitChanged = eyeChanged || before.views != settings.views || before.distance != settings.distance;
    if (eyeChanged) updateEye();
    if (orbitChanged) {
        clearOrbit();
        requestOrbit();
    }
}

void Session::clearOrbit() {
    orbit_.reset();
    emit orbitChanged();
}

// --- Exports ---------------------------------------------------------------------------------------

void Session::startStatisticsExport(const QString& path, StatisticsFormat format, bool orbit,
                                    const std::function<void(bool)>& finished) {
    if (!prepared_) {
        emit errorOccurred(tr("Cannot export statistics"), tr("No mesh is loaded."));
        finished(false);
        return;
    }
    const std::shared_ptr<const PreparedMesh> prepared = prepared_;
    const std::shared_ptr<const ClusterSet> clusters = clusters_;
    const Settings settings = exportSettings(settings_, orbit ? std::nullopt : std::optional<glm::dvec3>(eyePosition_));
    const std::string file = path.toStdString();
    runner_.run<RunStatistics>(
        taskgroups::exports, tr("Exporting statistics"),
        [prepared, clusters, settings, file, format](const ProgressCallback& progress) {
            return conescope::exportStatistics(*prepared, *clusters, settings, file, format, progress);
        },
        [this, path, finished](RunStatistics& run) {
            emit notice(tr("Wrote %1 (%2 views)").arg(path).arg(run.viewCount), 6000);
            finished(true);
        },
        [this, finished](const QString& error) {
            emit errorOccurred(tr("Cannot export statistics"), error);
            finished(false);
        });
}

bool Session::exportStatistics(const QString& path, StatisticsFormat format, bool orbit) {
    auto written = std::make_shared<bool>(false);
    startStatisticsExport(path, format, orbit, [written](bool success) { *written = success; });
    runner_.waitUntilIdle();
    return *written;
}

bool Session::exportPartition(const QString& path) {
    if (!prepared_ || !clusters_) {
        emit errorOccurred(tr("Cannot export the partition"), tr("No mesh is loaded."));
        return false;
    }
    try {
        conescope::exportPartition(*prepared_, *clusters_, measurement(), path.toStdString());
    } catch (const std::exception& error) {
        emit errorOccurred(tr("Cannot export the partition"), QString::fromStdString(error.what()));
        return false;
    }
    emit notice(tr("Wrote %1").arg(path), 6000);
    return true;
}

// --- The eye ---------------------------------------------------------------------------------------

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
    if (!prepared_ || position == eyePosition_) return;
    moveEyeSoon(position);
}

void Session::moveEyeToStart() {
    if (prepared_) moveEye(startingEyePosition(prepared_->box, settings_), -1);
}

void Session::stepOrbit(int step) {
    if (!prepared_) return;
    const std::vector<Eye> views = orbitOf(settings_, prepared_->box);
    if (views.empty()) return;
    const long count = long(views.size());
    const long next = orbitStep_ < 0 ? (step > 0 ? 0 : count - 1) : ((orbitStep_ + step) % count + count) % count;
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
    if (!prepared_ || !clusters_ || !scene_) return;
    measureCurrentEye();
    emit eyeMeasured();
}

void Session::measureCurrentEye() {
    const auto start = std::chrono::steady_clock::now();
    try {
        const Eye eye = eyeAt(settings_, eyePosition_, prepared_->box);
        measurement_ = measureEye(*prepared_, *clusters_, eye, displayedTest(settings_));
    } catch (const std::exception& error) {
        // An orthographic eye at the mesh centre has no direction: say so and show no decision.
        measurement_.reset();
        eyeError_ = QString::fromStdString(error.what());
        scene_->clearClusterDecisions();
        scene_->setTestDrawing({});
        measurePinnedEye();
        return;
    }
    eyeError_.clear();
    showMeasurement(*scene_, *prepared_, *clusters_, *measurement_);
    showEyeColouring(*scene_, *prepared_, *clusters_, *measurement_, coloring_);
    showTestDrawing(*scene_, *prepared_, *clusters_, picked_, *measurement_);
    measurePinnedEye();
    eyeSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --- Scene display and picking -----------------------------------------------------------------------

void Session::setLayerVisible(Layer layer, bool visible) {
    layers_[layer] = visible;
    if (scene_) scene_->setLayerVisible(layer, visible);
}

void Session::setFaceColoring(FaceColoring coloring) {
    coloring_ = coloring;
    if (!scene_) return;
    scene_->setFaceColoring(coloring);
    if (measurement_) showEyeColouring(*scene_, *prepared_, *clusters_, *measurement_, coloring);
}

void Session::pickCluster(int cluster) {
    if (!scene_ || cluster < -1 || cluster >= int(scene_->clusterCount())) cluster = -1;
    picked_ = cluster;
    if (scene_) scene_->setHighlightedCluster(cluster);
    if (scene_ && measurement_) showTestDrawing(*scene_, *prepared_, *clusters_, cluster, *measurement_);
    emit pickChanged(cluster);
}

const std::vector<ViewStatistics>& Session::orbitRows() const {
    static const std::vector<ViewStatistics> none;
    return orbit_ ? orbit_->views : none;
}

void Session::showClusterWhereItIsLost(int cluster) {
    pickCluster(cluster);
    if (!prepared_ || !clusters_ || picked_ < 0) return;
    const long view = viewMissingCluster(*prepared_, *clusters_, settings_, uint32_t(picked_));
    if (view >= 0) {
        moveEye(orbitOf(settings_, prepared_->box)[size_t(view)].position, view);
    } else {
        emit notice(tr("Cluster %1 is never drawn with back faces over the orbit").arg(picked_), 6000);
    }
}

void Session::adoptBuilderOf(const ClusterSet& clusters) {
    if (clusters.settings.builder == settings_.builder && clusters.settings.clusterFile == settings_.clusterFile) return;
    settings_.builder = clusters.settings.builder;
    settings_.clusterFile = clusters.settings.clusterFile;
    emit settingsAdjusted(settings_);
}

}  // namespace conescope
