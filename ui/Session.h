// What the window shows, without any widget: one snapshot of the settings and the stages built with
// them (prepared mesh, clusters, the orbit's statistics), the scene of those clusters, the cull eye's
// measurement, the cull eye and the picked cluster. Everything the window shows or exports is made
// from the snapshot (and from A's while one is pinned); the settings widgets show its settings. The
// slow stages run through a TaskRunner; every number comes from core/Pipeline.h. Signals say what is
// new, and the views (ObserverView, the docks) show it.
//
// A snapshot is shown whole: new clusters come with their scene, their orbit and (with A pinned) A
// against them; other settings of the test or views come with their orbit. So a Cancel at any stage
// drops what was being made and everything shown stays as it was, made with the settings shown.
//
// The public functions under "Actions" are what a click, a key or a replayed step (ReplayPlayer) does:
// both go through them.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include "Exports.h"
#include "SessionLod.h"
#include "TaskRunner.h"
#include "core/Comparison.h"
#include "core/Granularity.h"
#include "core/Lesson.h"
#include "core/MultiConeCulling.h"
#include "core/Pipeline.h"
#include "scene/ClusterScene.h"

namespace conescope {

// The displayed test over the orbit (measureOrbit) and the settings it was measured with.
struct OrbitMeasurement {
    Settings settings;
    CullTestStatistics statistics;
    // settings.conesPerCluster > 1: the clusters split into K sub-groups and that record over the orbit.
    std::shared_ptr<const MultiCones> multi;
    MultiConeCulling multiCones;
};

// The K-cone record from the cull eye: each sub-group's verdict (cullSubGroups), the faces' facing
// (classifyFaces) and the counts the panels show.
struct SubGroupsFromEye {
    std::shared_ptr<const MultiCones> multi;
    std::vector<uint8_t> culled;
    std::vector<Facing> facing;
    SubGroupEyeCounts counts;
};

// Settings and the stages built with them: what is shown, or what is pinned as A.
struct Snapshot {
    Settings settings;
    std::shared_ptr<const PreparedMesh> prepared;
    std::shared_ptr<const ClusterSet> clusters;
    std::shared_ptr<const OrbitMeasurement> orbit;
    ClusterConfiguration configuration() const { return {*clusters, settings}; }
    // The orbit's statistics when they were measured with these settings, else null.
    const CullTestStatistics* orbitStatistics() const;
};

class Session : public QObject {
    Q_OBJECT
public:
    explicit Session(QObject* parent = nullptr);
    ~Session() override;

