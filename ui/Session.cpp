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

// The settings with the default builder instead of a file builder whose ids could not be used, so
// a bad id file does not stick and raise its error again at every change.
Settings withoutClusterFile(Settings settings) {
    settings.builder = Settings{}.builder;
    settings.clusterFile.clear();
    settings.clusterIds.reset();
    return settings;
}

// What the window says when most of the shown clusters can never be culled (uncullableNote).
std::string uncullableIn(const Snapshot& shown) {
    size_t uncullable = 0;
    for (const ConeOfNormals& cone : shown.clusters->bounds.cones) uncullable += !cone.cullable;
    return uncullableNote(uncullable, shown.clusters->bounds.count());
}

// The budget warning for what the window shows, with the fewest clusters its limits allow.
std::string budgetMissedIn(const Snapshot& shown) {
    const Settings& settings = shown.settings;
    const size_t fewest = settings.clusterCount != 0 ? fewestClustersWithin(shown.prepared->mesh(), settings.limits) : 0;
    return budgetMissed(settings, shown.clusters->partition.clusterCount, fewest);
}

// What the window says of the shown clusters once built: a missed budget, best's fallback to the
// balanced partition, most clusters never cullable.
std::string clusterNotesIn(const Snapshot& shown) {
    return joinSentences({budgetMissedIn(shown), bestEffortNote(shown.clusters->bestEffort), uncullableIn(shown)});
}

// Whether the progress's stage is the one named: the same text, or the name and a space before the rest.
bool stageNamed(const QString& stage, const QString& name) {
    return stage == name || (stage.startsWith(name) && stage.size() > name.size() && stage[name.size()] == QLatin1Char(' '));
}

}  // namespace

const CullTestStatistics* Snapshot::orbitStatistics() const {
    return orbit && !firstStaleStage(orbit->settings, settings) ? &orbit->statistics : nullptr;
}

std::optional<Session::OrbitComparison> Session::measureSnapshot(Snapshot& b, const std::optional<Snapshot>& pin,
                                                                 const ProgressCallback& progress) {
    const bool compare = pin && pin->prepared == b.prepared;
    if (!b.orbitStatistics()) {
        auto orbit = std::make_shared<OrbitMeasurement>();
        orbit->settings = b.settings;
        const double end = compare ? 0.5 : 1.0, split = b.settings.conesPerCluster > 1 ? 0.5 * end : end;
        orbit->statistics = measureOrbit(*b.prepared, *b.clusters, b.settings, progressWithin(progress, 0.0, split));
        if (b.settings.conesPerCluster > 1) {
            const PreparedMesh& prepared = *b.prepared;
            const ClusterBounds& bounds = b.clusters->bounds;
            auto multi = std::make_shared<const MultiCones>(computeMultiCones(prepared.mesh(), prepared.faces, bounds, b.settings.conesPerCluster));
            orbit->multiCones = measureMultiCones(prepared.mesh(), prepared.world, prepared.faces, subGroupRecord(*multi, multi->cones, bounds.spheres),
                                                  orbitOf(b.settings, prepared.box), progressWithin(progress, split, end));
            orbit->multi = std::move(multi);
        }
        b.orbit = std::move(orbit);
    }
    if (!compare) return std::nullopt;
    OrbitComparison result{*pin, b, {}};
    result.a.settings = withSharedOptions(pin->settings, b.settings);
    result.comparison = compareClusterSets(*b.prepared, result.a.configuration(), b.configuration(), orbitOf(b.settings, b.prepared->box),
                                           progressWithin(progress, 0.5, 1.0, "comparing A and B"));
    return result;
}

