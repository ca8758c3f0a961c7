// What the window shows, without any widget: the pipeline's stages for the current mesh (prepared
// mesh, clusters, their scene, the cull eye's measurement, the orbit's rows), the settings, the cull
// eye and the picked cluster. The slow stages (open, clusters, orbit, statistics export) run through
// a TaskRunner; every number comes from core/Pipeline.h. Signals say what is new, and the views
// (ObserverView, the docks) show it.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <QObject>
#include <QString>
#include <QTimer>

#include "Exports.h"
#include "TaskRunner.h"
#include "core/Comparison.h"
#include "core/Pipeline.h"
#include "scene/ClusterScene.h"

namespace conescope {

class Session : public QObject {
    Q_OBJECT
public:
    explicit Session(QObject* parent = nullptr);
    ~Session() override;

    // --- Background stages ------------------------------------------------------------------------
    // Reads, prepares and clusters the file; meshShown() when it is shown, errorOccurred() when it
    // cannot be read (the mesh shown before stays).
    void openMesh(const QString& path);
    void waitUntilIdle() { runner_.waitUntilIdle(); }
    void cancelAll() { runner_.cancelAll(); }

    const Settings& settings() const { return settings_; }
    // Recomputes what the change makes stale: the clusters (partition or bounds), the eye, the orbit.
    void applySettings(const Settings& settings);

    // Statistics in the CLI's format for the current eye or the orbit, in the background;
    // `finished` says whether the file was written. exportStatistics waits for it.
    void startStatisticsExport(const QString& path, StatisticsFormat format, bool orbit,
                               const std::function<void(bool)>& finished);
    bool exportStatistics(const QString& path, StatisticsFormat format, bool orbit);
    bool exportPartition(const QString& path);

    // --- The cull eye -----------------------------------------------------------------------------
    glm::dvec3 eyePosition() const { return eyePosition_; }
    long orbitStep() const { return orbitStep_; }  // -1 when the eye is not on an orbit view
    // The eye the next loaded mesh starts with instead of startingEyePosition.
    void setInitialEye(const glm::dvec3& position);
    void moveEye(const glm::dvec3& position, long orbitStep = -1);
    // For a stream of moves (the handle dragged, the followed camera): measured once, when the
    // event loop is free. The eye leaves the orbit.
    void moveEyeSoon(const glm::dvec3& position);
    // The observer's camera moved while the eye follows it: only a new position moves the eye.
    void followCamera(const glm::dvec3& position);
    void moveEyeToStart();
    void stepOrbit(int step);
    void setAnimating(bool animate);

    // --- The stages -------------------------------------------------------------------------------
    const PreparedMesh* preparedMesh() const { return prepared_.get(); }
    const ClusterSet* clusters() const { return clusters_.get(); }
    const ClusterScene* scene() const { return scene_.get(); }
    // The current eye's measurement; null before a mesh is shown or for an eye that has none
    // (eyeError() then says why).
    const EyeMeasurement* measurement() const { return measurement_ ? &*measurement_ : nullptr; }
    QString eyeError() const { return eyeError_; }
    double eyeSeconds() const { return eyeSeconds_; }
    const std::vector<ViewStatistics>& orbitRows() const;
    // The displayed test over the orbit with every cluster's counts and fractions; null until measured.
    const CullTestStatistics* orbitStatistics() const { return orbit_ ? &*orbit_ : nullptr; }

    // --- How the scene is drawn (kept for every new scene) ----------------------------------------
    void setLayerVisible(Layer layer, bool visible);
    bool layerVisible(Layer layer) const { return layers_.at(layer); }
    void setFaceColoring(FaceColoring coloring);
    FaceColoring faceColoring() const { return coloring_; }