    // --- Actions -----------------------------------------------------------------------------------
    // Reads, prepares and clusters the file; meshShown() when it is shown, errorOccurred() when it
    // cannot be read (the mesh shown before stays).
    void openMesh(const QString& path);
    // Asks for these settings: what they make stale is built again in the background (the snapshot
    // changes when it is ready), the rest (test, projection, views) at once. settingsChanged() tells
    // the widgets; a cancelled or failed build puts the snapshot's settings back.
    void applySettings(const Settings& settings);
    // Cancels every background task, as the status bar's Cancel button: the snapshot stays, and so
    // do its settings (settingsChanged() when the widgets showed others), orbit and comparison.
    void cancel();
    // The next build (a load or new clusters) is cancelled as soon as it starts, as if Cancel were
    // pressed while it runs.
    void cancelNextBuild() { cancelNextBuild_ = true; }
    // Cancel is pressed when the progress next shows this stage: a task's title ("Building clusters")
    // or a stage of it ("scene", "orbit statistics"; a name also matches a stage it starts, followed
    // by a space: "bounds" matches "bounds (minimal)"). Empty disarms. cancelStageArmed() stays true
    // until the stage came; stagesSeen() lists the stages shown meanwhile.
    void cancelAtStage(const QString& stage);
    bool cancelStageArmed() const { return !cancelStage_.isEmpty(); }
    const QStringList& stagesSeen() const { return stagesSeen_; }
    void moveEye(const glm::dvec3& position, long orbitStep = -1);
    // The eye to orbit view `view` (0-based); false when the orbit has no such view.
    bool moveEyeToOrbitView(long view);
    // The next (step 1) or previous (-1) orbit view: from the view the eye is on, or from the one
    // nearest to it when it was moved off the orbit.
    void stepOrbit(int step);
    void moveEyeToStart();
    // A cluster index, or -1 for none (also for an index the clusters do not have).
    void pickCluster(int cluster);
    // Pins the snapshot as A; the settings from then on are B. The faces are coloured by the
    // comparison (FaceColoring::Comparison) and the orbit is compared too: A is pinned when that
    // comparison is measured (a Cancel meanwhile pins nothing).
    void pinAsA();
    // Drops A; faces coloured by the comparison go back to the cull decision.
    void clearPin();
    // A's snapshot becomes the shown one and the shown one A: no clusters are built; shown when the
    // comparison the other way round (and A's orbit, when measured with other views) is measured.
    void swapAB();
    // Statistics in the CLI's format for the current eye or the orbit, in the background; `finished`
    // says whether the file was written. While A is pinned, the document `conescope-cli compare`
    // writes for A and B (a, b, diff; CSV: its per-view table).
    void startStatisticsExport(const QString& path, StatisticsFormat format, bool orbit,
                               const std::function<void(bool)>& finished);
    void setFaceColoring(FaceColoring coloring);
    void setLayerVisible(Layer layer, bool visible);
    // The legend fitted to a view this many pixels high (ClusterScene::fitLegend), kept for new scenes.
    void fitLegend(int viewHeight, double pixelRatio = 1.0);

    // Blocking forms and helpers for the window's test interface.
    bool exportStatistics(const QString& path, StatisticsFormat format, bool orbit);
    bool exportPartition(const QString& path);
    void waitUntilIdle() { runner_.waitUntilIdle(); }
    bool busy() const { return runner_.busy(); }
    void cancelAll() { runner_.cancelAll(); }

    // --- The snapshot ------------------------------------------------------------------------------
    // The snapshot's settings: what everything shown was made with.
    const Settings& settings() const { return shown_.settings; }
    // The settings asked for last: the snapshot's, or ahead of them while a build runs.
    const Settings& askedSettings() const { return asked_; }
    const Snapshot& snapshot() const { return shown_; }
    const PreparedMesh* preparedMesh() const { return shown_.prepared.get(); }
    const ClusterSet* clusters() const { return shown_.clusters.get(); }
    const ClusterScene* scene() const { return scene_.get(); }
    // The current eye's measurement; null before a mesh is shown or for an eye that has none
    // (eyeError() then says why).
    const EyeMeasurement* measurement() const { return measurement_ ? &*measurement_ : nullptr; }
    QString eyeError() const { return eyeError_; }
    double eyeSeconds() const { return eyeSeconds_; }
    const std::vector<ViewStatistics>& orbitRows() const;
    // The displayed test over the orbit with every cluster's counts and fractions; null before a mesh.
    const CullTestStatistics* orbitStatistics() const { return shown_.orbitStatistics(); }
    // The K-cone record over the orbit and from the cull eye; null / empty with one cone per cluster
    // or before the orbit is measured with these settings.
    const OrbitMeasurement* orbitMultiCones() const;
    std::optional<SubGroupsFromEye> subGroupsFromEye() const;

    // --- The cull eye -----------------------------------------------------------------------------
    glm::dvec3 eyePosition() const { return eyePosition_; }
    long orbitStep() const { return orbitStep_; }  // -1 when the eye is not on an orbit view
    // The eye the next loaded mesh starts with instead of startingEyePosition.
    void setInitialEye(const glm::dvec3& position);
    // For a stream of moves (the handle dragged, the followed camera): measured once, when the
    // event loop is free. The eye leaves the orbit.
    void moveEyeSoon(const glm::dvec3& position);
    // The observer's camera moved while the eye follows it: only a new position moves the eye.
    void followCamera(const glm::dvec3& position);
    void setAnimating(bool animate);

