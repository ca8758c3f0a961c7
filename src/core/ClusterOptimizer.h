// A cluster builder that maximises the expected cull rate directly, at a given cluster budget.
// Its code is in optimizer/: the shared state (State.h), one file per step (Steps.h) and the
// parts it works on (Parts.h).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "ExpectedCull.h"  // the objective, expectedCullRate
#include "Mesh.h"
#include "meshopt/Meshopt.h"
#include "Partition.h"
#include "Progress.h"

namespace conescope {

// How long the optimized builder searches (docs/benchmarks.md has the measured trade):
//  Fast:     meshoptimizer's meshlets (cone weight 1; the default budget builds them anyway), then
//            greedy moves of border faces;
//  Balanced: the same start, then annealing: two sweeps on a mesh of one part, one on each part of
//            a larger mesh (the default);
//  Best:     clusters grown from like normals and reduced to the budget, also started from
//            meshoptimizer's meshlets where growth misses the budget or the mesh is small, and up
//            to 100 annealing sweeps. Several times slower; culls the most.
// Fast and Balanced grow clusters too when the budget is above meshoptimizer's count.
enum class Effort { Fast, Balanced, Best };

// The budget used when none is given: the count meshoptimizer's builder reaches at the same limits
// with cone weight 1, so that a comparison at defaults is at equal counts. For limits meshoptimizer
// does not take: clusters 68% full, min(maxTriangles, 2 maxVertices) being what a round patch within
// both limits can hold.
size_t defaultClusterBudget(const Mesh& mesh, const MeshletLimits& limits);

// What a caller does with each part of the partition as soon as it is made, on the thread that made
// it (say its bounds): the part's number among `parts`, its faces (ascending mesh face ids) and
// their clusters, numbered from 0 within the part. The partition numbers its clusters part after
// part, each part's in this order. Heard once for every part, empty ones included; when meshoptimizer's
// parts miss a smaller budget and grown clusters come nearer it, heard again once, as one part
// holding every face, with the partition returned.
using PartClusters = std::function<void(size_t part, size_t parts, const std::vector<uint32_t>& faces, const Partition& clusters)>;

// Optimises expectedCullRate under the vertex/triangle limits, from one of two starts:
//  - meshoptimizer's meshlets as they are (a meshlet may hold triangles of separate parts, as
//    meshoptimizer packs by distance);
//  - growth of small clusters of like normals (cone first, a little locality and vertex economy),
//    then reduction to the budget: clusters are dissolved face by face into neighbours with room (a
//    full neighbour first passes one of its own faces on), three are cut into two, and clusters
//    merge with their nearest ones across gaps when separate pieces must share clusters.
// Then local search: border faces move to the neighbouring cluster where the objective gains,
// greedily, then in annealing sweeps that accept a shrinking random loss, then greedily again.
// `effort` picks the start and the number of sweeps (Effort above); a mesh too large for a few
// slow-cooling sweeps gets none. The mesh is cut into parts that share the budget and are
// optimised independently, on all cores: from meshoptimizer's meshlets, the parts they come in
// (MeshletStream.h: consecutive meshlets of about 640 faces, each refined as soon as it is made, on
// one core while the meshlets are still being built on the other, then on both); from growth,
// halves of halves of at most 2^17 faces; a budget below meshoptimizer's count that its parts miss
// is grown too, and the result nearer the budget kept. targetClusters = 0 uses defaultClusterBudget;
// the result has at most targetClusters clusters whenever the limits allow meshoptimizer's count,
// and never more than meshoptimizer's count when a smaller budget is out of reach.
// Deterministic: the same input gives the same partition, on any number of cores.
// `progress` hears (parts done / parts, "clusters") as parts finish, on the calling thread;
// returning false stops the parts not yet started and throws OperationCancelled.
// `meshlets`: meshoptimizer's meshlets of this mesh at these limits when startsFromMeshoptMeshlets,
// already started (say while the mesh was being prepared); started here when needed and not given.
// Its thread helps with the parts once its meshlets are made, so a stream serves one build.
Partition buildOptimizedClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                                 size_t targetClusters = 0, const ProgressCallback& progress = {},
                                 Effort effort = Effort::Balanced, MeshletStream* meshlets = nullptr,
                                 const PartClusters& partDone = {});

// The annealing sweeps buildOptimizedClusters makes at `effort` on a mesh of `faceCount` faces
// from meshoptimizer's meshlets in `meshletParts` parts (meshletPartsFor), on each part when there
// are several; a mesh too large for slow cooling gets none.
size_t annealingSweepsFor(Effort effort, size_t faceCount, size_t meshletParts);

// Whether buildOptimizedClusters starts from meshoptimizer's meshlets at cone weight 1 (and takes
// their count as the default budget): the fast levels at limits meshoptimizer takes, for budgets up
// to that count.
bool startsFromMeshoptMeshlets(const MeshletLimits& limits, Effort effort);

}  // namespace conescope
