// Growth: one cluster at a time over edge neighbours, taking the face with the lowest score until
// none fits the limits or the triangle cap (kGrowthCap times the budget's mean size). Clusters end
// where the normals turn, so growth makes more of them than the budget, many small; the
// reduction then places those pieces.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "Steps.h"

namespace conescope::optimizer {

namespace {

// Growth score = cone cost (objective lost per triangle) + these weights times the distance from
// the cluster centre (in expected cluster radii) and the number of vertices the face adds.
// Measured on the CGAL meshes: weighing added vertices against the cone, instead of ranking them
// first as meshoptimizer does, lets clusters follow the normals (about 10% more culled after the
// search); weight 1 keeps the pieces compact enough for the reduction to reach the budget.
constexpr double kDistanceWeight = 0.05;
constexpr double kVertexWeight = 1.0;

// The cluster being grown, and the faces around it. vertexStamp[v] == mark: the cluster uses v
// (cluster ids only increase, so marks never repeat and need no clearing).
struct Growing {
    uint32_t cluster = kNone;
    uint32_t mark = 0;
    glm::dvec3 centroidSum{0.0};
    std::vector<uint32_t> candidates;   // unassigned edge neighbours (some taken since: skipped)
    std::vector<uint32_t> candidateOf;  // per face: the cluster it was last listed for
};

// The radius of a round patch of as many faces as a cluster may hold, at the mean face area: the
// unit of the score's distance term, so the weight means the same on every mesh.
double expectedClusterRadius(const State& state) {
    double totalArea = 0.0;
    for (double area : state.geometry.areas) totalArea += area;
    const double facesPerCluster = std::min<double>(double(state.faceCount), double(state.limits.maxTriangles));
    return std::sqrt(std::max(totalArea / double(std::max<size_t>(state.faceCount, 1)) * facesPerCluster / M_PI, 1e-300));
}

// Seed in the corner the last cluster left: the leftover face with the fewest free neighbours, so
// holes get filled before they close; else the first face not yet taken; kNone when none is left.
uint32_t nextSeed(const State& state, const std::vector<uint32_t>& leftovers, size_t& nextUnassigned) {
    uint32_t seed = kNone, fewest = kNone;
    for (uint32_t f : leftovers) {
        if (state.clusterOf[f] != kNone) continue;
        uint32_t free = 0;
        for (const uint32_t* g = state.acrossEdge.begin(f); g != state.acrossEdge.end(f); ++g) free += state.clusterOf[*g] == kNone;
        if (free < fewest) fewest = free, seed = f;
    }
    if (seed != kNone) return seed;
    while (nextUnassigned < state.faceCount && state.clusterOf[nextUnassigned] != kNone) ++nextUnassigned;
    return nextUnassigned == state.faceCount ? kNone : uint32_t(nextUnassigned);
}

// Vertices of `face` the growing cluster does not use yet (by stamp: no walk around the corners).
uint32_t verticesAdded(const State& state, const Growing& growing, uint32_t face) {
    uint32_t added = 0;
    for (size_t k = 0; k < state.mesh.faceSize(face); ++k)
        added += state.vertexStamp[state.mesh.faceBegin(face)[k]] != growing.mark && !repeatsEarlierVertex(state.mesh, face, k);
    return added;
}

// The face joins the growing cluster: counts, exact cap, and its free edge neighbours become candidates.
void take(State& state, Growing& growing, uint32_t face) {
    Cluster& grown = state.clusters[growing.cluster];
    grown.vertices += verticesAdded(state, growing, face);
    grown.triangles += state.faceTriangles[face];
    state.clusterOf[face] = growing.cluster;
    state.slotOf[face] = uint32_t(grown.faces.size());
    grown.faces.push_back(face);
    for (size_t k = 0; k < state.mesh.faceSize(face); ++k) state.vertexStamp[state.mesh.faceBegin(face)[k]] = growing.mark;
    growing.centroidSum += state.geometry.centroids[face];
    const glm::dvec3& normal = state.geometry.normals[face];
    if (state.usable[face] && !contains(grown.cap, normal)) {
        if (grown.cap.cosRadius > 1.0) {
            grown.cap = capThrough(normal);
        } else if (grown.cap.cosRadius > 0.0) {
            const size_t count = gatherNormals(state, growing.cluster, face);
            grown.cap = minimalCapWith(state.gathered.data(), count, normal);
        }
    }
    for (const uint32_t* g = state.acrossEdge.begin(face); g != state.acrossEdge.end(face); ++g)
        if (state.clusterOf[*g] == kNone && growing.candidateOf[*g] != growing.cluster)
            growing.candidateOf[*g] = growing.cluster, growing.candidates.push_back(*g);
}

// The candidate with the lowest score that fits, or kNone; drops candidates taken by then.
uint32_t bestCandidate(const State& state, Growing& growing, double triangleCap, double expectedRadius) {
    const Cluster& grown = state.clusters[growing.cluster];
    const glm::dvec3 center = growing.centroidSum / double(grown.faces.size());
    const double sinNow = sinOf(grown.cap);
    // The least cone cost any face can have. Adding a normal to a cap of half-angle at most 60
    // degrees (or to no cone) never lowers sinAfterAdding below sinNow, and the cost is then at
    // least sinNow (less a margin for rounding in its division by t). Wider caps and caps without
    // normals can give lower, even negative, costs: no floor.
    const bool costAtLeastSinNow = grown.cap.cosRadius <= 1.0 && !(grown.cap.cosRadius > 0.0 && grown.cap.cosRadius < 0.5);
    const double coneCostFloor = costAtLeastSinNow ? sinNow * (1.0 - 1e-9) : -std::numeric_limits<double>::infinity();
    uint32_t chosen = kNone;
    double bestScore = std::numeric_limits<double>::infinity();
    std::vector<uint32_t>& candidates = growing.candidates;
    for (size_t i = 0; i < candidates.size();) {
        const uint32_t f = candidates[i];
        if (state.clusterOf[f] != kNone) {  // taken since it was listed
            candidates[i] = candidates.back();
            candidates.pop_back();
            continue;
        }
        ++i;
        const uint32_t added = verticesAdded(state, growing, f);
        if (grown.vertices + added > state.limits.maxVertices || grown.triangles + state.faceTriangles[f] > triangleCap) continue;
        // A face whose added vertices alone lose to the best so far is skipped unscored.
        if (kVertexWeight * double(added) + coneCostFloor >= bestScore) continue;
        // Objective lost: the cluster's triangles on the wider cone, and the face itself.
        const double sinAfter =
            state.usable[f] ? sinAfterAdding(grown.cap, glm::dot(state.geometry.normals[f], grown.cap.axis)) : sinNow;
        const double t = double(state.faceTriangles[f]);
        const double coneCost = (double(grown.triangles) * (sinAfter - sinNow) + t * sinAfter) / t;
        const double distance = glm::length(state.geometry.centroids[f] - center) / expectedRadius;
        const double score = coneCost + kDistanceWeight * distance + kVertexWeight * double(added);
        if (score < bestScore) bestScore = score, chosen = f;
    }
    return chosen;
}

}  // namespace

void grow(State& state, double triangleCap) {
    const double expectedRadius = expectedClusterRadius(state);
    Growing growing;
    growing.candidateOf.assign(state.faceCount, kNone);
    std::vector<uint32_t> leftovers;  // the last cluster's candidates: where the next one starts
    size_t nextUnassigned = 0;
    std::fill(state.vertexStamp.begin(), state.vertexStamp.end(), 0);
    for (uint32_t seed; (seed = nextSeed(state, leftovers, nextUnassigned)) != kNone;) {
        state.clusters.emplace_back();
        ++state.liveClusters;
        growing.cluster = uint32_t(state.clusters.size() - 1);
        growing.mark = growing.cluster + 1;
        growing.centroidSum = glm::dvec3(0.0);
        growing.candidates.clear();
        take(state, growing, seed);
        for (uint32_t chosen; (chosen = bestCandidate(state, growing, triangleCap, expectedRadius)) != kNone;)
            take(state, growing, chosen);
        leftovers.swap(growing.candidates);
    }
    std::fill(state.vertexStamp.begin(), state.vertexStamp.end(), 0);  // the other steps stamp with state.stamp
}

}  // namespace conescope::optimizer
