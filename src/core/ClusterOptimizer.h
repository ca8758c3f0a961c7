// A cluster builder that maximises the expected cull rate directly, at a given cluster budget.
// Its code is in optimizer/: the shared state (State.h), one file per step (Steps.h) and the
// parts it works on (Parts.h).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "Effort.h"
#include "ExpectedCull.h"  // the objective, expectedCullRate
#include "Mesh.h"
#include "Partition.h"
#include "Progress.h"

namespace conescope {

class MeshletStream;  // meshopt/Meshopt.h: meshoptimizer's meshlets as they are made

// The budget used when none is given: the count meshoptimizer's builder reaches at the same limits
// with cone weight 1, so that a comparison at defaults is at equal counts. For limits meshoptimizer
// does not take: clusters 68% full, min(maxTriangles, 2 maxVertices) being what a round patch within
// both limits can hold.
size_t defaultClusterBudget(const Mesh& mesh, const MeshletLimits& limits);

// The fewest clusters the limits allow, whatever the partition: every triangle and every vertex a
// face uses must be in some cluster. A budget below it cannot be met; one at or above it may still
// be out of reach where the vertex limit binds (a 64-vertex patch of a surface holds about 98 triangles).
size_t fewestClustersWithin(const Mesh& mesh, const MeshletLimits& limits);

// What a caller does with each part of the partition as soon as it is made, on the thread that made
// it (say its bounds): the part's number among `parts`, its faces (ascending mesh face ids) and
// their clusters, numbered from 0 within the part. The partition numbers its clusters part after
// part, each part's in this order. Heard once for every part, empty ones included; when meshoptimizer's
// parts miss a smaller budget and grown clusters come nearer it, heard again once, as one part
// holding every face, with the partition returned.
using PartClusters = std::function<void(size_t part, size_t parts, const std::vector<uint32_t>& faces, const Partition& clusters)>;

// The culling efficiency a run reports for a partition (its shown cone and test from its orbit), so
// that the best effort never culls less there than balanced (buildPartition makes it from Settings).
using PartitionMeasure = std::function<double(const Partition&)>;

// Maximises expectedCullRate under the vertex/triangle limits at a budget of targetClusters (0:
// defaultClusterBudget): from meshoptimizer's meshlets or from grown clusters reduced to the budget,
// then local search, on parts of the mesh at once (docs/dev/architecture.md, "The optimized builder",
// has the steps). The result has at most targetClusters clusters whenever the limits allow
// meshoptimizer's count, and never more than that count. An explicit budget those steps miss is
// packed to (compact clusters, which cull less), on meshes up to 2^17 faces, where packing reaches
// it. The same input gives the same partition on any number of cores.
// `progress` hears (parts done / parts, "clusters") as parts finish; false cancels (OperationCancelled).
// `meshlets`: meshoptimizer's meshlets of this mesh at these limits when startsFromMeshoptMeshlets,
// already started (say while the mesh was being prepared); started here when needed and not given.
// Its thread helps with the parts once its meshlets are made, so a stream serves one build.
// `conesPerCluster` > 1: at the balanced and best efforts the partition is built for that many cones
// per cluster (optimizer/ForCones.h), and no part is heard. `choice`, when given, hears what the
// best effort chose between its two searches (ran = false at the other efforts), `measure` (empty:
// as `stats` with no options measures) what it tells them apart by at one count.
Partition buildOptimizedClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                                 size_t targetClusters = 0, const ProgressCallback& progress = {},
                                 Effort effort = Effort::Balanced, MeshletStream* meshlets = nullptr,
                                 const PartClusters& partDone = {}, uint32_t conesPerCluster = 1,
                                 BestEffortChoice* choice = nullptr, const PartitionMeasure& measure = {});

// The annealing sweeps buildOptimizedClusters makes at `effort` on a mesh of `faceCount` faces
// from meshoptimizer's meshlets in `meshletParts` parts (meshletPartsFor), on each part when there
// are several; a mesh too large for slow cooling gets none.
size_t annealingSweepsFor(Effort effort, size_t faceCount, size_t meshletParts);

// Whether buildOptimizedClusters starts from meshoptimizer's meshlets at cone weight 1 (and takes
// their count as the default budget): the fast levels at limits meshoptimizer takes, for budgets up
// to that count.
bool startsFromMeshoptMeshlets(const MeshletLimits& limits, Effort effort);

}  // namespace conescope