    // --- How the scene is drawn (kept for every new scene) ----------------------------------------
    bool layerVisible(Layer layer) const { return layers_.at(layer); }
    FaceColoring faceColoring() const { return coloring_; }
    int pickedCluster() const { return picked_; }
    // Picks the cluster and moves the eye to the first orbit view that loses its back faces (a miss
    // of the test first, else the partition's loss): the view that shows why it costs.
    void showClusterWhereItIsLost(int cluster);

    // --- The lesson (SessionEye.cpp) --------------------------------------------------------------------
    // Shows lesson step `step` (1 to kLessonStepCount) on the picked cluster; 0 ends the lesson. False,
    // and nothing changes, for a step outside 0..kLessonStepCount.
    bool setLessonStep(int step);
    int lessonStep() const { return lessonStep_; }
    // The lesson on the picked cluster from the measured eye with the shown test (core makeLesson), kept
    // whenever a cluster is picked: null without a pick or a measured eye. The lesson dock, the
    // cross-section and the explanation export all show this one value.
    const Lesson* lesson() const { return lesson_ ? &*lesson_ : nullptr; }
    // Writes the lesson as JSON (io/LessonIO.h); false (and errorOccurred) without one or on failure.
    bool exportExplanation(const QString& path);

    // --- A/B comparison (SessionComparison.cpp) ----------------------------------------------------
    bool hasPin() const { return pin_.has_value(); }
    // A's snapshot; its shared options (views, distance, projection) are the shown snapshot's.
    const Snapshot* pinned() const { return pin_ ? &*pin_ : nullptr; }
    const Settings* pinnedSettings() const { return pin_ ? &pin_->settings : nullptr; }
    const ClusterSet* pinnedClusters() const { return pin_ ? pin_->clusters.get() : nullptr; }
    // A against B from the current eye; null without a pin or a measured eye.
    const Comparison* eyeComparison() const { return eyeComparison_ ? &*eyeComparison_ : nullptr; }
    // A against B over the orbit; null until measured.
    const Comparison* orbitComparison() const { return orbitComparison_ ? &orbitComparison_->comparison : nullptr; }
    // A's cluster holding the first face of the current partition's `cluster`; -1 without a pin.
    int pinnedClusterOf(int cluster) const;

    // --- The cluster LOD hierarchy (SessionLod.cpp) ------------------------------------------------
    // Builds the hierarchy of the shown snapshot in the background (progress, Cancel); lodChanged()
    // when it is ready. New clusters drop it.
    void buildLodHierarchy();
    // Shows level `level`, the cut from the cull eye (kLodCut) or the snapshot's partition (kLodNone)
    // in the observer view; false, and nothing changes, without a hierarchy or for a missing level.
    bool showLodLevel(int level);
    // The cut's error bound: measured and cut again at once.
    void setLodThreshold(const LodThreshold& threshold);
    // A cluster of the LOD scene shown (-1: none).
    void pickLodCluster(int cluster);
    // The LOD statistics shown (lodStatistics) as `conescope-cli lod --eye` writes them for the cull eye
    // and threshold; false (and errorOccurred) without a hierarchy or when it cannot be written.
    bool exportLodStatistics(const QString& path, StatisticsFormat format);
    const ClusterHierarchy* lodHierarchy() const;
    // Each level and the cut from the cull eye with the shown settings and threshold; null without a
    // hierarchy or a measured eye.
    const LodStatistics* lodStatistics() const;
    const LodThreshold& lodThreshold() const;
    int lodLevelShown() const;  // kLodNone, kLodCut or a level
    // The cut from the cull eye: per level, per cluster, 1 when drawn (empty without a hierarchy).
    const std::vector<std::vector<uint8_t>>& lodCut() const;
    // The scene of the level or cut shown; null while the partition is shown.
    const ClusterScene* lodScene() const;
    // The level (or the cut as one level) the LOD scene shows, and its measurement from the cull eye;
    // null while the partition is shown.
    const LodLevel* lodLevelOnShow() const;
    const EyeMeasurement* lodMeasurement() const;
    int lodPickedCluster() const;  // a cluster of lodLevelOnShow(), -1 for none
    // The picked LOD cluster's family (its level, group, parents, children); none without a pick.
    std::optional<LodFamily> lodPick() const;
    // What the LOD scene's cluster `cluster` is in the hierarchy (the cut's clusters come from levels).
    std::optional<LodClusterId> lodClusterOf(int cluster) const;

