// The optimized builder aimed at K cones per cluster (MultiCones.h): after the build, faces move
// across cluster borders while the sum over clusters of their K sub-groups' expected culled
// triangles rises. One cone wants clusters whose normals are alike; K cones want clusters whose
// normals fall into K tight bundles, and a face on a border often fits a neighbour's bundle better.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Cones.h"
#include "core/Mesh.h"
#include "core/Partition.h"
#include "core/Progress.h"

namespace conescope {

// One cluster's faces (ascending ids, as computeMultiCones takes them) split into K sub-groups as
// computeMultiCones splits them, and the objective's share: each sub-group's expectedCulledTriangles
// summed (a sub-group holding a degenerate face never culls, as in the record).
struct ConeGroupSplit {
    std::vector<uint32_t> faces;   // ascending
    std::vector<uint8_t> group;    // per face
    std::vector<ConeOfNormals> cones;  // per sub-group
    std::vector<uint32_t> triangles;   // per sub-group
    double value = 0.0;
};
ConeGroupSplit splitClusterForCones(const Mesh& mesh, const FaceGeometry& faces, std::vector<uint32_t> clusterFaces, uint32_t conesPerCluster);

// Moves faces of `partition` to clusters across their edges, within `limits`, keeping every cluster
// non-empty and edge-connected (as far as it was) and the cluster count, while the sum of
// splitClusterForCones values rises: at most `passes` sweeps over the faces, fewer once a sweep
// gains under a ten-thousandth. A move is first weighed with both clusters' sub-groups as they are
// (cheap: no split) and tried only when that gains more than -`tryBelow` triangles; it is made when
// the two clusters split again gain (a split may find bundles the kept sub-groups miss, so a larger
// `tryBelow` finds more moves in more time). Returns the moves made. `progress` hears the sweeps
// ("clusters for K cones"); returning false throws OperationCancelled.
size_t refineForCones(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, uint32_t conesPerCluster,
                      Partition& partition, int passes = 6, double tryBelow = 0.0, const ProgressCallback& progress = {});

}  // namespace conescope
