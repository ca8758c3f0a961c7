// Three into two: a cluster no neighbour has room for face by face, and two of its neighbours,
// cut again into two compact halves (the reduction's step where every neighbour is full).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "Steps.h"

namespace conescope::optimizer {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The two faces of state.pool farthest apart, roughly: the one farthest from the pool's centre,
// then the one farthest from that. They seed the two halves of threeIntoTwo.
void farthestPair(const State& state, uint32_t seeds[2]) {
    const std::vector<glm::dvec3>& centroids = state.geometry.centroids;
    glm::dvec3 center(0.0);
    for (uint32_t f : state.pool) center += centroids[f];
    center /= double(state.pool.size());
    seeds[0] = seeds[1] = state.pool[0];
    double farthest = -1.0;
    for (uint32_t f : state.pool)
        if (glm::length(centroids[f] - center) > farthest) farthest = glm::length(centroids[f] - center), seeds[0] = f;
    farthest = -1.0;
    for (uint32_t f : state.pool) {
        const double distance = glm::length(centroids[f] - centroids[seeds[0]]);
        if (distance > farthest) farthest = distance, seeds[1] = f;
    }
}

// Balanced flood of state.pool from the two seeds: each half takes its nearest faces (faceMark =
// 0 or 1) until it holds half of the `total` triangles. False when some face was reached by
// neither half.
bool floodInHalves(State& state, const uint32_t seeds[2], double total, double sideTriangles[2]) {
    struct FloodStep {
        double distance;
        uint32_t face, side;
        bool operator<(const FloodStep& other) const {
            if (distance != other.distance) return distance > other.distance;
            return face > other.face;
        }
    };
    std::priority_queue<FloodStep> heap;
    const uint32_t member = ++state.stamp;
    for (uint32_t f : state.pool) state.faceStamp[f] = member;
    const uint32_t taken = ++state.stamp;
    for (uint32_t side = 0; side < 2; ++side) heap.push({0.0, seeds[side], side});
    sideTriangles[0] = sideTriangles[1] = 0.0;
    size_t assigned = 0;
    while (!heap.empty()) {
        const FloodStep top = heap.top();
        heap.pop();
        if (state.faceStamp[top.face] == taken) continue;
        if (sideTriangles[top.side] + state.faceTriangles[top.face] > 0.5 * total + 2.0 && sideTriangles[1 - top.side] < 0.5 * total)
            continue;  // this half is full; the other may still reach the face
        state.faceStamp[top.face] = taken;
        state.faceMark[top.face] = top.side;
        sideTriangles[top.side] += state.faceTriangles[top.face];
        ++assigned;
        for (const uint32_t* g = state.acrossEdge.begin(top.face); g != state.acrossEdge.end(top.face); ++g)
            if (state.faceStamp[*g] == member)
                heap.push({glm::length(state.geometry.centroids[*g] - state.geometry.centroids[seeds[top.side]]), *g, top.side});
    }
    return assigned == state.pool.size();
}

// The objective of the two halves floodInHalves marked, or -infinity when one breaks a limit.
double valueOfHalves(State& state, const double sideTriangles[2]) {
    double value = 0.0;
    for (uint32_t side = 0; side < 2; ++side) {
        ++state.stamp;
        uint32_t vertices = 0;
        state.gathered.clear();
        for (uint32_t f : state.pool) {
            if (state.faceMark[f] != side) continue;
            if (state.usable[f]) state.gathered.push_back(state.geometry.normals[f]);
            for (size_t k = 0; k < state.mesh.faceSize(f); ++k) {
                const uint32_t v = state.mesh.faceBegin(f)[k];
                if (state.vertexStamp[v] != state.stamp) state.vertexStamp[v] = state.stamp, ++vertices;
            }
        }
        if (vertices > state.limits.maxVertices || sideTriangles[side] > double(state.limits.maxTriangles)) return -kInfinity;
        value += valueOf(sideTriangles[side], minimalCap(state.gathered.data(), state.gathered.size()));
    }
    return value;
}

// Distinct vertices of the faces in state.pool.
size_t poolVertices(State& state) {
    ++state.stamp;
    size_t vertices = 0;
    for (uint32_t f : state.pool)
        for (size_t k = 0; k < state.mesh.faceSize(f); ++k) {
            uint32_t& stamp = state.vertexStamp[state.mesh.faceBegin(f)[k]];
            vertices += stamp != state.stamp;
            stamp = state.stamp;
        }
    return vertices;
}

}  // namespace

// This cluster and two of its neighbours are cut again into two compact halves grown from their
// two farthest faces; the count drops by one when both halves fit. For when no neighbour has
// room to take the cluster face by face. The best pair by objective wins.
bool threeIntoTwo(State& state, uint32_t cluster) {
    std::vector<uint32_t>& neighbours = state.neighbours;
    clustersAround(state, cluster, 64, neighbours);
    double bestValue = -kInfinity;
    uint32_t bestPair[2] = {kNone, kNone};
    for (size_t i = 0; i < neighbours.size(); ++i)
        for (size_t j = i + 1; j < neighbours.size(); ++j) {
            const uint32_t a = neighbours[i], b = neighbours[j];
            const double total = double(state.clusters[cluster].triangles) + state.clusters[a].triangles + state.clusters[b].triangles;
            if (total > 2.0 * double(state.limits.maxTriangles)) continue;
            state.pool = state.clusters[cluster].faces;
            state.pool.insert(state.pool.end(), state.clusters[a].faces.begin(), state.clusters[a].faces.end());
            state.pool.insert(state.pool.end(), state.clusters[b].faces.begin(), state.clusters[b].faces.end());
            if (poolVertices(state) > 2 * size_t(state.limits.maxVertices)) continue;  // no two halves hold them
            uint32_t seeds[2];
            farthestPair(state, seeds);
            double sideTriangles[2];
            if (!floodInHalves(state, seeds, total, sideTriangles)) continue;
            const double value = valueOfHalves(state, sideTriangles);
            if (value <= bestValue) continue;
            bestValue = value;
            state.bestPool = state.pool;
            state.bestHalf.clear();
            for (uint32_t f : state.pool)
                if (state.faceMark[f] == 0) state.bestHalf.push_back(f);
            bestPair[0] = a, bestPair[1] = b;
        }
    if (bestPair[0] == kNone) return false;
    // Half 0 goes to the first neighbour, half 1 to the second; this cluster empties.
    ++state.stamp;
    for (uint32_t f : state.bestHalf) state.faceStamp[f] = state.stamp;
    for (uint32_t f : state.bestPool) {
        const uint32_t want = state.faceStamp[f] == state.stamp ? bestPair[0] : bestPair[1];
        if (state.clusterOf[f] != want) move(state, f, want);
    }
    state.clusters[bestPair[0]].cap = exactCap(state, bestPair[0]);
    state.clusters[bestPair[1]].cap = exactCap(state, bestPair[1]);
    state.clusters[cluster].cap = Cap{};
    --state.liveClusters;
    state.members = {cluster, bestPair[0], bestPair[1]};  // what changed
    return true;
}

}  // namespace conescope::optimizer
