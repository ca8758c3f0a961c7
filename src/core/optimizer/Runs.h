// One run of the optimized builder's steps (Steps.h) on a mesh or a part of one, as a plan of
// search asks for it: where it starts, whether it also grows its own clusters, its annealing.
// ClusterOptimizer.cpp decides the plan and the parts.
#pragma once

#include <cstddef>
#include <optional>

#include "core/Mesh.h"
#include "core/Partition.h"

namespace conescope {

// Growth from meshoptimizer's meshlets where half the triangles are in clusters with no cone:
// there single moves across edges gain nothing (no cluster gets a cone from one face more or less,
// and meshlets that join separate pieces, as foliage's leaves, cannot part them), while growth
// groups like normals and the reduction merges them across gaps. Where fewer are, growth beats the
// searched meshlets less often and costs as much (docs/benchmarks.md, "Foliage and small props").
constexpr double kGrowWhereUncullable = 0.5;
constexpr double kNever = 2.0;
// A mesh of one part (below 2,048 faces) anneals up to 10 sweeps of this many face visits in all:
// milliseconds, on props whose whole run takes about ten.
constexpr double kOnePartSweepVisits = 8000.0;
constexpr size_t kOnePartSweepsAtMost = 10;

// How one effort level searches: where it starts, and its annealing. Sweeps go over all faces; a
// level gets at most maxSweeps, and no more face visits than sweepFaceVisits (each visit costs well
// under a microsecond). From a growth start fewer than minSweeps cool too fast to pay. From
// meshoptimizer's meshlets the first sweeps pay most, and the second only on a mesh of one part, so
// the balanced level takes one on each part of a larger mesh, and on a mesh of one part (props of
// a few clusters, whose whole run takes milliseconds) as many as a few thousand face visits buy,
// from two to ten (annealingSweepsFor).
// docs/benchmarks.md ("Why the constants are what they are") has the figures.
struct SearchPlan {
    bool growthStart;  // false: start from meshoptimizer's meshlets where they are within the limits
    size_t maxSweeps, minSweeps;
    double sweepFaceVisits;
    size_t sweepsPerPart;  // at most this many on each of meshoptimizer's meshlet parts, when more than one
    // From meshoptimizer's meshlets, clusters are also grown and reduced (and the better run kept)
    // on a part where the searched meshlets leave at least this share of the triangles in clusters
    // with no cone, and on a mesh of one part (growOnOnePart).
    double growWhereUncullable = kNever;
    bool growOnOnePart = false;
    // A mesh of one part anneals as many sweeps as onePartSweepVisits face visits buy, from
    // maxSweeps down to minSweeps.
    double onePartSweepVisits = 0.0;
    // How far the default orbit's eyes are from the whole mesh (3 half-diagonals of its box), for
    // keeping grown clusters only where they cull more from there too.
    double viewDistance = 0.0;
    // Whether meshoptimizer's builder takes the limits, so that its meshlets can be a start: asked
    // of meshopt/ once per build (searchPlanFor), not again at every step that needs to know.
    bool meshoptLimits = false;
};

// The annealing sweeps the plan buys for a mesh of this size; too few to cool slowly are not worth
// their time (0).
size_t annealingSweeps(const SearchPlan& plan, size_t faceCount);

// The one rule for which of two runs to keep at a budget: within it first, then the nearer count
// (fewer clusters cull less, and only equal counts compare fairly). Empty when the counts are equal
// and the objective decides.
std::optional<bool> nearerTheBudget(size_t a, size_t b, size_t target);

// One run of the whole optimisation on a mesh at a budget of `target` clusters, with `sweeps`
// annealing sweeps; `meshlets`: meshoptimizer's meshlets of this mesh when the plan starts there.
Partition optimizeClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t target,
                           const SearchPlan& plan, size_t sweeps, const Partition* meshlets);

}  // namespace conescope