    // --- The granularity report (SessionGranularity.cpp) -------------------------------------------
    // Measures the granularity report of the shown clusters with the shown settings over the orbit's
    // views (measureGranularity) in the background, with progress and Cancel; granularityChanged()
    // when it is shown.
    void measureGranularity();
    // The report of the shown clusters and settings; null before it is measured and as soon as the
    // clusters or settings shown are others than it was measured with.
    const GranularityReport* granularity() const;
    // What the report is measured with: the shown settings for the orbit, every test with the shown
    // one first (granularitySettings). `conescope-cli granularity` with them writes the same rows.
    Settings granularityRunSettings() const;
    // The report shown as `conescope-cli granularity` writes it; false (and errorOccurred) without one
    // or when it cannot be written.
    bool exportGranularity(const QString& path, StatisticsFormat format);

signals:
    // The granularity report was measured, or dropped with the clusters or settings it was made for.
    void granularityChanged();
    // A pin was set, swapped or cleared, or its comparison with the current settings was measured.
    void comparisonChanged();
    // A new scene (new mesh or new clusters), its eye already measured. `previous` (null for the
    // first) is still alive: views take its actors out.
    void sceneReplaced(const conescope::ClusterScene* previous, bool newMesh);
    // A new mesh is shown, with what the user should know about it (may be empty).
    void meshShown(const QString& path, const QString& loadMessage);
    void eyeMoved();
    // The eye was measured again (measurement() is null and eyeError() set when it has no measurement).
    void eyeMeasured();
    // The orbit's rows changed, or moveEye put the eye on an orbit view (or off it).
    void orbitChanged();
    void pickChanged(int cluster);
    // The lesson's step changed (0: the lesson ended).
    void lessonStepChanged(int step);
    // The lesson's numbers and words changed: another eye, cluster, test or step.
    void lessonChanged();
    // The settings the widgets show: asked for, adopted (the builder a mesh is shown with) or put
    // back (a cancelled or failed build).
    void settingsChanged(const conescope::Settings& settings);
    void faceColoringChanged(conescope::FaceColoring coloring);
    void errorOccurred(const QString& title, const QString& message);
    void notice(const QString& message, int milliseconds);
    // A slow stage: its start, progress and the end of all of them.
    void taskStarted(const QString& title);
    void progressChanged(double fraction, const QString& stage);
    void idle();
    // The hierarchy, what is shown of it, its threshold, its measurement or its pick changed.
    // `previousScene` (the LOD scene shown before, or null) is still alive: views take its actors out.
    void lodChanged(const conescope::ClusterScene* previousScene);

private:
    // Runs `write`; says "Wrote PATH", or "Cannot export WHAT" with the writer's message. What every
    // export does once it has something to write.
    bool writeExport(const QString& what, const QString& path, const std::function<void()>& write);
    // The K-cone record from the cull eye into the scene (the sub-group colouring), or none.
    void showSubGroups();
    // A against B over B's orbit, with A and B as they were compared (their clusters and settings).
    struct OrbitComparison {
        Snapshot a, b;
        Comparison comparison;
    };
    // Completes `b` in the background: its orbit (kept when measured with its settings) and, with
    // `pin` on its prepared mesh, A against it over the same views.
    static std::optional<OrbitComparison> measureSnapshot(Snapshot& b, const std::optional<Snapshot>& pin, const ProgressCallback& progress);
    // What a build delivers to the UI thread: the snapshot with its orbit, its scene and, with A
    // pinned, A against it.
    struct SceneResult {
        Snapshot snapshot;
        std::unique_ptr<ClusterScene> scene;
        std::optional<OrbitComparison> comparison;
        std::string builderNote;  // why the clusters came from another builder than the settings said
    };