Session::Session(QObject* parent) : QObject(parent), layers_(firstLookLayers()), lod_(std::make_unique<SessionLod>()) {
    animationTimer_.setInterval(animationIntervalMs);
    connect(&animationTimer_, &QTimer::timeout, this, [this]() { stepOrbit(1); });
    connect(&runner_, &TaskRunner::taskStarted, this, [this](const QString& title) {
        emit taskStarted(title);
        stageShown(title);
    });
    connect(&runner_, &TaskRunner::progressChanged, this, [this](double fraction, const QString& stage) {
        emit progressChanged(fraction, stage);
        stageShown(stage);
    });
    // The task is cancelled already, where it showed the stage: the rest of Cancel's work.
    connect(&runner_, &TaskRunner::stageCancelled, this, [this]() {
        cancelStage_.clear();
        cancel();
    });
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
            auto prepared = std::make_shared<PreparedMesh>(loadMesh(file, settings, progressWithin(progress, 0.0, 0.4), &meshlets));
            // An id file is read here, so the builder is chosen knowing whether it could be.
            Settings chosen = builderForMesh(withClusterIds(settings), prepared->mesh(), result.builderNote);
            std::shared_ptr<ClusterSet> clusters;
            try {
                clusters = std::make_shared<ClusterSet>(buildClusters(*prepared, chosen, nullptr, progressWithin(progress, 0.4, 0.9), meshlets.get()));
            } catch (const std::exception& error) {
                if (chosen.builder != Builder::File) throw;
                // A mesh that cannot be read by the file builder can still be looked at.
                result.builderNote = std::string(error.what()) + ": clusters from the " + toString(Settings{}.builder) + " builder instead";
                chosen = withoutClusterFile(chosen);
                clusters = std::make_shared<ClusterSet>(buildClusters(*prepared, chosen, nullptr, progressWithin(progress, 0.4, 0.9)));
            }
            progress(0.85, "scene");
            result.scene = makeScene(*prepared, *clusters);
            result.snapshot = Snapshot{chosen, prepared, clusters, nullptr};
            measureSnapshot(result.snapshot, std::nullopt, progressWithin(progress, 0.9, 1.0));  // a new mesh drops A
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
                {loadMessage(*shown_.prepared), builderNote, clusterNotesIn(shown_)});
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
    Snapshot asked = shown_;
    asked.settings = asked_;
    if (asked.orbitStatistics() && (!pin_ || orbitComparison_)) {
        // Nothing the orbit or the comparison depends on: shown at once.
        runner_.cancel(taskgroups::orbit);
        setShownSettings(asked_);
        return;
    }
    requestOrbit();
}

void Session::setShownSettings(const Settings& settings) {
    shown_.settings = settings;
    // A is seen from the same eyes as B.
    if (pin_) pin_->settings = withSharedOptions(pin_->settings, settings);
    dropStaleGranularity();
}

