// The cut through a cluster LOD hierarchy from an eye, as engines choose it, and cone culling of
// each level and of the cut: how much of what an engine draws the cone test can still skip.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ClusterHierarchy.h"
#include "core/MultiConeCulling.h"

namespace conescope {

// The largest error the cut allows: `value` pixels on a screen `screenHeight` pixels high seen
// through a vertical field of view of `fovDegrees`, or `value` world units when `worldUnits`.
struct LodThreshold {
    double value = 1.0;
    bool worldUnits = false;
    double screenHeight = 1080.0;
    double fovDegrees = 60.0;
};

// An error bound as the eye sees it: in pixels, error / (distance from the eye to the sphere) times
// the screen's pixels per unit of tangent; infinite from inside the sphere (unless the error is 0).
// In world units, the error itself.
double projectedError(double error, const Sphere& sphere, const glm::dvec3& eye, const LodThreshold& threshold);

// Per level, per cluster: 1 when the cut from `eye` draws it, that is when its own error seen from
// the eye is within the threshold and its group's is not (the rule engines use). Every region of the
// surface is drawn by exactly one level's clusters.
std::vector<std::vector<uint8_t>> cutFrom(const ClusterHierarchy& hierarchy, const glm::dvec3& eye, const LodThreshold& threshold);

// The clusters a cut draws as one mesh over the original's positions: their faces, with the face
// arrays "cluster_id" (numbered level after level) and "level".
Mesh meshOfCut(const ClusterHierarchy& hierarchy, const std::vector<std::vector<uint8_t>>& drawn);

// K cones per cluster (MultiCones.h: the float record, tested batched as the product does) over the
// same views as the one-cone numbers beside it; cones 0 when not measured.
using LodMultiConeCulling = MultiConeCulling;

// One level over the views: its size, how wide its cones are, and the displayed test's culling.
struct LodLevelStatistics {
    size_t level = 0;
    size_t clusters = 0, triangles = 0, groups = 0;
    double meanHalfAngleDegrees = 0.0;  // of the clusters with a cone, triangle-weighted
    double maxHalfAngleDegrees = 0.0;
    double minError = 0.0, maxError = 0.0;  // own errors, world units
    CullTestStatistics culling;         // measureCulling of the level alone
    LodMultiConeCulling multiCones;     // the level alone with K cones per cluster
};

// The cut from one eye: what it draws and what the test culls of it.
struct LodCutView {
    size_t view = 0;
    Eye eye;
    size_t clusters = 0, triangles = 0;
    size_t clustersCulled = 0, trianglesCulled = 0, backFacingTriangles = 0, falseCulls = 0;
    std::vector<size_t> clustersPerLevel;
    double efficiency = 0.0;
    LodMultiConeCulling multiCones;     // the cut's clusters with K cones each
};

struct LodCutStatistics {
    std::vector<LodCutView> views;
    size_t trianglesCulled = 0, backFacingTriangles = 0, falseCulls = 0;  // summed over the views
    double meanTriangles = 0.0, meanClusters = 0.0;
    double efficiency = 0.0;       // culled / back-facing over all the views
    std::vector<size_t> levelsUsed;  // levels drawn from at least one view
    LodMultiConeCulling multiCones;  // summed over the views
};

struct LodStatistics {
    std::vector<LodLevelStatistics> levels;
    LodCutStatistics cut;
    LodThreshold threshold;
    double buildSeconds = 0.0;
};

// Each level and the cut over the views of `settings` (its orbit or its one eye) with the displayed
// cone and test, and with `conesPerCluster` cones per cluster when it is above 0. Cancellable
// between views.
LodStatistics measureHierarchy(const ClusterHierarchy& hierarchy, const Settings& settings, const LodThreshold& threshold,
                               const ProgressCallback& progress = {}, uint32_t conesPerCluster = 0);

// The whole job from a mesh, as `conescope-cli lod` runs it without a hierarchy file: prepareMesh,
// buildClusterHierarchy, measureHierarchy. What batch --lod computes per mesh.
LodStatistics lodOfMesh(const Mesh& mesh, const std::string& meshName, const Settings& settings, const LodThreshold& threshold,
                        const LodBuildOptions& options = {}, const ProgressCallback& progress = {});

}  // namespace conescope
