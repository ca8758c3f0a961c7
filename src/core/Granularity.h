// How much culling each record granularity gets on one partition, and what it costs: one cone per
// cluster with each cone and test of a run, K cones per cluster (MultiCones.h, float and compact
// records) and per-triangle culling after the cluster test, the ceiling. What `conescope-cli
// granularity` writes; every row comes from the same partition and views.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "Pipeline.h"

namespace conescope {

struct GranularityRow {
    std::string record;            // "minimal/octagon", an engine record's name, "cones-4", "cones-4-compact", "triangle"
    size_t bytesPerCluster = 0;    // the record a renderer stores per cluster
    double bitsPerTriangle = 0.0;  // bytesPerCluster * 8 * clusters / triangles
    size_t trianglesCulled = 0;    // summed over the views
    size_t backFacingTriangles = 0;
    double efficiency = 0.0;       // trianglesCulled / backFacingTriangles
    double culledShare = 0.0;      // trianglesCulled / (triangles * views): of all triangles
    double testsPerView = 0.0;     // cluster, sub-group and triangle tests made per view
    size_t falseCulls = 0;         // culled clusters or sub-groups holding a visible face
};

// How wide the cones of K sub-groups per cluster open (K = 1: each cluster's own minimal cone).
struct GranularityConeWidths {
    uint32_t cones = 1;
    double meanHalfAngleDegrees = 0.0;  // triangle-weighted over the sub-groups with a cone; 0 when none has one (conelessShare 1)
    double conelessShare = 0.0;         // of all triangles: in sub-groups no cone narrower than a hemisphere holds
    double expectedCulledShare = 0.0;   // sum T (1 - sin alpha) / 2 / T: culled from a random far direction
};

struct GranularityReport {
    RunStatistics run;             // the one-cone rows' statistics, as `stats` gives them
    std::vector<GranularityRow> rows;
    std::vector<GranularityConeWidths> widths;  // K = 1 and each of kGranularityCones (measureGranularity)
};

// The sub-group counts the rows are made for.
constexpr uint32_t kGranularityCones[] = {2, 4, 8};

// The settings a granularity report runs with: without tests given (`testsGiven` false) every test
// the tool offers but the oracle (which reads faces, not a record), the default first, for the
// per-triangle row culls after it.
Settings granularitySettings(Settings settings, bool testsGiven);

// One row per cone and test of the run, from its statistics (engine records, which read cones of
// their own, once each).
std::vector<GranularityRow> oneConeRows(const RunStatistics& run);

// The K-cone rows (float and compact record for each of kGranularityCones) and the per-triangle row
// after `clusterTest` (the run's displayed test), over `views`: one pass of the oracle per view.
// `progress` hears of every view and may cancel there. `widths`, when given, gets each K's cone widths.
std::vector<GranularityRow> finerRows(const PreparedMesh& prepared, const ClusterSet& clusters, const std::vector<Eye>& views,
                                      const Settings& settings, const ProgressCallback& progress = {},
                                      std::vector<GranularityConeWidths>* widths = nullptr);

// The whole report from prepared stages: measureRun for the one-cone rows, finerRows for the others.
GranularityReport measureGranularity(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                                     const ProgressCallback& progress = {});

// The whole report from a mesh, its stages made as runStatistics makes them: its one-cone rows are
// `stats`' numbers for the same mesh and settings.
GranularityReport runGranularity(const Mesh& mesh, const Settings& settings, const std::string& meshName = {},
                                 const ProgressCallback& progress = {});

}  // namespace conescope