void Session::requestClusters() {
    if (!shown_.prepared || runner_.busy(taskgroups::load)) return;
    runner_.cancel(taskgroups::clusters);
    runner_.cancel(taskgroups::orbit);
    const Snapshot from = shown_;
    const Settings settings = asked_;
    // Another winding repair, or a meshlet file the mesh was not read with (it may cut polygons).
    const bool reprepare = from.prepared->fixWindingAsked != settings.fixWinding || needsClusterFile(*from.prepared, settings);
    const std::optional<Snapshot> pin = pin_;
    runner_.run<SceneResult>(
        taskgroups::clusters, tr("Building clusters"),
        [from, settings, reprepare, pin](const ProgressCallback& progress) {
            std::shared_ptr<const PreparedMesh> prepared = from.prepared;
            if (reprepare) prepared = std::make_shared<PreparedMesh>(reprepareMesh(*prepared, settings, progressWithin(progress, 0.0, 0.3)));
            auto clusters = std::make_shared<ClusterSet>(buildClusters(*prepared, withClusterIds(settings), reprepare ? nullptr : from.clusters.get(),
                                                                       progressWithin(progress, reprepare ? 0.3 : 0.0, 0.8)));
            progress(0.8, "scene");
            SceneResult result;
            result.scene = makeScene(*prepared, *clusters);
            result.snapshot = Snapshot{settings, prepared, clusters, nullptr};
            result.comparison = measureSnapshot(result.snapshot, pin, progressWithin(progress, 0.85, 1.0));
            return result;
        },
        [this](SceneResult& result) {
            showSceneResult(result, false);
            const std::string said = clusterNotesIn(shown_);
            if (!said.empty()) emit notice(QString::fromStdString(said), 8000);
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
    const bool working = runner_.busy();
    runner_.cancelAll();
    revertToSnapshot();
    if (!working) {
        // Pressed as the last task ended: what it made is shown whole.
        emit notice(tr("Nothing to cancel: what is shown was already finished"), 5000);
        return;
    }
    // A pinned while new clusters were built is compared only once they are shown: without its
    // comparison, it is unpinned (the window never shows A without A against B).
    if (pin_ && !orbitComparison_) clearPin();
    emit notice(tr("Cancelled: the mesh, clusters, settings and orbit shown before stay"), 5000);
}

void Session::cancelAtStage(const QString& stage) {
    cancelStage_ = stage;
    stagesSeen_.clear();
    runner_.cancelAtStage(stage, [stage](const QString& shown) { return stageNamed(shown, stage); });
}

void Session::stageShown(const QString& stage) {
    if (!cancelStage_.isEmpty() && !stagesSeen_.contains(stage)) stagesSeen_.push_back(stage);
}

void Session::revertToSnapshot() {
    if (!shown_.prepared || sameSettings(asked_, shown_.settings)) return;
    asked_ = shown_.settings;
    emit settingsChanged(asked_);
}

void Session::requestOrbit() {
    if (!shown_.clusters) return;
    runner_.cancel(taskgroups::orbit);
    Snapshot asked = shown_;
    asked.settings = asked_;
    const std::optional<Snapshot> pin = pin_;
    using Measured = std::pair<Snapshot, std::optional<OrbitComparison>>;
    runner_.run<Measured>(
        taskgroups::orbit, tr("Orbit statistics"),
        [asked, pin](const ProgressCallback& progress) {
            Snapshot measured = asked;
            std::optional<OrbitComparison> comparison = measureSnapshot(measured, pin, progress);
            return Measured{measured, comparison};
        },
        [this, pin](Measured& measured) {
            // Other clusters shown meanwhile, or other settings asked: those asked for their own.
            if (measured.first.clusters != shown_.clusters || !sameSettings(measured.first.settings, asked_)) return;
            const Settings before = shown_.settings;
            setShownSettings(measured.first.settings);
            shown_.orbit = measured.first.orbit;
            showSubGroups();
            adoptComparison(measured.second);
            if (displayedTest(before) != displayedTest(shown_.settings) || before.orthographic != shown_.settings.orthographic) updateEye();
            emit orbitChanged();
            emit comparisonChanged();
            if (!pin || !pin_ || pin->clusters != pin_->clusters) completeComparison();  // A pinned meanwhile
        },
        [this](const QString& error) {
            emit errorOccurred(tr("Cannot measure the orbit"), error + tr("\n\nThe settings and orbit shown before stay."));
            revertToSnapshot();
        });
}

void Session::adoptComparison(const std::optional<OrbitComparison>& comparison) {
    orbitComparison_.reset();
    if (!pin_ || !comparison || comparison->a.clusters != pin_->clusters || comparison->b.clusters != shown_.clusters) return;
    if (!sameSettings(comparison->a.settings, pin_->settings) || !sameSettings(comparison->b.settings, shown_.settings)) return;
    orbitComparison_ = comparison;
}

void Session::completeComparison() {
    if (pin_ && !orbitComparison_ && pin_->prepared == shown_.prepared && !runner_.busy(taskgroups::load) &&
        !runner_.busy(taskgroups::clusters))
        requestOrbit();
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
    if (newMesh) dropPin();
    else dropStalePin();
    setShownSettings(shown_.settings);  // A is seen from these eyes
    adoptComparison(result.comparison);
    if (newMesh) {
        if (!eyeGiven_) eyePosition_ = startingEyePosition(shown_.prepared->box, shown_.settings);
        eyeGiven_ = false;
        orbitStep_ = -1;
    }
    measureCurrentEye();
    emit sceneReplaced(previous.get(), newMesh);
    updateLod();
    emit eyeMoved();
    emit eyeMeasured();
    emit orbitChanged();
    emit comparisonChanged();
    // What was asked meanwhile (other clusters, another test or views) or A pinned meanwhile follows.
    reconcile();
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
    return writeExport(tr("Cannot export the partition"), path, [&] {
        conescope::exportPartition(*shown_.prepared, *shown_.clusters, displayedTest(shown_.settings), measurement(),
                                   path.toStdString());
    });
}

bool Session::writeExport(const QString& what, const QString& path, const std::function<void()>& write) {
    try {
        write();
    } catch (const std::exception& error) {
        emit errorOccurred(what, QString::fromStdString(error.what()));
        return false;
    }
    emit notice(tr("Wrote %1").arg(path), 6000);
    return true;
}

}  // namespace conescope
