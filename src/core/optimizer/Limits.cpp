// Clusters over the limits made as good as moves allow. meshoptimizer's meshlets hold fan
// triangles, and a polygon split across two of them joins one whole: that meshlet can then hold
// more vertices or triangles than the limits. Rejecting such a start sent every polygon mesh to
// growth, which made more clusters than meshoptimizer's count and took several times as long;
// peeling the excess off and reducing again reached the count on a third of the parts at twice
// the time (docs/benchmarks.md).
#include <algorithm>
#include <limits>
#include <vector>

#include "Steps.h"

namespace conescope::optimizer {

namespace {

bool overLimits(const State& state, const Cluster& cluster) {
    return cluster.triangles > state.limits.maxTriangles || cluster.vertices > state.limits.maxVertices;
}

// The move out of an overfull cluster that loses least: a face whose going lowers what is over
// (a vertex only it uses, when vertices are over) to the neighbour where it fits best. Ties go to
// the lowest face, so the result does not depend on the order the faces are stored in.
bool shedOne(State& state, uint32_t cluster) {
    const Cluster& full = state.clusters[cluster];
    const bool verticesOver = full.vertices > state.limits.maxVertices;
    double bestGain = -std::numeric_limits<double>::infinity();
    uint32_t bestFace = kNone, bestTarget = kNone;
    for (uint32_t f : full.faces) {
        uint32_t around[8];
        const size_t count = neighbourClusters(state, f, around);
        if (count == 0 || (verticesOver && ownVertices(state, f) == 0)) continue;
        double gain = 0.0;
        const uint32_t to = cheapestHome(state, f, around, count, &gain);
        if (to != kNone && (gain > bestGain || (gain == bestGain && f < bestFace))) bestGain = gain, bestFace = f, bestTarget = to;
    }
    if (bestFace == kNone) return false;
    move(state, bestFace, bestTarget);
    if (state.usable[bestFace]) state.clusters[bestTarget].cap = growCap(state.clusters[bestTarget].cap, state.geometry.normals[bestFace]);
    state.members.push_back(bestTarget);
    return true;
}

}  // namespace

void shedOverLimits(State& state) {
    state.members.clear();  // the clusters that took faces
    for (uint32_t c = 0; c < state.clusters.size(); ++c) {
        Cluster& cluster = state.clusters[c];
        if (!overLimits(state, cluster)) continue;
        while (overLimits(state, cluster) && cluster.faces.size() > 1 && shedOne(state, c)) state.members.push_back(c);
        if (overLimits(state, cluster)) cluster.keptVertices = cluster.vertices, cluster.keptTriangles = cluster.triangles;
    }
    std::sort(state.members.begin(), state.members.end());
    state.members.erase(std::unique(state.members.begin(), state.members.end()), state.members.end());
    for (uint32_t c : state.members) state.clusters[c].cap = exactCap(state, c);
}

}  // namespace conescope::optimizer
