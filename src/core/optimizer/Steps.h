// The optimized builder's steps, in the order optimizeClusters (ClusterOptimizer.cpp) runs them;
// each in its own file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "State.h"
#include "core/Progress.h"

namespace conescope::optimizer {

// Limits.cpp: clusters over the limits (meshoptimizer's meshlets once each polygon split across
// two of them has joined one whole) pass border faces to neighbours with room, where the objective
// loses least, until within them or no face fits elsewhere; each cluster still over them may keep
// the size it is left with, never growing past it.
void shedOverLimits(State& state);

// Reduction.cpp: of the clusters `face` could join, the one where the objective loses least (by
// the grown cap's bound; that change in *gain); kNone when it fits in none.
uint32_t cheapestHome(const State& state, uint32_t face, const uint32_t* targets, size_t targetCount, double* gain = nullptr);

// Growth.cpp: clusters of like normals grown one at a time over edge neighbours, each until no
// face fits the limits or `triangleCap` triangles. Makes more clusters than the budget.
void grow(State& state, double triangleCap);

// Reduction.cpp: clusters dissolved into neighbours, merged or cut three into two until at most
// `target` are left (or no step gets further).
void reduceTo(State& state, size_t target);

// Reduction.cpp: where reduceTo stopped above `target` (every merge breaks the limits), whole
// clusters merge up to `allowed.limits`, at most `allowed.clusters` of them, so that the clusters
// over the limits are no more and no larger than in meshoptimizer's partition of whole faces
// (shedOverLimits). Each cluster left over the limits keeps its size (never grows past it).
struct Overfill {
    size_t clusters = 0;
    MeshletLimits limits;
};
void overfillTo(State& state, size_t target, const Overfill& allowed);

// ThreeIntoTwo.cpp: the cluster and the two of its neighbours whose faces, cut again into two
// compact halves within the limits, score best by the objective become those two halves; false
// (nothing changes) when no pair fits. On success state.members lists the three clusters.
bool threeIntoTwo(State& state, uint32_t cluster);

// LocalSearch.cpp: border faces moved to the neighbouring cluster where the objective gains, until
// no move gains (or a pass limit).
void refine(State& state);
// LocalSearch.cpp: the same, starting from the border faces of the clusters that `moved` faces
// left or joined (and their neighbours' clusters) since a refinement: elsewhere nothing changed
// that a greedy move could use.
void refineAround(State& state, const std::vector<uint32_t>& moved);
// LocalSearch.cpp: `sweeps` annealing sweeps over all border faces, cooling from sweep to sweep.
// Returns the faces moved, in order (a face moved twice is listed twice).
std::vector<uint32_t> anneal(State& state, size_t sweeps);
// LocalSearch.cpp: `start` annealed `sweeps` times, then greedy moves where faces moved (`start`
// itself when `sweeps` is 0). Annealing accepts losses: the caller keeps the better of the two.
// Compact packed cells gain much from it (docs/dev/benchmarks-log.md has the sweeps' figures).
Partition annealedFurther(State& state, const Partition& start, size_t sweeps);

// Packing.cpp: for an explicit budget the other steps missed (`made`): `target` compact clusters
// grown at once from the centres of made's largest ones (else from seeds spread over the mesh),
// what they leave reduced into them, then local search; the packing that reaches the budget with
// cells turned most towards their normals, annealed `sweeps` times, else `made`. Reaches
// budgets up to about triangles / 93 at 64 vertices, where the other steps stop near triangles / 86.
// `progress` hears (1, "packing clusters") before each packing; false throws OperationCancelled.
Partition packToBudget(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t target, size_t sweeps,
                       const Partition& made, const ProgressCallback& progress = {});

}  // namespace conescope::optimizer
