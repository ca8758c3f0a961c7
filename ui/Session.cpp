#include "Session.h"

#include <algorithm>
#include <chrono>

#include <QFileInfo>

#include "MeshLoading.h"
#include "SceneBinding.h"
#include "TaskGroups.h"
#include "core/SettingsSchema.h"

namespace conescope {

namespace {

constexpr int animationIntervalMs = 150;

// Maps a stage's progress into [from, to] of the whole task.
ProgressCallback scaled(const ProgressCallback& progress, double from, double to) {
    return [progress, from, to](double fraction, const std::string& stage) {
        return progress(from + (to - from) * fraction, stage);
    };
}

// The settings with the default builder instead of a file builder whose ids could not be used, so
// a bad id file does not stick and raise its error again at every change.
Settings withoutClusterFile(Settings settings) {
    settings.builder = Settings{}.builder;
    settings.clusterFile.clear();
    settings.clusterIds.reset();
    return settings;
}

// The budget warning for what the window shows, with the fewest clusters its limits allow.
std::string budgetMissedIn(const Snapshot& shown) {
    const Settings& settings = shown.settings;
    const size_t fewest = settings.clusterCount != 0 ? fewestClustersWithin(shown.prepared->mesh(), settings.limits) : 0;
    return budgetMissed(settings, shown.clusters->partition.clusterCount, fewest);
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

// --- Loading and building ------------------------------------------------------------------------

void Session::openMesh(const QString& path) {
    // A new mesh replaces whatever was being computed for the old one.
    runner_.cancelAll();
    const std::string file = path.toStdString();
    const Settings settings = asked_;
    runner_.run<SceneResult>(
        taskgroups::load, tr("Loading %1").arg(QFileInfo(path).fileName()),
        [file, settings](const ProgressCallback& progress) {
            SceneResult result;
            std::shared_ptr<MeshletStream> meshlets;  // built while the mesh is prepared, when the builder starts there
            auto prepared = std::make_shared<PreparedMesh>(loadMesh(file, settings, scaled(progress, 0.0, 0.4), &meshlets));
            // An id file is read here, so the builder is chosen knowing whether it could be.
            Settings chosen = builderForMesh(withClusterIds(settings), prepared->mesh(), result.builderNote);
            std::shared_ptr<ClusterSet> clusters;
            try {
                clusters = std::make_shared<ClusterSet>(buildClusters(*prepared, chosen, nullptr, scaled(progress, 0.4, 0.9), meshlets.get()));
            } catch (const std::exception& error) {
                if (chosen.builder != Builder::File) throw;
                // A mesh that cannot be read by the file builder can still be looked at.
                result.builderNote = std::string(error.what()) + ": clusters from the " + toString(Settings{}.builder) + " builder instead";
                chosen = withoutClusterFile(chosen);
                clusters = std::make_shared<ClusterSet>(buildClusters(*prepared, chosen, nullptr, scaled(progress, 0.4, 0.9)));
            }
            progress(0.9, "scene");
            result.scene = makeScene(*prepared, *clusters);
            result.snapshot = Snapshot{chosen, prepared, clusters};
            return result;
        },
        [this, path](SceneResult& result) {
            const std::string builderNote = result.builderNote;
            // The builder the mesh is shown with is asked for from now on; whatever else was asked
            // meanwhile stays asked.
            const Settings& chosen = result.snapshot.settings;
            if (chosen.builder != asked_.builder || chosen.clusterFile != asked_.clusterFile) {
                asked_.builder = chosen.builder;
                asked_.clusterFile = chosen.clusterFile;
                emit settingsChanged(asked_);
            }
            showSceneResult(result, true);
            const std::string message = joinSentences(
                {loadMessage(*shown_.prepared), builderNote, budgetMissedIn(shown_)});
            emit meshShown(path, QString::fromStdString(message));
        },
        [this, path](const QString& error) {
            emit errorOccurred(tr("Cannot open %1").arg(QFileInfo(path).fileName()),
                               shown_.prepared ? error + tr("\n\nThe mesh shown before stays loaded.") : error);
            // What was asked while it loaded goes to the mesh still shown.
            if (shown_.prepared) reconcile();
        });
    buildStarted();
}

bool Session::needsBuild() const {
    return shown_.clusters && (shown_.prepared->fixWindingAsked != asked_.fixWinding || needsClusterFile(*shown_.prepared, asked_) ||
                               boundsChanged(shown_.clusters->builtWith, asked_));
}

void Session::applySettings(const Settings& settings) {
    asked_ = settings;
    emit settingsChanged(asked_);
    if (!shown_.prepared) {
        shown_.settings = settings;  // no mesh: the next one is loaded with them
        return;
    }
    // A mesh still loading picks them up when it arrives.
    if (!runner_.busy(taskgroups::load)) reconcile();
}

void Session::reconcile() {
    if (needsBuild()) {
        requestClusters();
        return;
    }
    // Back to what is built, or nothing to build: a queued build is not needed any more.
    runner_.cancel(taskgroups::clusters);
    const Settings before = shown_.settings;
    setShownSettings(asked_);
    const bool eyeChanged = displayedTest(before) != displayedTest(asked_) || before.orthographic != asked_.orthographic;
    const bool orbitChanged = eyeChanged || before.views != asked_.views || before.distance != asked_.distance;
    if (eyeChanged) updateEye();
    // A build asked for and given up may have cancelled the snapshot's orbit: measured again.
    if (orbitChanged || (!orbit_ && !runner_.busy(taskgroups::orbit))) {
        clearOrbit();
        requestOrbit();
    }
}

void Session::setShownSettings(const Settings& settings) {
    shown_.settings = settings;
    // A is seen from the same eyes as B.
    if (pin_) pin_->settings = withSharedOptions(pin_->settings, settings);
}

void Session::requestClusters() {
    if (!shown_.prepared || runner_.busy(taskgroups::load)) return;
    runner_.cancel(taskgroups::clusters);
    runner_.cancel(taskgroups::orbit);
    const Snapshot from = shown_;
    const Settings settings = asked_;
    // Another winding repair, or a meshlet file the mesh was not read with (it may cut polygons).
    const bool reprepare = from.prepared->fixWindingAsked != settings.fixWinding || needsClusterFile(*from.prepared, settings);
    runner_.run<SceneResult>(
        taskgroups::clusters, tr("Building clusters"),
        [from, settings, reprepare](const ProgressCallback& progress) {
            std::shared_ptr<const PreparedMesh> prepared = from.prepared;
            if (reprepare) prepared = std::make_shared<PreparedMesh>(reprepareMesh(*prepared, settings, scaled(progress, 0.0, 0.3)));
            auto clusters = std::make_shared<ClusterSet>(
                buildClusters(*prepared, withClusterIds(settings), reprepare ? nullptr : from.clusters.get(), scaled(progress, reprepare ? 0.3 : 0.0, 0.9)));
            progress(0.9, "scene");
            SceneResult result;
            result.scene = makeScene(*prepared, *clusters);
            result.snapshot = Snapshot{settings, prepared, clusters};
            return result;
        },
        [this](SceneResult& result) {
            showSceneResult(result, false);
            const std::string missed = budgetMissedIn(shown_);
            if (!missed.empty()) emit notice(QString::fromStdString(missed), 8000);
        },
        [this, settings](const QString& error) {
            if (settings.builder == Builder::File) {
                // Back to the default builder: the id file's error is said once, not at every change.
                emit errorOccurred(tr("Cannot use the cluster ids"),
                                   error + tr("\n\nThe clusters come from the %1 builder instead.")
                                               .arg(QString::fromStdString(toString(Settings{}.builder))));
                applySettings(withoutClusterFile(asked_));
                return;
            }
            buildFailed(error);
        });
    buildStarted();
}

void Session::buildStarted() {
    if (!cancelNextBuild_) return;
    cancelNextBuild_ = false;
    cancel();
}

void Session::buildFailed(const QString& error) {
    emit errorOccurred(tr("Cannot build the clusters"), error + tr("\n\nThe clusters and settings shown before stay."));
    revertToSnapshot();
}

void Session::cancel() {
    runner_.cancelAll();
    revertToSnapshot();
    emit notice(tr("Cancelled: the mesh, clusters and settings shown before stay"), 5000);
}

void Session::revertToSnapshot() {
    if (!shown_.prepared || sameSettings(asked_, shown_.settings)) return;
    asked_ = shown_.settings;
    emit settingsChanged(asked_);
}

void Session::requestOrbit() {
    if (!shown_.clusters) return;
    runner_.cancel(taskgroups::orbit);
    const Snapshot snapshot = shown_;
    runner_.run<CullTestStatistics>(
        taskgroups::orbit, tr("Orbit statistics"),
        [snapshot](const ProgressCallback& progress) {
            return measureOrbit(*snapshot.prepared, *snapshot.clusters, snapshot.settings, progress);
        },
        [this, snapshot](CullTestStatistics& orbit) {
            // Made for other clusters meanwhile: their own orbit follows. (A change of test, views or
            // projection asks for a new orbit, which cancels this one.)
            if (snapshot.clusters != shown_.clusters) return;
            orbit_ = std::move(orbit);
            emit orbitChanged();
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot measure the orbit"), error); });
    requestOrbitComparison();
}

void Session::showSceneResult(SceneResult& result, bool newMesh) {
    const bool samePartition = !newMesh && shown_.clusters && result.snapshot.prepared == shown_.prepared &&
                               !partitionChanged(shown_.clusters->builtWith, result.snapshot.clusters->builtWith);
    // The views take the previous scene's actors out when they hear of the new one.
    const std::unique_ptr<ClusterScene> previous = std::move(scene_);
    shown_ = result.snapshot;
    scene_ = std::move(result.scene);
    for (const auto& [layer, visible] : layers_) scene_->setLayerVisible(layer, visible);
    scene_->setFaceColoring(coloring_);
    if (legendViewHeight_ > 0) scene_->fitLegend(legendViewHeight_, legendPixelRatio_);
    if (!samePartition || picked_ >= int(shown_.clusters->partition.clusterCount)) picked_ = -1;
    scene_->setHighlightedCluster(picked_);
    orbit_.reset();
    orbitComparison_.reset();
    if (newMesh) dropPin();
    else dropStalePin();
    // What was asked meanwhile and needs no other stages is shown with these at once.
    const bool stale = needsBuild();
    setShownSettings(stale ? shown_.settings : asked_);
    if (newMesh) {
        if (!eyeGiven_) eyePosition_ = startingEyePosition(shown_.prepared->box, shown_.settings);
        eyeGiven_ = false;
        orbitStep_ = -1;
    }
    measureCurrentEye();
    emit sceneReplaced(previous.get(), newMesh);
    emit eyeMoved();
    emit eyeMeasured();
    if (stale) requestClusters();
    else requestOrbit();
}

void Session::clearOrbit() {
    orbit_.reset();
    emit orbitChanged();
}

// --- Exports ---------------------------------------------------------------------------------------

void Session::startStatisticsExport(const QString& path, StatisticsFormat format, bool orbit,
                                    const std::function<void(bool)>& finished) {
    if (!shown_.clusters) {
        emit errorOccurred(tr("Cannot export statistics"), tr("No mesh is loaded."));
        finished(false);
        return;
    }
    // The snapshot shown (and A's), not the settings a build may be making meanwhile.
    const Snapshot b = shown_;
    const std::optional<Snapshot> a = pin_;
    const Settings settingsB = exportSettings(b.settings, orbit ? std::nullopt : std::optional<glm::dvec3>(eyePosition_));
    const std::string file = path.toStdString();
    runner_.run<size_t>(
        taskgroups::exports, tr("Exporting statistics"),
        [a, b, settingsB, file, format](const ProgressCallback& progress) -> size_t {
            if (!a) return conescope::exportStatistics(*b.prepared, *b.clusters, settingsB, file, format, progress).viewCount;
            const Settings settingsA = withSharedOptions(a->settings, settingsB);
            return exportComparison(*b.prepared, {*a->clusters, settingsA}, {*b.clusters, settingsB}, file, format, progress)
                .views.size();
        },
        [this, path, finished](size_t& views) {
            emit notice(tr("Wrote %1 (%2 views)").arg(path).arg(views), 6000);
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
    if (!shown_.clusters) {
        emit errorOccurred(tr("Cannot export the partition"), tr("No mesh is loaded."));
        return false;
    }
    try {
        conescope::exportPartition(*shown_.prepared, *shown_.clusters, displayedTest(shown_.settings), measurement(),
                                   path.toStdString());
    } catch (const std::exception& error) {
        emit errorOccurred(tr("Cannot export the partition"), QString::fromStdString(error.what()));
        return false;
    }
    emit notice(tr("Wrote %1").arg(path), 6000);
    return true;
}

}  // namespace conescope
