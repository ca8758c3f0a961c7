// The optimized builder's policy as one decision: what a build at an effort and a budget does,
// picked from the effort, the budget against meshoptimizer's count and the mesh's size
// (docs/dev/architecture.md, "How the optimized builder decides", has the diagram).
// ClusterOptimizer.cpp carries the plan out.
#pragma once

#include <cstddef>

#include "Runs.h"
#include "core/ClusterOptimizer.h"

namespace conescope {

// Every threshold of the policy, here and nowhere else (docs/benchmarks.md has the figures).
// The default budget for limits meshoptimizer does not take fills clusters to this share of a round
// patch: 84 triangles at 64/124, about what meshoptimizer reaches at cone weight 1.
constexpr double kDefaultFill = 0.68;
// Packing and the further annealing of an explicit budget run on meshes up to this many faces.
constexpr size_t kPackingFacesAtMost = size_t(1) << 17;
// The climb searches on its own within this many face visits, every stride budgets at most this
// far apart, up to this multiple of meshoptimizer's count.
constexpr size_t kClimbWork = size_t(1) << 17;
constexpr size_t kClimbStrideAtMost = 8;
constexpr double kClimbAboveCount = 1.25;
// At the default budget the balanced level also grows clusters over the whole of a mesh of several
// meshlet parts below this many faces and keeps them where they cull more in expectation: across
// the parts' seams, growth joins like normals that meshoptimizer's meshlets of separate pieces mix
// (props of 2,048 faces and more: 1.08x an earlier build's culling, from 1.02x, for 1.4x their time).
// Up to 70,000 faces it bought 0.6% more for a fifth more time (docs/dev/benchmarks-log.md).
constexpr size_t kGrowWholeBelowFaces = 20000;
// A partition built for K cones: sweeps over the faces at most, and how far below zero a move
// weighed with the kept sub-groups is still tried at the best effort (docs/benchmarks.md,
// "A partition built for K cones").
constexpr int kForConesPasses = 6;
constexpr double kForConesTryBelowBest = 2.0;

// What the build knows before it starts: the mesh's faces, whether meshoptimizer takes the limits,
// its meshlet count there (0 where no explicit budget is set against it: asking waits for every
// meshlet), the fewest clusters the limits allow, the default orbit's distance and the cones per
// cluster the record will have.
struct BuildFacts {
    size_t faces = 0;
    bool meshoptLimits = false;
    size_t meshletCount = 0;
    size_t fewest = 0;
    double viewDistance = 0.0;
    uint32_t conesPerCluster = 1;
};

// Where a build starts: meshoptimizer's meshlets (searched at the budget), the same split to a
// budget above their count, or clusters grown from like normals and reduced to the budget.
enum class BuildStart { Meshlets, SplitMeshlets, Grown };

// From meshoptimizer's meshlets, whether clusters are grown too and the better at the budget kept
// (the meshlets' searched count at the default budget): never, when the searched meshlets miss the
// budget, or always.
enum class AlsoGrown { Never, WhenMissed, Always };

struct BuildPlan {
    Effort effort = Effort::Balanced;
    size_t budget = 0;  // 0: the default
    SearchPlan search{};
    BuildStart start = BuildStart::Grown;
    AlsoGrown alsoGrown = AlsoGrown::Never;
    // An explicit budget the start reached is annealed further (finishSweeps, as a packing is); one it
    // missed is packed to with compact clusters, kept only where they reach it.
    bool annealFurther = false;
    bool packWhenMissed = false;
    size_t finishSweeps = 0;
    // The balanced level's climb from the fewest clusters, one cluster at a time (climbStride).
    bool climb = false;
    // The best level runs the balanced plan too and keeps the better: nearer the budget, then what
    // the run measures (never below the default there).
    bool alsoBalanced = false;
    // For K > 1 cones per cluster, balanced and best move faces afterwards while the K sub-groups'
    // expected culling rises (optimizer/ForCones.h); best also tries moves the kept sub-groups
    // weigh at down to -kForConesTryBelowBest triangles. 1: not aimed at K cones.
    uint32_t forCones = 1;
    double forConesTryBelow = 0.0;
};

// How each effort searches (sweeps, growth where meshlets leave clusters with no cone).
SearchPlan searchPlanFor(Effort effort, bool meshoptLimits);

// Whether a plan at this effort starts from meshoptimizer's meshlets (and needs their count).
bool startsFromMeshlets(Effort effort, bool meshoptLimits);

// The plan of a build at `effort` and `budget` (0: the default) on a mesh with these facts.
BuildPlan planBuild(Effort effort, size_t budget, const BuildFacts& facts);

// Every how many budgets the climb from `from` to `highest` searches on its own: 0 when even every
// kClimbStrideAtMost-th budget costs too much.
size_t climbStride(size_t faceCount, size_t from, size_t highest);

// The highest budget a balanced build climbs to.
size_t highestClimb(size_t meshletCount);

}  // namespace conescope