    // Whether the asked settings need stages other than the snapshot's.
    bool needsBuild() const;
    // The snapshot to the asked settings: a build when they need one, another orbit when the test or
    // views change (shown when measured), else at once.
    void reconcile();
    void requestClusters();
    void buildStarted();
    void buildFailed(const QString& error);
    // The widgets back to the snapshot's settings.
    void revertToSnapshot();
    void setShownSettings(const Settings& settings);
    // The asked settings on the shown clusters, with their orbit and A's comparison, shown together.
    void requestOrbit();
    // A's comparison when it was made for A as pinned and B as shown, else none.
    void adoptComparison(const std::optional<OrbitComparison>& comparison);
    // A pinned without its comparison asks for one, unless new clusters are on their way (they bring it).
    void completeComparison();
    void showSceneResult(SceneResult& result, bool newMesh);
    // A task's title or stage shown: kept in stagesSeen() while a Cancel stage is armed.
    void stageShown(const QString& stage);
    void updateEye();
    void measureCurrentEye();
    // The picked cluster's lesson from the measured eye, and the lesson layer's drawing of it.
    void updateLesson();
    // A against B from the measured eye, its per-face diff in the scene (or none without a pin).
    void measurePinnedEye();
    // Drops A without touching the colouring: a new mesh, or A made for another prepared mesh.
    void dropPin();
    void dropStalePin();
    // The hierarchy measured from the cull eye, the cut and the LOD scene again (dropped when the
    // snapshot's clusters are not the ones it was built from).
    void updateLod();
    // The scene of what the LOD view shows, from the measured cut.
    void makeLodScene(std::unique_ptr<ClusterScene>& previous);

    TaskRunner runner_;
    Snapshot shown_;
    Settings asked_;
    bool cancelNextBuild_ = false;
    QString cancelStage_;
    QStringList stagesSeen_;
    std::unique_ptr<ClusterScene> scene_;
    std::optional<EyeMeasurement> measurement_;
    QString eyeError_;
    double eyeSeconds_ = 0.0;
    glm::dvec3 eyePosition_{0.0, 0.0, 3.0};
    bool eyeGiven_ = false;  // the next mesh keeps eyePosition_ instead of the starting position
    long orbitStep_ = -1;
    bool eyeUpdateScheduled_ = false;
    QTimer animationTimer_;
    std::map<Layer, bool> layers_;
    int legendViewHeight_ = 0;  // 0: not known yet
    double legendPixelRatio_ = 1.0;
    FaceColoring coloring_ = FaceColoring::CullDecision;
    int picked_ = -1;
    int lessonStep_ = 0;
    std::optional<Lesson> lesson_;
    std::optional<Snapshot> pin_;
    std::optional<Comparison> eyeComparison_;
    std::optional<OrbitComparison> orbitComparison_;
    std::unique_ptr<SessionLod> lod_;
    // The granularity report and what it was measured from.
    std::shared_ptr<const GranularityReport> granularity_;
    std::shared_ptr<const ClusterSet> granularityClusters_;
    Settings granularitySettings_;
    // Drops the report when the shown clusters or settings are not its own (granularityChanged()).
    void dropStaleGranularity();
};

}  // namespace conescope
