// How long the optimized builder searches: a setting of its own, so that what names it (Settings.h,
// the schema, the window) does not see the builder (ClusterOptimizer.h).
#pragma once

namespace conescope {

// docs/benchmarks.md has the measured trade; optimizer/BuildPlan.h what each level does:
//  Fast:     meshoptimizer's meshlets (cone weight 1; the default budget builds them anyway), then
//            greedy moves of border faces;
//  Balanced: the same start, then annealing: two to ten sweeps on a mesh of one part (below 2,048
//            faces), one on each part of a larger mesh; where the meshlets leave most triangles in
//            clusters with no cone (foliage, props of a few clusters), clusters grown from like
//            normals too, and the better kept (the default);
//  Best:     clusters grown from like normals and reduced to the budget, also started from
//            meshoptimizer's meshlets where growth misses the budget or the mesh is small, and up
//            to 100 annealing sweeps; then the balanced search too, whose partition is kept where
//            it is nearer the budget or culls more in expectation (best never below balanced).
//            Several times slower; culls the most.
// Fast and Balanced grow clusters too when the budget is above meshoptimizer's count.
enum class Effort { Fast, Balanced, Best };

}  // namespace conescope
