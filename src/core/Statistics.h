// Cull statistics over a set of views: per view, per cluster and totals, for every (cone, test).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "CullMap.h"
#include "Culling.h"
#include "MeshChecks.h"
#include "Progress.h"
#include "Settings.h"

namespace conescope {

struct ViewStatistics {
    size_t view = 0;
    Eye eye;
    size_t clustersCulled = 0;
    size_t trianglesCulled = 0;       // triangles in culled clusters
    size_t backFacingTriangles = 0;   // by the per-face oracle
    size_t frontFacingTriangles = 0;
    size_t backFacingClusters = 0;    // clusters whose faces are all back-facing
    size_t missedClusters = 0;        // back-facing clusters the test drew
    size_t falseCulls = 0;            // culled clusters holding a front-facing face: must be 0
    // The back-facing triangles not culled, by why: trianglesCulled + testLossTriangles +
    // partitionLossTriangles = backFacingTriangles. Degenerate faces are in none of them.
    size_t testLossTriangles = 0;       // in back-facing clusters the test drew (a better test could cull them)
    size_t partitionLossTriangles = 0;  // in clusters holding a visible face (no conservative test could)
    // Of testLossTriangles, those the quantised record's float original culls (RecordTests.h).
    size_t quantisationLossTriangles = 0;
    double efficiency = 0.0;          // trianglesCulled / backFacingTriangles (1 when none face away)
    double nanosecondsPerCluster = 0.0;
};

struct ClusterStatistics {
    uint32_t cluster = 0;
    size_t faces = 0;
    size_t triangles = 0;
    size_t vertices = 0;
    double halfAngleDegrees = 90.0;
    bool cullable = false;
    size_t timesCulled = 0;
    size_t timesBackFacing = 0;       // views from which every face was back-facing
    size_t timesMissed = 0;           // of those, views from which the test drew it
    size_t falseCulls = 0;
    size_t testLossTriangles = 0;     // summed over the views, as in ViewStatistics
    size_t partitionLossTriangles = 0;
    size_t quantisationLossTriangles = 0;
    double sphereRadius = 0.0;        // the bounding sphere's
    double cullFraction = 0.0;        // share of directions at infinity the test culls it from (CullMap.h)
    double oracleFraction = 0.0;      // share from which every face faces away
};

struct CullTestStatistics {
    ConeMethod cone = kDefaultCone;
    CullTest test = kDefaultTest;
    size_t clustersCulled = 0;
    size_t trianglesCulled = 0;
    size_t backFacingTriangles = 0;
    size_t missedClusters = 0;
    size_t falseCulls = 0;
    size_t testLossTriangles = 0;
    size_t partitionLossTriangles = 0;
    size_t quantisationLossTriangles = 0;
    double efficiency = 0.0;
    double nanosecondsPerCluster = 0.0;
    size_t bytesPerCluster = 0;       // the record the test reads (recordBytes, RecordTests.h)
    bool engineRecord = false;        // an engine's record as shipped: not conservative, false culls reported
    size_t uncullableClusters = 0;
    double expectedEfficiency = 0.0;  // sum T_c (1 - sin alpha_c) / T: random-direction estimate
    // The partition's summary, view-independent apart from the first.
    double meanViewEfficiency = 0.0;  // the views' efficiencies averaged (each view weighs the same)
    double meanClusterTriangles = 0.0, meanClusterVertices = 0.0;  // fill of the limits
    double meanSphereRadius = 0.0, maxSphereRadius = 0.0;  // sprawl: what frustum and occlusion culling see
    double cullFraction = 0.0;        // triangle-weighted mean of the clusters' cullFraction (0 before addCullMap)
    double oracleFraction = 0.0;      // triangle-weighted mean of the clusters' oracleFraction
    std::vector<ViewStatistics> views;
    std::vector<ClusterStatistics> clusters;
};

// The float K-cone record (each sub-group's cone, its cluster's sphere) over views: triangles in
// culled sub-groups against back-facing triangles. cones = 0: not measured.
struct MultiConeCulling {
    uint32_t cones = 0;
    size_t trianglesCulled = 0, backFacingTriangles = 0, falseCulls = 0;
    double efficiency = 0.0;       // trianglesCulled / backFacingTriangles
    size_t bytesPerCluster = 0;    // multiConeRecordBytes of the float record
};

struct RunStatistics {
    Settings settings;
    std::string meshName;
    size_t vertices = 0;
    size_t faces = 0;
    size_t triangles = 0;
    size_t degenerateFaces = 0;
    MeshReport meshReport;            // winding and manifold problems found before culling
    size_t windingFixedFaces = 0;     // faces flipped because settings.fixWinding was set
    size_t clusters = 0;
    size_t fewestClusters = 0;        // fewestClustersWithin the settings' limits: says why a budget was missed
    BestEffortChoice bestEffort;      // --effort best: which of its two searches made the partition (bestEffortNote)
    size_t viewCount = 0;
    std::vector<CullTestStatistics> results;
    MultiConeCulling multiCones;      // settings.conesPerCluster > 1: the displayed cone's partition with K cones (cones = 0 otherwise)
};

// Triangles culled / back-facing triangles; 1 when nothing faces away (nothing to cull, nothing lost).
double cullEfficiency(size_t trianglesCulled, size_t backFacingTriangles);

// The share of clusters whose normals fit in no cone narrower than a hemisphere: no test culls them
// from any eye. 0 without clusters.
double uncullableShare(size_t uncullableClusters, size_t clusters);

// When most clusters (more than half) are such, a sentence for the user saying so, why and what
// could help; empty otherwise. What the text summary, batch's report and the window say.
std::string uncullableNote(size_t uncullableClusters, size_t clusters);

// A sentence for the user when --effort best kept the balanced search's partition (BestEffortChoice),
// saying why: best's own came farther from the budget, or culled less as the run measures it (its
// shown cone and test from its orbit) or in expectation. Empty when best kept its own or did not run.
std::string bestEffortNote(const BestEffortChoice& choice);

// The efficiency a run with these settings reports for this partition of the mesh from its orbit:
// its shown cone and test (displayedCone, displayedTest) from its orbit views around the world box,
// as runStatistics measures it. What the best effort tells its two searches apart by
// (buildPartition). A single eye (settings.eye) does not choose: the window moves its eye over one
// partition, and `stats --eye` must give that partition's numbers.
double shownEfficiency(const Mesh& mesh, const FaceGeometry& faces, const Partition& partition, const Settings& settings);

// Statistics for one (cone, test) over the given views from prepared bounds. `progress` hears of
// every 16th view and may cancel there (OperationCancelled).
CullTestStatistics measureCulling(const CullingInput& input, const std::vector<Eye>& views, CullTest test,
                              const ProgressCallback& progress = {});

// Fills the clusters' cullFraction / oracleFraction and their triangle-weighted means from a cull
// map of the same bounds (computeCullMap, CullMap.h): kept apart from measureCulling, which the
// window calls at every eye move.
void addCullMap(CullTestStatistics& statistics, const CullMap& map);

}  // namespace conescope
