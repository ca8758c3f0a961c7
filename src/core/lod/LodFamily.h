// What a viewer of a cluster LOD hierarchy asks of one cluster and of a cut: the cluster's family
// (its group, the clusters made from that group above, the ones it was made from below), and the
// clusters a cut draws as one level, so they can be shown and picked like any partition.
#pragma once

#include <cstdint>
#include <vector>

#include "ClusterHierarchy.h"
#include "LodCut.h"

namespace conescope {

// A cluster of a level: `cluster` of hierarchy.levels[level].
struct LodClusterId {
    size_t level = 0;
    uint32_t cluster = 0;
    bool operator==(const LodClusterId& other) const { return level == other.level && cluster == other.cluster; }
};

// Cluster `id`'s relatives: the other members of its group (same level, same group; none at the top),
// its parents (the level above's clusters made from its group: sourceGroup == its group) and its
// children (the level below's clusters of the group it was made from: group == its sourceGroup).
struct LodFamily {
    LodClusterId cluster;
    uint32_t group = kNoGroup, sourceGroup = kNoGroup;
    std::vector<uint32_t> groupMates, parents, children;
};
LodFamily lodFamilyOf(const ClusterHierarchy& hierarchy, LodClusterId id);

// Per level, per cluster, where the cut from `eye` stands to it: 0 it draws the cluster (cutFrom's
// rule), 1 a coarser level is drawn there (its group's error is within the threshold), 2 a finer one
// (its own error is not). What a viewer colours a level by.
std::vector<std::vector<uint8_t>> cutClassesFrom(const ClusterHierarchy& hierarchy, const glm::dvec3& eye, const LodThreshold& threshold);

// The clusters a cut draws (cutFrom's per level flags) as one level over level 0's positions: every
// drawn face (fanned into triangles) with its cluster, the clusters numbered in order (level after
// level, cluster order within one), bounded with the cone and sphere of `settings`. `origin` gets,
// per cluster of the result, the level's cluster it is.
LodLevel levelOfCut(const ClusterHierarchy& hierarchy, const std::vector<std::vector<uint8_t>>& drawn, const Settings& settings,
                    std::vector<LodClusterId>& origin);

}  // namespace conescope
