// Cull statistics over a set of views: per view, per cluster and totals, for every (cone, test).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

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
    size_t falseCulls = 0;
};

struct TestStatistics {
    ConeMethod cone = ConeMethod::Minimal;
    CullTest test = CullTest::Vertices;
    size_t clustersCulled = 0;
    size_t trianglesCulled = 0;
    size_t backFacingTriangles = 0;
    size_t missedClusters = 0;
    size_t falseCulls = 0;
    double efficiency = 0.0;
    double nanosecondsPerCluster = 0.0;
    size_t uncullableClusters = 0;
    double expectedEfficiency = 0.0;  // sum T_c (1 - sin alpha_c) / T: random-direction estimate
    std::vector<ViewStatistics> views;
    std::vector<ClusterStatistics> clusters;
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
    size_t viewCount = 0;
    std::vector<TestStatistics> results;
};

// Builds the partition the settings ask for. The optimized builder reports its progress through
// `progress` (stage "clusters") and can be cancelled there; the others report nothing.
Partition buildPartition(const Mesh& mesh, const FaceGeometry& faces, const Settings& settings,
                         const ProgressCallback& progress = {});

// Statistics for one (cone, test) over the given views from prepared bounds.
TestStatistics measureCulling(const CullingInput& input, const std::vector<Eye>& views, CullTest test);

}  // namespace conescope
