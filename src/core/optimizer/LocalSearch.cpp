// Local search on the objective: a border face moves to the neighbouring cluster where the
// objective gains, first greedily near the last moves (refine), then in annealing sweeps that
// also take a shrinking random loss (anneal), to cross ridges single greedy moves cannot.
#include <cmath>
#include <vector>

#include "Steps.h"

namespace conescope::optimizer {

namespace {

// Annealing temperatures, in triangles of objective: a sweep takes a move whose gain exceeds
// -T * Exp(1). Hot enough to cross the ridges single moves cannot, cooling to plain descent.
constexpr double kStartTemperature = 1.0;
constexpr double kEndTemperature = 0.15;
// Greedy local search stops after this many passes over the faces near the last moves.
constexpr size_t kRefinementPasses = 30;
// What a greedy move must gain: more than rounding, so no pair of moves can undo each other forever.
constexpr double kGreedyThreshold = 1e-9;

// Best move of `face` to a neighbouring cluster if its gain exceeds `threshold`; made when the
// face's cluster stays in one piece. Exact caps for both clusters, but only after cheap bounds
// from the caps' bounding points leave the move a chance.
bool tryMove(State& state, uint32_t face, double threshold) {
    const uint32_t from = state.clusterOf[face];
    const Cluster& source = state.clusters[from];
    if (source.faces.size() <= 1) return false;
    uint32_t targets[8];
    const size_t targetCount = neighbourClusters(state, face, targets);
    if (targetCount == 0) return false;
    const glm::dvec3& normal = state.geometry.normals[face];
    const double t = double(state.faceTriangles[face]);
    const double valueFrom = valueOf(source.triangles, source.cap);
    const bool binds = bindsCap(state, face);
    // Upper bound on what the source can gain: its cap shrinks at most to its other bounding points.
    const double boundFrom = valueOf(double(source.triangles) - t, binds ? supportCapRemoving(source.cap, normal) : source.cap);
    Cap capFrom{};
    bool capFromKnown = !binds;
    if (!binds) capFrom = source.cap;
    double bestGain = threshold;
    uint32_t bestTarget = kNone;
    Cap bestCap{};
    for (size_t i = 0; i < targetCount; ++i) {
        const uint32_t to = targets[i];
        const Cluster& target = state.clusters[to];
        if (!fits(state, face, to)) continue;
        const double valueTo = valueOf(target.triangles, target.cap);
        const bool inside = !state.usable[face] || contains(target.cap, normal);
        // Cheap bound first: the target's cap grows at least to hold its bounding points and the face.
        if (target.cap.cosRadius > 1.0) {
            // no normals yet: nothing cheap to bound with
        } else if (!inside) {
            const double bound = boundFrom + valueOf(double(target.triangles) + t, supportCapAdding(target.cap, normal)) - valueFrom - valueTo;
            if (bound <= bestGain) continue;
        } else if (boundFrom + valueOf(double(target.triangles) + t, target.cap) - valueFrom - valueTo <= bestGain) {
            continue;
        }
        if (!capFromKnown) capFrom = capRemoving(state, face), capFromKnown = true;
        const Cap capTo = capAdding(state, to, face);
        const double gain = valueOf(double(source.triangles) - t, capFrom) + valueOf(double(target.triangles) + t, capTo) - valueFrom - valueTo;
        if (gain > bestGain) bestGain = gain, bestTarget = to, bestCap = capTo;
    }
    if (bestTarget == kNone || !staysConnectedWithout(state, face)) return false;
    move(state, face, bestTarget);
    state.clusters[from].cap = capFrom;
    state.clusters[bestTarget].cap = bestCap;
    return true;
}

// Whether a face has an edge neighbour in another cluster: only such faces can move.
bool onBorder(const State& state, uint32_t face) {
    const uint32_t own = state.clusterOf[face];
    bool border = false;
    for (const uint32_t* g = state.acrossEdge.begin(face); g != state.acrossEdge.end(face) && !border; ++g)
        border = state.clusterOf[*g] != own;
    return border;
}

// Faces queued for another look once `face` has moved: its neighbourhood changed, so its edge
// neighbours (and the face itself) may now have a better place.
void queueAround(const State& state, uint32_t face, std::vector<uint8_t>& queued, std::vector<uint32_t>& work) {
    for (const uint32_t* g = state.acrossEdge.begin(face); g != state.acrossEdge.end(face); ++g)
        if (!queued[*g]) queued[*g] = 1, work.push_back(*g);
    if (!queued[face]) queued[face] = 1, work.push_back(face);
}

// Greedy passes over `work` and, pass by pass, over the faces around the last moves.
void refineFrom(State& state, std::vector<uint32_t> work, std::vector<uint8_t>& queued) {
    std::vector<uint32_t> next;
    for (size_t pass = 0; pass < kRefinementPasses && !work.empty(); ++pass) {
        next.clear();
        for (uint32_t f : work) queued[f] = 0;
        for (uint32_t f : work)
            if (tryMove(state, f, kGreedyThreshold)) queueAround(state, f, queued, next);
        work.swap(next);
    }
}

}  // namespace

void refine(State& state) {
    std::vector<uint32_t> work;
    std::vector<uint8_t> queued(state.faceCount, 0);
    for (uint32_t f = 0; f < state.faceCount; ++f) {
        uint32_t around[8];
        if (neighbourClusters(state, f, around) > 0) work.push_back(f), queued[f] = 1;
    }
    refineFrom(state, std::move(work), queued);
}

// A move changes the caps and counts of the clusters it leaves and joins, and so what every border
// face of those may gain. One cold sweep touches a part of the clusters; a full refinement after it
// spent most of its time where nothing had changed.
void refineAround(State& state, const std::vector<uint32_t>& moved) {
    std::vector<uint32_t> work;
    std::vector<uint8_t> queued(state.faceCount, 0), touched(state.clusters.size(), 0);
    for (uint32_t f : moved) {
        touched[state.clusterOf[f]] = 1;
        for (const uint32_t* g = state.acrossEdge.begin(f); g != state.acrossEdge.end(f); ++g) touched[state.clusterOf[*g]] = 1;
    }
    for (uint32_t f = 0; f < state.faceCount; ++f)
        if (touched[state.clusterOf[f]] && onBorder(state, f)) work.push_back(f), queued[f] = 1;
    refineFrom(state, std::move(work), queued);
}

// Annealing in sweeps: every border face in turn is offered its best move, taken when the gain
// beats -T * Exp(1), with T falling geometrically from sweep to sweep. It crosses the ridges
// where a group of faces must move together but each single move loses. Walking faces in order
// keeps memory access local; the generator is fixed, so the result is deterministic.
std::vector<uint32_t> anneal(State& state, size_t sweeps) {
    std::vector<uint32_t> moved;
    uint64_t random = 0x853C49E6748FEA9Bull;
    auto uniform = [&]() {
        random = random * 6364136223846793005ull + 1442695040888963407ull;
        return (double(random >> 11) + 0.5) / 9007199254740992.0;  // (0, 1)
    };
    for (size_t sweep = 0; sweep < sweeps; ++sweep) {
        const double progress = sweeps > 1 ? double(sweep) / double(sweeps - 1) : 1.0;
        const double temperature = kStartTemperature * std::pow(kEndTemperature / kStartTemperature, progress);
        for (uint32_t face = 0; face < state.faceCount; ++face)
            if (onBorder(state, face) && tryMove(state, face, temperature * std::log(uniform()))) moved.push_back(face);
    }
    return moved;
}

Partition annealedFurther(State& state, const Partition& start, size_t sweeps) {
    if (sweeps == 0) return start;
    assign(state, start);
    refineAround(state, anneal(state, sweeps));
    return result(state);
}

}  // namespace conescope::optimizer
