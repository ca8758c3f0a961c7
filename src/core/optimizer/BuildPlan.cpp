#include "BuildPlan.h"

#include <algorithm>
#include <limits>

#include "core/meshopt/Meshopt.h"

namespace conescope {

SearchPlan searchPlanFor(Effort effort, bool meshoptLimits) {
    SearchPlan plan;
    switch (effort) {
        case Effort::Fast: plan = {false, 0, 0, 0.0, 0}; break;
        case Effort::Balanced:
            plan = {false, 2, 2, std::numeric_limits<double>::infinity(), 1, kGrowWhereUncullable, true, kOnePartSweepVisits};
            break;
        case Effort::Best: plan = {true, 100, 8, 5.0e6, 100}; break;
    }
    plan.meshoptLimits = meshoptLimits;
    return plan;
}

bool startsFromMeshlets(Effort effort, bool meshoptLimits) { return !searchPlanFor(effort, meshoptLimits).growthStart && meshoptLimits; }

size_t annealingSweepsFor(Effort effort, size_t faceCount, size_t meshletParts) {
    const SearchPlan plan = searchPlanFor(effort, false);
    if (meshletParts == 1 && plan.onePartSweepVisits > 0.0)
        return std::clamp<size_t>(size_t(plan.onePartSweepVisits / double(std::max<size_t>(faceCount, 1))), plan.minSweeps, kOnePartSweepsAtMost);
    const size_t sweeps = annealingSweeps(plan, faceCount);
    return meshletParts > 1 ? std::min(sweeps, plan.sweepsPerPart) : sweeps;
}

size_t climbStride(size_t faceCount, size_t from, size_t highest) {
    const size_t steps = highest - std::min(from, highest) + 1;
    for (size_t stride = 1; stride <= kClimbStrideAtMost; ++stride)
        if (faceCount * ((steps + stride - 1) / stride + 1) <= kClimbWork) return stride;
    return 0;
}

size_t highestClimb(size_t meshletCount) { return size_t(kClimbAboveCount * double(meshletCount)); }

namespace {

// From meshoptimizer's meshlets: the default budget keeps them (as fast as meshoptimizer's own
// build); an explicit one at the balanced level grows its own clusters too (growth beat the searched
// meshlets a few clusters below their count: "Budget sweep"), elsewhere where the meshlets miss it;
// a budget above their count splits them, against growth (growth alone culled less than the count
// on a third of CGAL's meshes).
void chooseStart(BuildPlan& plan, const BuildFacts& facts) {
    if (!startsFromMeshlets(plan.effort, facts.meshoptLimits)) {
        plan.start = BuildStart::Grown;
    } else if (plan.budget == 0) {
        plan.start = BuildStart::Meshlets;
        const bool wholeGrowth = plan.effort == Effort::Balanced && facts.faces < kGrowWholeBelowFaces && meshletPartsFor(facts.faces) > 1;
        plan.alsoGrown = wholeGrowth ? AlsoGrown::Always : AlsoGrown::Never;
    } else if (plan.budget <= facts.meshletCount) {
        plan.start = BuildStart::Meshlets;
        plan.alsoGrown = plan.effort == Effort::Balanced ? AlsoGrown::Always : AlsoGrown::WhenMissed;
    } else {
        plan.start = BuildStart::SplitMeshlets;
    }
}

// An explicit budget on a mesh up to kPackingFacesAtMost faces is annealed as long as a packing (the
// best level's sweeps, one run) at the balanced level, so every budget meets the same search; one the
// start missed is packed to where the limits allow it. The best level has annealed that long already.
void chooseFinish(BuildPlan& plan, const BuildFacts& facts) {
    if (plan.budget == 0 || facts.faces > kPackingFacesAtMost) return;
    plan.finishSweeps = plan.effort == Effort::Fast ? 0 : annealingSweepsFor(Effort::Best, facts.faces, 1);
    plan.annealFurther = plan.effort == Effort::Balanced && plan.finishSweeps > 0;
    plan.packWhenMissed = plan.budget >= facts.fewest;
}

// On small meshes an explicit balanced budget climbs from the fewest clusters, so one more cluster
// never culls less in expectation (searched alone, one more cluster could cull less: the budget
// sweep in docs/dev/benchmarks-log.md). Which budgets climb depends on the mesh and limits only.
bool climbs(const BuildPlan& plan, const BuildFacts& facts) {
    if (plan.effort != Effort::Balanced || plan.budget == 0 || !facts.meshoptLimits) return false;
    const size_t highest = highestClimb(facts.meshletCount);
    return plan.budget > facts.fewest && plan.budget <= highest && climbStride(facts.faces, facts.meshletCount, highest) != 0;
}

}  // namespace

BuildPlan planBuild(Effort effort, size_t budget, const BuildFacts& facts) {
    BuildPlan plan;
    plan.effort = effort;
    plan.budget = budget;
    plan.search = searchPlanFor(effort, facts.meshoptLimits);
    plan.search.viewDistance = facts.viewDistance;
    chooseStart(plan, facts);
    chooseFinish(plan, facts);
    plan.climb = climbs(plan, facts);
    plan.alsoBalanced = effort == Effort::Best;
    if (facts.conesPerCluster > 1 && effort != Effort::Fast) {
        plan.forCones = facts.conesPerCluster;
        plan.forConesTryBelow = effort == Effort::Best ? kForConesTryBelowBest : 0.0;
    }
    return plan;
}

}  // namespace conescope
