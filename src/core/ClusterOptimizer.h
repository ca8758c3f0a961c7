// A cluster builder that maximises the expected cull rate directly, at a given cluster budget.
// Its code is in optimizer/: the shared state (State.h), one file per step (Steps.h) and the
// parts of large meshes (Parts.h).
#pragma once

#include <cstddef>

#include "ExpectedCull.h"  // the objective, expectedCullRate
#include "Mesh.h"
#include "Partition.h"
#include "Progress.h"

namespace conescope {

// The budget used when none is given: the count meshoptimizer's builder reaches at the same limits
// with cone weight 1, so that a comparison at defaults is at equal counts. For limits meshoptimizer
// does not take: clusters 68% full, min(maxTriangles, 2 maxVertices) being what a round patch within
// both limits can hold.
size_t defaultClusterBudget(const Mesh& mesh, const MeshletLimits& limits);

// Optimises expectedCullRate under the vertex/triangle limits with clusters that stay connected
// across edges (wherever the mesh is):
//  1. growth of small clusters of like normals (cone first, a little locality and vertex economy),
//  2. reduction to the budget: clusters are dissolved face by face into neighbours with room
//     (a full neighbour first passes one of its own faces on), or three are cut into two,
//  3. local search: border faces move to the neighbouring cluster where the objective gains,
//     first greedily, then in annealing sweeps that accept a shrinking random loss, then greedily.
// Annealing gets a fixed budget of face visits; a mesh too large for a few slow-cooling sweeps
// gets none. A mesh of more than 2^17 faces is cut at median centroids into parts of at most that
// many, which share the budget by triangles and are optimised independently, on all cores.
// targetClusters = 0 uses defaultClusterBudget. Clusters merge across gaps between separate pieces
// (with their nearest clusters) when that is what reaching the budget takes, and a run that stays
// above it starts again from meshoptimizer's meshlets (which pack vertices tighter): the result has
// at most targetClusters clusters whenever the limits allow meshoptimizer's count.
// Deterministic: the same input gives the same partition, on any number of cores.
// `progress` hears (parts done / parts, "clusters") as parts finish, on the calling thread;
// returning false stops the parts not yet started and throws OperationCancelled.
Partition buildOptimizedClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                                 size_t targetClusters = 0, const ProgressCallback& progress = {});

}  // namespace conescope
