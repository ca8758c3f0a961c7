#include "Runs.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "State.h"
#include "Steps.h"
#include "core/meshopt/Meshopt.h"

namespace conescope {

size_t annealingSweeps(const SearchPlan& plan, size_t faceCount) {
    const double affordable = plan.sweepFaceVisits / double(std::max<size_t>(faceCount, 1));  // may be infinite
    const size_t sweeps = affordable >= double(plan.maxSweeps) ? plan.maxSweeps : size_t(affordable);
    return sweeps < plan.minSweeps ? 0 : sweeps;
}

std::optional<bool> nearerTheBudget(size_t a, size_t b, size_t target) {
    const bool aAbove = a > target, bAbove = b > target;
    if (aAbove != bAbove) return !aAbove;
    if (a != b) return aAbove ? a < b : a > b;
    return std::nullopt;
}

namespace {

// Growth stops a cluster at this multiple of the budget's mean size (or the triangle limit). At
// exactly the mean, every cluster ends up the same size and the reduction can get stuck a few
// clusters above the budget on regular meshes; the margin lets some grow larger instead.
constexpr double kGrowthCap = 1.25;

// The sum of the objective over the clusters: which of two runs to keep at the same count.
double objectiveOf(const optimizer::State& state) {
    double value = 0.0;
    for (const optimizer::Cluster& cluster : state.clusters)
        if (!cluster.faces.empty()) value += optimizer::valueOf(cluster.triangles, cluster.cap);
    return value;
}

bool withinLimits(const optimizer::State& state) {
    for (const optimizer::Cluster& cluster : state.clusters)
        if (cluster.triangles > state.limits.maxTriangles || cluster.vertices > state.limits.maxVertices) return false;
    return true;
}

// Whether run `a` is the one to keep over run `b` (nearerTheBudget, then the better objective).
bool closerToTheBudget(size_t a, double aValue, size_t b, double bValue, size_t target) {
    return nearerTheBudget(a, b, target).value_or(aValue > bValue);
}
bool closerToTheBudget(const optimizer::State& a, const optimizer::State& b, size_t target) {
    return closerToTheBudget(a.liveClusters, objectiveOf(a), b.liveClusters, objectiveOf(b), target);
}

// Where meshoptimizer's partition of whole faces is over the limits (a polygon split across
// meshlets joins one whole): how many of its clusters are, and the most they hold. A run from
// other clusters may end with as many that large (optimizer::overfillTo), no more.
optimizer::Overfill overfillOf(const optimizer::State& state) {
    optimizer::Overfill allowed{0, state.limits};
    for (const optimizer::Cluster& cluster : state.clusters) {
        if (cluster.faces.empty() || (cluster.vertices <= state.limits.maxVertices && cluster.triangles <= state.limits.maxTriangles)) continue;
        ++allowed.clusters;
        allowed.limits.maxVertices = std::max<size_t>(allowed.limits.maxVertices, cluster.vertices);
        allowed.limits.maxTriangles = std::max<size_t>(allowed.limits.maxTriangles, cluster.triangles);
    }
    return allowed;
}

// Reduction to the budget and local search from the clusters `state` holds; where the limits stop
// the reduction above the budget, clusters as full as meshoptimizer's own may take it there.
void reduceAndSearch(optimizer::State& state, size_t target, size_t sweeps, const optimizer::Overfill& allowed = {}) {
    optimizer::reduceTo(state, target);
    optimizer::overfillTo(state, target, allowed);
    optimizer::refine(state);
    // Annealing moves change only the clusters they touch: the refinement after it looks there.
    if (sweeps > 0) optimizer::refineAround(state, optimizer::anneal(state, sweeps));
}

// Clusters grown from like normals and reduced to the budget, then searched, in `state` (cleared first).
void growAndSearch(optimizer::State& state, size_t target, size_t sweeps, const optimizer::Overfill& allowed = {}) {
    optimizer::clear(state);
    const double triangles = double(triangleCount(state.mesh));
    const MeshletLimits& limits = state.limits;
    optimizer::grow(state, std::min(double(limits.maxTriangles), kGrowthCap * triangles / double(target)));
    if (state.liveClusters < target) {  // a generous budget: grow again at its mean size
        optimizer::clear(state);
        optimizer::grow(state, std::min(double(limits.maxTriangles), triangles / double(target)));
    }
    reduceAndSearch(state, target, sweeps, allowed);
}

// The share of the triangles in clusters with no cone (wider than a hemisphere, or no normals).
double uncullableShare(const optimizer::State& state) {
    double all = 0.0, uncullable = 0.0;
    for (const optimizer::Cluster& cluster : state.clusters) {
        if (cluster.faces.empty()) continue;
        all += cluster.triangles;
        if (!(cluster.cap.cosRadius > 0.0) || cluster.cap.cosRadius > 1.0) uncullable += cluster.triangles;
    }
    return all > 0.0 ? uncullable / all : 0.0;
}

// Below this many faces the best effort also starts from meshoptimizer's meshlets every time: on
// small meshes of few clusters growth can end below meshoptimizer's own objective (CGAL's patch-01,
// dragknob, patch-13), and the second start costs little there.
constexpr size_t kBothStartsBelowFaces = size_t(1) << 14;

// meshoptimizer's meshlets searched at the budget, or those meshlets again where the search ended
// lower in the objective at their count (annealing accepts losses): never worse than
// meshoptimizer's own partition, in expectation over view directions. A polygon split across
// meshlets joins one of them whole and can overfill it: such meshlets first pass faces to
// neighbours with room, and those still over the limits keep their size, never growing past it
// (the limits of meshoptimizer's own partition of these faces; whole polygons within the limits
// need more clusters than its count on most polygon meshes). A meshlet's pieces stay together:
// handing its smaller pieces to neighbours with room (measured on CGAL's cheese) widened those
// neighbours' cones more than it saved. *allowed: what meshoptimizer's partition holds over the limits.
std::unique_ptr<optimizer::State> searchFromMeshlets(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                                                     const Partition& meshlets, size_t target, size_t sweeps,
                                                     optimizer::Overfill* allowed = nullptr) {
    auto state = std::make_unique<optimizer::State>(mesh, faces, limits);
    optimizer::assign(*state, meshlets);
    const double startValue = objectiveOf(*state);
    if (allowed) *allowed = overfillOf(*state);
    if (!withinLimits(*state)) optimizer::shedOverLimits(*state);
    reduceAndSearch(*state, target, sweeps);
    if (state->liveClusters >= meshlets.clusterCount && objectiveOf(*state) < startValue) optimizer::assign(*state, meshlets);
    return state;
}

// The objective from eyes `distance` away: each cluster's cone widened by the angle its bounding
// sphere (about its faces' centroids, out to its vertices) spans from there (what a cone and
// sphere test culls; the octagon's apex test culls from about as many views).
double objectiveFrom(const optimizer::State& state, double distance) {
    double value = 0.0;
    for (const optimizer::Cluster& cluster : state.clusters) {
        if (cluster.faces.empty() || !(cluster.cap.cosRadius > 0.0) || cluster.cap.cosRadius > 1.0) continue;
        glm::dvec3 centre(0.0);
        for (uint32_t f : cluster.faces) centre += state.geometry.centroids[f];
        centre /= double(cluster.faces.size());
        double radius = 0.0;
        for (uint32_t f : cluster.faces)
            for (size_t k = 0; k < state.mesh.faceSize(f); ++k)
                radius = std::max(radius, glm::length(glm::dvec3(state.mesh.positions[state.mesh.faceBegin(f)[k]]) - centre));
        const double widened = std::acos(std::min(1.0, cluster.cap.cosRadius)) + std::asin(std::min(1.0, radius / distance));
        if (widened < M_PI / 2) value += expectedCulledTriangles(cluster.triangles, std::sin(widened));
    }
    return value;
}

// A run kept as a partition, with what the comparison of runs needs.
struct Run {
    Partition partition;
    size_t clusters;
    double objective;
};
Run runOf(const optimizer::State& state) { return {optimizer::result(state), state.liveClusters, objectiveOf(state)}; }

}  // namespace

// The fast levels start from meshoptimizer's meshlets (`meshlets`, given when the budget is at most
// their count) and keep that run when it reaches the budget; the balanced level also grows clusters where those meshlets stay mostly without a cone
// (SearchPlan::growWhereUncullable), with no more clusters over the limits than meshoptimizer's
// partition holds, and keeps the better. Otherwise, and at the best level, clusters are grown and
// reduced; at the best level, where that cannot get down to the budget (the limits bind: thin
// strips, many vertices per triangle), and always on small meshes, meshoptimizer's start is
// searched too, and the run nearer the budget (then the better objective) is kept.
Partition optimizeClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t target,
                           const SearchPlan& plan, size_t sweeps, const Partition* meshlets) {
    std::unique_ptr<optimizer::State> packed;
    optimizer::Overfill allowed;
    if (!plan.growthStart && meshlets) {
        packed = searchFromMeshlets(mesh, faces, limits, *meshlets, target, sweeps, &allowed);
        if (packed->liveClusters <= target) {
            if (uncullableShare(*packed) < plan.growWhereUncullable) return optimizer::result(*packed);
            // Growth is kept where it culls more from afar and from the default orbit's distance:
            // clusters of like normals spread wider, and a wide bounding sphere narrows the views
            // a cluster is culled from up close (a door's panel as one cluster culled less at 3
            // half-diagonals than meshoptimizer's meshlets of it).
            Run fromMeshlets = runOf(*packed);
            const double meshletsNearBy = objectiveFrom(*packed, plan.viewDistance);
            growAndSearch(*packed, target, sweeps, allowed);  // the same state, cleared
            const bool grownBetter = closerToTheBudget(packed->liveClusters, objectiveOf(*packed), fromMeshlets.clusters, fromMeshlets.objective, target) &&
                                     objectiveFrom(*packed, plan.viewDistance) >= meshletsNearBy;
            return grownBetter ? optimizer::result(*packed) : std::move(fromMeshlets.partition);
        }
    }
    optimizer::State state(mesh, faces, limits);
    growAndSearch(state, target, sweeps, allowed);
    // The fast levels keep meshoptimizer's start when growth gets no nearer the budget: a budget
    // the limits do not allow must not end above meshoptimizer's count.
    if (packed && !closerToTheBudget(state, *packed, target)) return optimizer::result(*packed);
    const bool small = mesh.faceCount() < kBothStartsBelowFaces;
    if (!plan.growthStart || (state.liveClusters <= target && !small) || !plan.meshoptLimits) return optimizer::result(state);
    packed = searchFromMeshlets(mesh, faces, limits, meshlets ? *meshlets : buildMeshoptMeshlets(mesh, limits, 1.0f), target, sweeps);
    return optimizer::result(closerToTheBudget(*packed, state, target) ? *packed : state);
}

}  // namespace conescope
