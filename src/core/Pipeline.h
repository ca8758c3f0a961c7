// The pipeline as stages, each a value built by one function from the one before and the settings:
//   Mesh -> PreparedMesh (face geometry, checks, winding repair, world positions)
//        -> ClusterSet (partition + bounds for the displayed cone)
//        -> measurements (per-view decisions and statistics: one eye, the orbit, a whole run).
// runStatistics (the CLI), the window, the headless screenshot and the exports all go through these,
// so what each shows or writes for the same Settings agrees number for number, and nothing is
// prepared twice. A change of settings makes stale the stages core/SettingsSchema.h says.
#pragma once

#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "BuildPartition.h"
#include "Culling.h"
#include "MeshChecks.h"
#include "Settings.h"
#include "Statistics.h"

namespace conescope {

// A mesh ready for clustering: the mesh as culled (winding repaired when asked), its world
// positions, face geometry and world box, plus the report of its problems.
struct PreparedMesh {
    std::string path;
    std::string name;                 // file name, as statistics record it
    std::shared_ptr<const Mesh> original;  // as read: what runStatistics (exports) starts from
    std::shared_ptr<const Mesh> culled;    // the original, or its repaired copy
    const Mesh& mesh() const { return *culled; }
    std::vector<glm::vec3> world;
    FaceGeometry faces;
    Aabb box;
    MeshReport report;
    bool fixWindingAsked = false;     // the settings.fixWinding it was prepared with
    size_t windingFixedFaces = 0;
    std::vector<std::string> readerNotes;  // what the file's reader noticed (io's MeshFile::notes)
    size_t triangles = 0;
    double prepareSeconds = 0.0;
};

// The clusters of a prepared mesh for the builder, cone and sphere of `settings`.
struct ClusterSet {
    // The settings the partition and bounds were built with: only what makes them (builder, limits,
    // cone, sphere) means anything here. The test, the views and the projection can change without new
    // clusters, so the settings a set is shown with are the caller's, never these.
    Settings builtWith;
    Partition partition;
    ClusterBounds bounds;
    // The bounds' view-independent shares (CullMap.h), made once with them: the orbit, the
    // statistics and the exports all read these.
    CullMap cullMap;
    double partitionSeconds = 0.0;
    double boundsSeconds = 0.0;
    BestEffortChoice bestEffort;  // what --effort best chose between its two searches (ran = false otherwise)
};

// True when going from `before` to `after` needs a new partition (builder or its parameters).
bool partitionChanged(const Settings& before, const Settings& after);
// True when it needs new bounds (a new partition, cone method or sphere method).
bool boundsChanged(const Settings& before, const Settings& after);

// Reads nothing: takes a mesh already read and computes what every later stage needs, exactly as
// runStatistics does (face geometry, mesh checks, winding repair when settings.fixWinding).
// `progress` may cancel between stages (it then throws OperationCancelled).
PreparedMesh prepareMesh(std::shared_ptr<const Mesh> mesh, const std::string& path, bool fixWinding,
                         const ProgressCallback& progress = {});

// prepareMesh of a mesh the caller keeps alive while the stages are used (borrowed, not copied),
// after validateMesh, its statistics named `meshName`: what the whole runs from a mesh start with.
PreparedMesh prepareBorrowed(const Mesh& mesh, const std::string& meshName, bool fixWinding, const ProgressCallback& progress = {});

// Partition (buildPartition) then bounds for the displayed cone (computeClusterBounds). Reuses
// `previous` partition when only the cone or sphere changed. `meshlets`: the builder's start
// when it was started beforehand (meshoptStartInBackground).
ClusterSet buildClusters(const PreparedMesh& prepared, const Settings& settings, const ClusterSet* previous = nullptr,
                         const ProgressCallback& progress = {}, MeshletStream* meshlets = nullptr);

// meshoptimizer's meshlets that buildClusters starts from with these settings, started on another
// thread from the mesh as read, so that they are made while prepareMesh works on the same mesh
// (they need neither its face geometry nor its checks). Null when the settings start elsewhere
// (startsFromMeshoptMeshlets) or repair the winding (the faces would change).
std::shared_ptr<MeshletStream> meshoptStartInBackground(std::shared_ptr<const Mesh> mesh, const Settings& settings);

CullingInput cullingInput(const PreparedMesh& prepared, const ClusterSet& clusters);

// The eye a run with settings.eye = position makes (viewsFor): perspective at the point, or
// orthographic looking from it to the mesh centre. Throws std::invalid_argument for an
// orthographic eye at the centre.
Eye eyeAt(const Settings& settings, const glm::dvec3& position, const Aabb& worldBox);

// The orbit view whose direction from the mesh centre is nearest the eye's at `position` (every
// orbit eye lies on that ray from the centre); 0 for an eye at the centre. Where stepping through
// the orbit goes on from when the eye was moved off it.
size_t nearestOrbitView(const Settings& settings, const Aabb& worldBox, const glm::dvec3& position);

// What the window shows for one eye: the cull decision of every cluster for `test`, and the
// statistics of that single view (measureCulling over {eye}).
struct EyeMeasurement {
    Eye eye;
    std::vector<uint8_t> culled;      // 1 = culled, per cluster
    CullTestStatistics statistics;        // statistics.views[0] is this eye
    const ViewStatistics& view() const { return statistics.views.front(); }
};
EyeMeasurement measureEye(const PreparedMesh& prepared, const ClusterSet& clusters, const Eye& eye, CullTest test);

// Clusters whose every face faces away from the measured eye (1 = yes), as the oracle inside
// measureCulling counted them: what the scene colours a missed cull.
std::vector<uint8_t> allBackFacingClusters(const EyeMeasurement& measurement);

// Where the cull eye starts on a new mesh: above and in front, settings.distance half-diagonals from
// the centre but at most 2, so the first picture shows culled and drawn clusters and the eye near.
glm::dvec3 startingEyePosition(const Aabb& worldBox, const Settings& settings);

// The displayed test over the standard orbit (measureCulling over orbitOf) with the cull map of the
// clusters: the efficiency plot's rows (views) and the worst-cluster table (clusters). Cancellable
// between views.
CullTestStatistics measureOrbit(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                            const ProgressCallback& progress = {});

// How the displayed test decided on one cluster from one eye, and how the cluster's faces faced it.
struct ClusterInView {
    bool culled = false;  // the product's decision (cullClusters)
    size_t frontFaces = 0, backFaces = 0;
};
// The displayed test's decision on `cluster` and its faces' facing from every orbit view (one float
// batch for all the views): the same verdicts the orbit statistics counted.
std::vector<ClusterInView> clusterOverOrbit(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                                            uint32_t cluster);

// The first orbit view from which the displayed test culls `cluster` holding a visible face (a
// false cull, only an engine's record makes one) or draws it although every face faces away (a
// miss: the test's loss), whichever comes first; else the first from which it is drawn holding back
// faces and a visible one (the partition's loss); -1 when it is never lost. Where to put the eye to
// see why it costs.
long viewMissingCluster(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings, uint32_t cluster);

// The settings for a statistics export: the current settings with the eye set (current eye) or
// cleared (orbit).
Settings exportSettings(const Settings& settings, const std::optional<glm::dvec3>& eye);

// The builder a freshly opened mesh is shown with: a mesh that carries a cluster_id array shows its
// own partition (the file builder), and the file builder falls back to the default builder for a
// mesh without groups or ids when no cluster file is given, or when its cluster file was not read
// (settings.clusterIds for an id file, the mesh's fileClusters for a meshlet file). `why` gets a
// sentence for the user when the builder changed.
Settings builderForMesh(const Settings& settings, const Mesh& mesh, std::string& why);

// A sentence for the user when a cluster budget was asked for (--clusters) and the builder that takes
// one made another count; empty otherwise. Numbers compared at the asked count would not be at equal
// counts. It says whether the limits make the budget impossible (`fewestPossible`,
// fewestClustersWithin; 0 when unknown) or the builder reached no nearer.
std::string budgetMissed(const Settings& settings, size_t clustersMade, size_t fewestPossible);

// The statistics of a whole run from the stages: every cone and test of `settings` over its views
// (the single eye or the orbit), the displayed cone's bounds taken from `clusters`, the others
// computed for the same partition. When `settings` make a stage stale (another winding repair,
// another partition), that stage is built again from the one before it.
RunStatistics measureRun(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                         const ProgressCallback& progress = {});

// The whole run from a mesh: prepareMesh, buildClusters, measureRun. What `conescope-cli stats` writes.
RunStatistics runStatistics(const Mesh& mesh, const Settings& settings, const std::string& meshName = {},
                            const ProgressCallback& progress = {});

// What happened to a face from one eye, as the statistics count it.
enum class FaceLoss : uint8_t { Visible = 0, Culled = 1, Test = 2, Partition = 3 };

// Per face, what happened to it from the measured eye, given the oracle's facing from that eye
// (classifyFaces): a back face culled, drawn by the test's caution, or drawn because its cluster holds
// a visible face; anything else is Visible (front-facing or degenerate).
std::vector<FaceLoss> faceLosses(const ClusterSet& clusters, const EyeMeasurement& measurement,
                                 const std::vector<Facing>& facing);

// Per-face arrays for one eye, for ParaView and the like: `culled` (its cluster was culled),
// `back_facing` (the oracle's verdict) and `loss` (a FaceLoss: 0 visible or degenerate, 1 culled,
// 2 a back face the test drew, 3 a back face drawn because its cluster holds a visible face).
std::map<std::string, std::vector<double>> eyeFaceArrays(const PreparedMesh& prepared, const ClusterSet& clusters,
                                                         const EyeMeasurement& measurement);

// Per-face arrays describing the partition for writePolyData: cluster_id plus each cluster's cone
// and bounds spread to its faces (cone_half_angle_deg, cone_axis_x/y/z, cone_cullable,
// sphere_center_x/y/z, sphere_radius, aabb_min_x/y/z, aabb_max_x/y/z, and from the cull map
// cull_fraction for `test` and oracle_fraction).
std::map<std::string, std::vector<double>> partitionFaceArrays(const PreparedMesh& prepared, const ClusterSet& clusters,
                                                               CullTest test);

}  // namespace conescope
