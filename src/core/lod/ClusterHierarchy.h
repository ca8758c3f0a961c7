// A cluster LOD hierarchy as engines draw them (Nanite, meshoptimizer's clusterlod): level 0 is a
// partition of the mesh; each level above groups adjacent clusters of the one below, simplifies
// every group to about half its triangles with the group's border locked, and splits it into
// clusters again. A cut through it from an eye (LodCut.h) picks, per region, the coarsest clusters
// whose error is small enough there.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "core/Effort.h"
#include "core/Pipeline.h"
#include "core/Spheres.h"

namespace conescope {

constexpr uint32_t kNoGroup = std::numeric_limits<uint32_t>::max();

// Where a cluster sits in the hierarchy, and the two error bounds the cut compares. `error` is its
// own (the simplification of the group it was made from; 0 at level 0) and `parentError` its
// group's, at which the level above replaces it (infinite at the top). Each error comes with the
// sphere it is measured from; a parent's error and sphere hold its children's, so the error seen
// from any eye never falls going up (the cut rule needs that).
struct LodCluster {
    uint32_t group = kNoGroup;        // its group in this level (kNoGroup: the top, never replaced)
    uint32_t sourceGroup = kNoGroup;  // the group of the level below it was made from (kNoGroup at level 0)
    double error = 0.0;
    double parentError = std::numeric_limits<double>::infinity();
    Sphere errorSphere, parentSphere;
};

// One level: a mesh of its own faces over the same positions as the original (level 0 is the mesh as
// prepared, the others triangles), its clusters with bounds as any partition gets them, and each
// cluster's place.
struct LodLevel {
    PreparedMesh prepared;
    ClusterSet clusters;
    std::vector<LodCluster> place;  // per cluster
    size_t groups = 0;              // groups of this level's clusters (0 at the top)
    size_t triangles() const { return prepared.triangles; }
};

struct ClusterHierarchy {
    std::vector<LodLevel> levels;
    Settings settings;  // the builder and limits of level 0, the cone and sphere of every level
    double buildSeconds = 0.0;
};

// How a hierarchy is built. Groups of up to `groupSize` adjacent clusters are simplified to
// `reduction` of their triangles; building stops when one group is left, after `maxLevels`, or when a
// level keeps more than `stallShare` of the triangles of the one below (simplification stalled).
// Per cluster its group, from the level's triangles and their clusters: groupAdjacentClusters's
// signature, so that another grouping (bench/lod_grouping.cpp: METIS) can be measured against it.
using ClusterGrouping = std::function<std::vector<uint32_t>(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle,
                                                            size_t clusterCount, size_t groupSize)>;

struct LodBuildOptions {
    size_t groupSize = 8;
    ClusterGrouping grouping;  // empty: groupAdjacentClusters
    double reduction = 0.5;
    double stallShare = 0.85;
    size_t maxLevels = 24;
    // How long the optimized builder searches when it splits a simplified group (level 0 is built
    // with the settings' own effort): fast keeps a 50,000-triangle hierarchy within 3x a default
    // run; balanced culls a little more per level at about twice the build time (docs/benchmarks.md).
    Effort splitEffort = Effort::Fast;
};

// Builds the hierarchy of `prepared`: level 0 by buildClusters with `settings`, the levels above from
// it. Reports a stage per level and may cancel between groups (OperationCancelled).
ClusterHierarchy buildClusterHierarchy(const PreparedMesh& prepared, const Settings& settings, const LodBuildOptions& options = {},
                                       const ProgressCallback& progress = {});

// A level of `base`'s hierarchy from its triangles (three ids into base's positions) and their
// clusters (numbered in order of first use), bounded with the cone and sphere of `settings`; its
// places are left to the caller.
LodLevel lodLevelOf(const PreparedMesh& base, const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle,
                    const Settings& settings);

// Groups of at most `groupSize` clusters, grown from the cluster with the fewest free neighbours by
// the neighbour sharing the most border (edges) with the group: per cluster its group.
// `clusterOfTriangle` and `triangles` (three vertex ids each) give the adjacency.
std::vector<uint32_t> groupAdjacentClusters(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle,
                                            size_t clusterCount, size_t groupSize);

// A sphere holding every one of `spheres` (not the smallest: centred at their mean).
Sphere sphereAroundSpheres(const std::vector<Sphere>& spheres);

}  // namespace conescope
