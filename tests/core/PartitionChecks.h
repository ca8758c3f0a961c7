// Checks of a partition the optimizer tests share: valid within the limits, filled as
// meshoptimizer's own, in one piece.
#pragma once

#include <cstddef>

#include "core/Mesh.h"
#include "core/Partition.h"

namespace conescope {

// Every face in exactly one non-empty cluster, each cluster within both limits.
void expectValidWithinLimits(const Mesh& mesh, const Partition& partition, const MeshletLimits& limits);

// On polygon meshes meshoptimizer's meshlets split polygons, and its partition of whole faces
// holds more than the limits where they join a full meshlet: the default has its count, never
// more clusters over the limits nor a larger one (and holds the limits where meshoptimizer does).
void expectMeshoptimizersCountAndFill(const Mesh& mesh, const Partition& partition, const MeshletLimits& limits);

// Number of clusters whose faces do not form one piece across shared edges.
size_t disconnectedClusters(const Mesh& mesh, const Partition& partition);

}  // namespace conescope
