// Packing: for an explicit budget the other steps miss where the vertex limit binds. Clusters
// shaped by their normals, or meshoptimizer's meshlets, hold about 86 triangles in 64 vertices; a
// round 64-vertex patch holds up to about 98. So the clusters are made again for their shape: as
// many seeds as the budget (the centres of the largest clusters made, else spread farthest first)
// grow all at once, each cell taking its nearest faces while within the limits, and move to their
// cells' centres a few times (Lloyd). What no cell could take is grown into clusters of its own and
// the reduction places those; the local search then turns the compact cells towards the normals.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

#include "Steps.h"
#include "core/ExpectedCull.h"

namespace conescope::optimizer {

namespace {

// Lloyd rounds: the cells' seeds moved to their centres and grown again. Most of the gain comes
// in the first few.
constexpr int kLloydRounds = 4;
// How much a turned normal counts against a face, in cell radii at a right angle (1 - cos): cells
// that follow the normals cull more but hold fewer triangles in their vertices. The largest weight
// that still reaches the budget is searched for among these (a turn weight helps packed cells cull:
// docs/dev/benchmarks-log.md, "Real props, polygons, double-sided meshes and budgets").
constexpr double kTurnWeights[] = {0.0, 0.0625, 0.25, 1.0, 4.0, 16.0};

// Below this many faces packing is tried whatever the budget asks per cluster: it costs little.
constexpr size_t kAlwaysTriedBelowFaces = size_t(1) << 14;

struct Reach {
    double distance;
    uint32_t face, cluster;
    bool operator<(const Reach& other) const {
        if (distance != other.distance) return distance > other.distance;
        return face != other.face ? face > other.face : cluster > other.cluster;
    }
};

struct Seed {
    uint32_t face;
    glm::dvec3 normal;  // the cell's mean normal, faces turned from it are farther
};

// `count` seed faces, each the farthest (along edges, centroid to centroid) from those before it;
// a piece no seed reached yet is the farthest of all, so separate pieces get seeds first.
std::vector<Seed> spreadSeeds(const State& state, size_t count) {
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<glm::dvec3>& centroids = state.geometry.centroids;
    std::vector<double> distance(state.faceCount, inf);
    std::priority_queue<std::pair<double, uint32_t>> farthest;  // lazy: stale entries skipped
    for (uint32_t f = 0; f < state.faceCount; ++f) farthest.push({inf, f});
    std::vector<Seed> seeds;
    std::priority_queue<Reach> near;
    while (seeds.size() < count && !farthest.empty()) {
        const auto [d, seed] = farthest.top();
        farthest.pop();
        if (d != distance[seed] || (d == 0.0 && !seeds.empty())) continue;
        seeds.push_back({seed, state.geometry.normals[seed]});
        distance[seed] = 0.0;
        near.push({0.0, seed, 0});
        while (!near.empty()) {  // distances shortened by the new seed
            const Reach top = near.top();
            near.pop();
            if (top.distance > distance[top.face]) continue;
            for (const uint32_t* g = state.acrossEdge.begin(top.face); g != state.acrossEdge.end(top.face); ++g) {
                const double through = top.distance + glm::length(centroids[*g] - centroids[top.face]);
                if (through < distance[*g]) distance[*g] = through, near.push({through, *g, 0}), farthest.push({through, *g});
            }
        }
    }
    return seeds;
}

// How far a face is from a seed: centroid distance plus, in units of a cell's radius, how far its
// normal turns from the seed's.
double reachOf(const State& state, const Seed& seed, uint32_t face, double turnWeight) {
    const double turn = state.usable[face] ? 1.0 - glm::dot(state.geometry.normals[face], seed.normal) : 0.0;
    return glm::length(state.geometry.centroids[face] - state.geometry.centroids[seed.face]) + turnWeight * turn;
}

// Every seed grows at once, the nearest face to its seed first, each cluster taking a face only
// within the limits. Returns the triangles left to no cluster.
size_t growCells(State& state, const std::vector<Seed>& seeds, double turnWeight) {
    clear(state);
    state.clusters.resize(seeds.size());
    state.liveClusters = seeds.size();
    std::priority_queue<Reach> heap;
    for (uint32_t c = 0; c < seeds.size(); ++c) heap.push({0.0, seeds[c].face, c});
    size_t taken = 0;
    while (!heap.empty()) {
        const Reach top = heap.top();
        heap.pop();
        if (state.clusterOf[top.face] != kNone || !fits(state, top.face, top.cluster)) continue;
        attach(state, top.face, top.cluster);
        taken += state.faceTriangles[top.face];
        for (const uint32_t* g = state.acrossEdge.begin(top.face); g != state.acrossEdge.end(top.face); ++g)
            if (state.clusterOf[*g] == kNone) heap.push({reachOf(state, seeds[top.cluster], *g, turnWeight), *g, top.cluster});
    }
    state.liveClusters = size_t(std::count_if(state.clusters.begin(), state.clusters.end(), [](const Cluster& c) { return !c.faces.empty(); }));
    size_t triangles = 0;
    for (uint32_t t : state.faceTriangles) triangles += t;
    return triangles - taken;
}

// Each cell's face nearest its centre (of face centroids, weighed by triangles): the next seeds.
std::vector<Seed> centredSeeds(const State& state) {
    std::vector<Seed> seeds;
    for (const Cluster& cell : state.clusters) {
        glm::dvec3 sum(0.0), normal(0.0);
        double weight = 0.0;
        for (uint32_t f : cell.faces) {
            sum += double(state.faceTriangles[f]) * state.geometry.centroids[f], weight += state.faceTriangles[f];
            if (state.usable[f]) normal += state.geometry.areas[f] * state.geometry.normals[f];
        }
        if (cell.faces.empty()) continue;
        const glm::dvec3 centre = weight > 0.0 ? sum / weight : state.geometry.centroids[cell.faces[0]];
        uint32_t nearest = cell.faces[0];
        for (uint32_t f : cell.faces)
            if (glm::length(state.geometry.centroids[f] - centre) < glm::length(state.geometry.centroids[nearest] - centre)) nearest = f;
        const double length = glm::length(normal);
        seeds.push_back({nearest, length > 0.0 ? normal / length : state.geometry.normals[nearest]});
    }
    return seeds;
}

// Seeds where the clusters already made are, the smallest left out: cells then take those
// clusters' places and normals (they culled more, and reached more budgets, than seeds spread
// evenly on CGAL's knot2, femur and mannequin-devil).
std::vector<Seed> largestCentres(State& state, const Partition& made, size_t count) {
    assign(state, made);
    const std::vector<Seed> centres = centredSeeds(state);  // one per cluster, in order
    std::vector<uint32_t> order(centres.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return state.clusters[a].triangles > state.clusters[b].triangles; });
    std::vector<Seed> seeds;
    for (size_t i = 0; i < std::min(count, order.size()); ++i) seeds.push_back(centres[order[i]]);
    return seeds;
}

// One packing at one turn weight (in cell radii): cells grown, moved to their centres while that
// leaves fewer triangles out, what is left grown and reduced, then local search. `state` is the
// packings' own, cleared first (its adjacency is made once for them all).
Partition packWith(State& state, size_t target, std::vector<Seed> seeds, double turnWeight) {
    std::vector<Seed> bestSeeds = seeds;
    size_t fewestLeft = growCells(state, seeds, turnWeight);
    bool lastIsBest = true;
    for (int round = 0; round < kLloydRounds && fewestLeft > 0; ++round) {
        seeds = centredSeeds(state);
        const size_t left = growCells(state, seeds, turnWeight);
        lastIsBest = left < fewestLeft;
        if (lastIsBest) fewestLeft = left, bestSeeds = seeds;
    }
    if (!lastIsBest) growCells(state, bestSeeds, turnWeight);
    for (uint32_t c = 0; c < state.clusters.size(); ++c) state.clusters[c].cap = exactCap(state, c);
    // What no cell took: clusters of its own (within the limits), which the reduction places.
    grow(state, double(state.limits.maxTriangles));
    reduceTo(state, target);
    refine(state);
    return result(state);
}

}  // namespace

