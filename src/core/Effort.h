// How long the optimized builder searches: a setting of its own, so that what names it (Settings.h,
// the schema, the window) does not see the builder (ClusterOptimizer.h).
#pragma once

#include <cstddef>

namespace conescope {

// docs/benchmarks.md has the measured trade; optimizer/BuildPlan.h what each level does:
//  Fast:     meshoptimizer's meshlets (cone weight 1; the default budget builds them anyway), then
//            greedy moves of border faces;
//  Balanced: the same start, then annealing: two to ten sweeps on a mesh of one part (below 2,048
//            faces), one on each part of a larger mesh; clusters grown from like normals too, and
//            the better kept, on a mesh below 20,000 faces and where the meshlets leave most
//            triangles in clusters with no cone (foliage) (the default);
//  Best:     clusters grown from like normals and reduced to the budget, also started from
//            meshoptimizer's meshlets where growth misses the budget or the mesh is small, and up
//            to 100 annealing sweeps; then the balanced search too, whose partition is kept where
//            it is nearer the budget or culls more in expectation or as the run measures it (best
//            never below balanced in either; BestEffortChoice says which was kept).
//            Several times slower; culls the most.
// Fast and Balanced grow clusters too when the budget is above meshoptimizer's count.
enum class Effort { Fast, Balanced, Best };

// What the best effort's two searches made (buildOptimizedClusters, ClusterOptimizer.h), so a run can
// say when best gave the balanced search's partition and why: its own came farther from the budget,
// or at one count culled less in expectation over far views (expectedCullRate) or as the run measures
// it (its shown cone and test from its orbit: shownEfficiency, Statistics.h).
struct BestEffortChoice {
    bool ran = false;           // the best effort built both; nothing else below is set otherwise
    bool keptBalanced = false;  // the partition returned is the balanced search's
    size_t ownClusters = 0, balancedClusters = 0;
    double ownEfficiency = 0.0, balancedEfficiency = 0.0;  // as the run measures it (shownEfficiency)
    double ownExpected = 0.0, balancedExpected = 0.0;      // expectedCullRate
};

}  // namespace conescope
