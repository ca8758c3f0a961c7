// Which clusters cost the most: the per-cluster statistics of one (cone, test) ranked by a chosen
// column, for the worst-cluster table of the CLI (`conescope-cli clusters`) and the window.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Statistics.h"

namespace conescope {

enum class ClusterSortKey {
    TestLoss,        // back faces the test drew although the whole cluster faced away (summed over views)
    PartitionLoss,   // back faces in views where the cluster also held a visible face
    Lost,            // both
    Missed,          // views where the whole cluster faced away and the test drew it
    Triangles,
    Vertices,
    HalfAngle,
    SphereRadius,
    CullFraction,    // ascending: the clusters culled from the fewest directions first
    OracleFraction,  // ascending
    Culled,          // ascending: the clusters culled least often first
    FalseCulls,      // views from which an engine's record culled it holding a visible face
    QuantisationLoss,  // back faces the quantised record drew and its float original culls
    MostCulled,      // the clusters culled most often first: a lesson's example of a cull
};

std::string toString(ClusterSortKey key);  // "test-loss", "partition-loss", "lost", "missed", ...
// Throws std::invalid_argument listing the names.
ClusterSortKey parseClusterSortKey(const std::string& text);
const std::vector<ClusterSortKey>& allClusterSortKeys();

// Cluster ids, worst first by `key` (ties by id), at most `top` of them (0 = all).
std::vector<uint32_t> rankClusters(const CullTestStatistics& statistics, ClusterSortKey key, size_t top = 0);

}  // namespace conescope