Partition packToBudget(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t target, size_t sweeps,
                       const Partition& made, const ProgressCallback& progress) {
    // Each packing may take a second on a large mesh: a cancel is heard between them.
    State state(mesh, faces, limits);
    auto pack = [&](const std::vector<Seed>& seeds, double turnWeight) {
        if (progress && !progress(1.0, "packing clusters")) throw OperationCancelled();
        return packWith(state, target, seeds, turnWeight);
    };
    // A round patch of maxVertices holds about 2 V - 2 - 3.5 sqrt(V) triangles (98 at 64): packing
    // discs gets no further (rings of a thin tube and closed pieces can: CGAL's pipe at 107). On a
    // large mesh, where trying costs several seconds, a budget past that is not tried.
    const double roundPatch = 2.0 * double(limits.maxVertices) - 2.0 - 3.0 * std::sqrt(double(limits.maxVertices));
    if (mesh.faceCount() > kAlwaysTriedBelowFaces && double(triangleCount(mesh)) > double(target) * roundPatch) return made;
    double area = 0.0;
    for (double a : faces.areas) area += a;
    const double cellRadius = std::sqrt(area / double(target) / M_PI);
    // Small meshes try the weights from the largest down, from both starts in turn, and keep the
    // first packing that reaches the budget: whether one does varies from weight to weight on props
    // of many pieces, and the larger weights cull more. Large ones, where a packing costs seconds,
    // bisect for the largest weight that reaches it, from the first start that does.
    Partition best = made;
    if (mesh.faceCount() <= kAlwaysTriedBelowFaces) {
        const std::vector<Seed> starts[2] = {largestCentres(state, made, target), spreadSeeds(state, target)};
        // Weight 0 first: where its packings end far above the budget (more than 5% and one),
        // no weight was seen to reach it, and the other ten packings are not worth their time.
        Partition tightest[2] = {pack(starts[0], 0.0), pack(starts[1], 0.0)};
        const size_t nearest = std::min(tightest[0].clusterCount, tightest[1].clusterCount);
        if (double(nearest) > 1.05 * double(target) + 1.0) return best;
        for (size_t i = std::size(kTurnWeights); i-- > 1;)
            for (const std::vector<Seed>& seeds : starts) {
                Partition packed = pack(seeds, kTurnWeights[i] * cellRadius);
                if (packed.clusterCount <= target) return annealedFurther(state, packed, sweeps);
            }
        for (const Partition& packed : tightest)
            if (packed.clusterCount <= target) return annealedFurther(state, packed, sweeps);
        return best;
    }
    double bestRate = -1.0;
    for (const bool fromMade : {true, false}) {
        const std::vector<Seed> seeds = fromMade ? largestCentres(state, made, target) : spreadSeeds(state, target);
        // Whether the packing at weight i reaches the budget; kept when it culls most so far.
        auto reaches = [&](size_t i) {
            Partition packed = pack(seeds, kTurnWeights[i] * cellRadius);
            if (packed.clusterCount > target) return false;
            const double rate = expectedCullRate(mesh, faces, packed);
            if (rate > bestRate) bestRate = rate, best = std::move(packed);
            return true;
        };
        // Weight 0 packs tightest, mostly: where it misses, the next start is tried.
        if (!reaches(0)) continue;
        for (size_t reached = 0, missed = std::size(kTurnWeights); missed - reached > 1;) {
            const size_t middle = (reached + missed) / 2;
            (reaches(middle) ? reached : missed) = middle;
        }
        break;
    }
    return best.clusterCount <= target ? annealedFurther(state, best, sweeps) : best;
}

}  // namespace conescope::optimizer