    // A cluster index, or -1 for none (also for an index the clusters do not have).
    void pickCluster(int cluster);
    int pickedCluster() const { return picked_; }
    // Picks the cluster and moves the eye to the first orbit view that loses its back faces (a miss
    // of the test first, else the partition's loss): the view that shows why it costs.
    void showClusterWhereItIsLost(int cluster);

    // --- A/B comparison (SessionComparison.cpp) ----------------------------------------------------
    // Pins the current settings and clusters as A; the settings from then on are B. The scene then
    // has the per-face diff of the eye (FaceColoring::Comparison) and the orbit is compared too.
    void pinAsA();
    void clearPin();
    // A's settings and clusters become the current ones and the current ones A: nothing is rebuilt.
    void swapAB();
    bool hasPin() const { return pin_.has_value(); }
    const Settings* pinnedSettings() const { return pin_ ? &pin_->settings : nullptr; }
    const ClusterSet* pinnedClusters() const { return pin_ ? pin_->clusters.get() : nullptr; }
    // A against B from the current eye; null without a pin or a measured eye.
    const Comparison* eyeComparison() const { return eyeComparison_ ? &*eyeComparison_ : nullptr; }
    // A against B over the orbit; null until measured.
    const Comparison* orbitComparison() const { return orbitComparison_ ? &*orbitComparison_ : nullptr; }
    // A's cluster holding the first face of the current partition's `cluster`; -1 without a pin.
    int pinnedClusterOf(int cluster) const;

signals:
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
    // The session chose other settings than it was given (the builder a mesh can be shown with):
    // the settings panel shows them.
    void settingsAdjusted(const conescope::Settings& settings);
    void errorOccurred(const QString& title, const QString& message);
    void notice(const QString& message, int milliseconds);
    // A slow stage: its start, progress and the end of all of them.
    void taskStarted(const QString& title);
    void progressChanged(double fraction, const QString& stage);
    void idle();

private:
    // What the clusters stage delivers to the UI thread.
    struct SceneResult {
        std::shared_ptr<const PreparedMesh> prepared;
        std::shared_ptr<const ClusterSet> clusters;
        std::unique_ptr<ClusterScene> scene;
        std::string builderNote;  // why the clusters came from another builder than the settings said
    };

    void requestClusters(bool reprepare);
    void requestOrbit();
    void showSceneResult(SceneResult& result, bool newMesh);
    void clearOrbit();
    // Takes the builder the clusters were made with as the current one (builderForMesh's choice).
    void adoptBuilderOf(const ClusterSet& clusters);
    void updateEye();
    void measureCurrentEye();
    // A against B from the measured eye, its per-face diff in the scene (or none without a pin).
    void measurePinnedEye();
    void requestOrbitComparison();
    // Drops a pin made for another prepared mesh (a new file, another winding repair).
    void dropStalePin();

    TaskRunner runner_;
    Settings settings_;
    std::shared_ptr<const PreparedMesh> prepared_;
    std::shared_ptr<const ClusterSet> clusters_;
    std::unique_ptr<ClusterScene> scene_;
    std::optional<EyeMeasurement> measurement_;
    QString eyeError_;
    double eyeSeconds_ = 0.0;
    std::optional<CullTestStatistics> orbit_;
    glm::dvec3 eyePosition_{0.0, 0.0, 3.0};
    bool eyeGiven_ = false;  // the next mesh keeps eyePosition_ instead of the starting position
    long orbitStep_ = -1;
    bool eyeUpdateScheduled_ = false;
    QTimer animationTimer_;
    std::map<Layer, bool> layers_;
    FaceColoring coloring_ = FaceColoring::CullDecision;
    int picked_ = -1;
    struct Pin {
        Settings settings;
        std::shared_ptr<const ClusterSet> clusters;
        std::shared_ptr<const PreparedMesh> prepared;  // the mesh the clusters were made for
    };
    std::optional<Pin> pin_;
    std::optional<Comparison> eyeComparison_;
    std::optional<Comparison> orbitComparison_;
};

}  // namespace conescope
