// Reduction to the budget: growth leaves more clusters than the budget, many small. The smallest
// are dissolved face by face into their neighbours; where that gets stuck, whole clusters merge
// (cheapest loss first), faces that save a vertex move to make room, and three clusters are cut
// again into two. Last, clusters merge with near ones they do not touch, so a mesh of many
// separate pieces reaches the budget too.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <queue>
#include <vector>

#include "Reduction.h"

namespace conescope::optimizer {

namespace {

constexpr size_t kFailuresPerRemoval = 4;
constexpr size_t kFailuresAtLeast = 32;


// Whether no cluster within `rings` steps of `cluster` (over shared edges) changed after commit
// `failed`: a dissolve reads two rings (its faces' new homes, and theirs when they make room), a
// three-into-two one.
bool unchangedSince(const State& state, Changes& changes, uint32_t cluster, uint32_t failed, int rings) {
    if (failed == kNone || changes.at[cluster] > failed) return false;
    clustersAround(state, cluster, std::numeric_limits<size_t>::max(), changes.ring);
    for (uint32_t n : changes.ring) {
        if (changes.at[n] > failed) return false;
        if (rings < 2) continue;
        clustersAround(state, n, std::numeric_limits<size_t>::max(), changes.nextRing);
        for (uint32_t m : changes.nextRing)
            if (changes.at[m] > failed) return false;
    }
    return true;
}

// The faces a cluster could pass on to a third cluster (not `from`) while a dissolve of `from`
// runs: border faces with a neighbour that has room, in the cluster's order. They do not depend on
// the face that needs the room, so they are listed once and kept until some face moves (a failing
// dissolve asks the same full neighbours again for every one of its faces).
struct Handover {
    uint32_t face, to, own;  // own: vertices only this face uses in its cluster
    int8_t connected;        // whether its cluster stays in one piece without it: -1 not yet known
};
struct Handovers {
    std::vector<uint32_t> listedAt;               // per cluster: the epoch its list is of
    std::vector<std::vector<Handover>> ofCluster;  // per cluster
    uint32_t epoch = 1;                            // bumped whenever a face moves
    // The caps of the clusters a dissolve grew, as they were before it (savedAt: its epoch at
    // the start), put back when it fails.
    std::vector<uint32_t> savedAt;
    std::vector<std::pair<uint32_t, Cap>> savedCaps;
    uint32_t dissolveEpoch = 0;
    explicit Handovers(size_t clusters) : listedAt(clusters, 0), ofCluster(clusters), savedAt(clusters, 0) {}
};

// A face moves to a cluster during a dissolve: recorded for undoMoves, the cluster's cap grown
// to hold it and its cap before kept.
void handOver(State& state, Handovers& handovers, uint32_t face, uint32_t to) {
    if (handovers.savedAt[to] != handovers.dissolveEpoch)
        handovers.savedAt[to] = handovers.dissolveEpoch, handovers.savedCaps.emplace_back(to, state.clusters[to].cap);
    moveGrowingCap(state, face, to);
    ++handovers.epoch;
}

std::vector<Handover>& handoversOf(State& state, Handovers& handovers, uint32_t cluster, uint32_t from) {
    std::vector<Handover>& list = handovers.ofCluster[cluster];
    if (handovers.listedAt[cluster] == handovers.epoch) return list;
    handovers.listedAt[cluster] = handovers.epoch;
    list.clear();
    for (uint32_t g : state.clusters[cluster].faces) {
        // Only a border face has somewhere to go; most members are inside, so ask that first.
        uint32_t others[8];
        const size_t otherCount = neighbourClusters(state, g, others);
        for (size_t i = 0; i < otherCount; ++i)
            if (others[i] != from && fits(state, g, others[i])) {
                list.push_back({g, others[i], ownVertices(state, g), -1});
                break;
            }
    }
    return list;
}

// Frees room for `face` in `cluster` by passing one of the cluster's border faces on to a third
// cluster (not `from`, where `face` comes from). Cheap tests first (would `face` fit without it),
// the connectivity walk last. The move is recorded in state.undo. (Chains of two such hand-overs
// reached tight budgets slightly more often at twice the cost: not worth it.)
bool makeRoom(State& state, uint32_t face, uint32_t cluster, uint32_t from, Handovers& handovers) {
    const Cluster& full = state.clusters[cluster];
    // Who in the cluster uses each corner of `face` (none, one face, or more), so that what
    // arrives without g is a lookup per corner rather than a walk around it for every g.
    state.corners.clear();
    for (size_t k = 0; k < state.mesh.faceSize(face); ++k) {
        if (repeatsEarlierVertex(state.mesh, face, k)) continue;
        const uint32_t v = state.mesh.faceBegin(face)[k];
        State::Corner corner;
        for (const uint32_t* g = state.aroundVertex.begin(v); g != state.aroundVertex.end(v) && corner.users < 2; ++g)
            if (state.clusterOf[*g] == cluster) corner.soleUser = *g, ++corner.users;
        state.corners.push_back(corner);
    }
    for (Handover& hand : handoversOf(state, handovers, cluster, from)) {
        const uint32_t g = hand.face;
        if (full.triangles - state.faceTriangles[g] + state.faceTriangles[face] > state.limits.maxTriangles) continue;
        // Vertices once g is gone: g's own ones leave, face's ones not used by the rest arrive.
        uint32_t arriving = 0;
        for (const State::Corner& corner : state.corners) arriving += corner.users == 0 || (corner.users == 1 && corner.soleUser == g);
        if (full.vertices - hand.own + arriving > state.limits.maxVertices) continue;
        bool touches = false;  // `face` must still border the cluster without g
        for (const uint32_t* k = state.acrossEdge.begin(face); k != state.acrossEdge.end(face); ++k)
            touches |= *k != g && state.clusterOf[*k] == cluster;
        if (!touches) continue;
        if (hand.connected < 0) hand.connected = staysConnectedWithout(state, g);
        if (!hand.connected) continue;
        handOver(state, handovers, g, hand.to);
        return true;
    }
    return false;
}

}  // namespace

// Live clusters, smallest first (ties by id): the order in which dissolving is tried.
std::vector<uint32_t> clustersBySize(const State& state) {
    std::vector<uint32_t> order;
    for (uint32_t c = 0; c < state.clusters.size(); ++c)
        if (!state.clusters[c].faces.empty()) order.push_back(c);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return state.clusters[a].triangles < state.clusters[b].triangles; });
    return order;
}

// The face moves on (recorded in state.undo) and the cluster it joins gets a cap that holds it
// (grown, not exact: cheap, and recomputed once the step is done).
void moveGrowingCap(State& state, uint32_t face, uint32_t to) {
    moveRecorded(state, face, to);
    if (state.usable[face]) state.clusters[to].cap = growCap(state.clusters[to].cap, state.geometry.normals[face]);
}

// Exact caps for every cluster the moves in state.undo touched.
void recomputeTouchedCaps(State& state) {
    state.members.clear();
    for (const State::Moved& moved : state.undo) state.members.push_back(moved.from), state.members.push_back(state.clusterOf[moved.face]);
    std::sort(state.members.begin(), state.members.end());
    state.members.erase(std::unique(state.members.begin(), state.members.end()), state.members.end());
    for (uint32_t c : state.members) state.clusters[c].cap = state.clusters[c].faces.empty() ? Cap{} : exactCap(state, c);
}


uint32_t cheapestHome(const State& state, uint32_t face, const uint32_t* targets, size_t targetCount, double* gainOut) {
    // Every target's gain first, then whether the face fits, best gain first (ties: the earlier
    // target): the walk around the face's corners that `fits` takes costs more than a gain.
    constexpr size_t kMostTargets = 128;
    std::pair<double, uint32_t> byGain[kMostTargets];
    size_t count = 0;
    for (size_t k = 0; k < std::min(targetCount, kMostTargets); ++k) {
        const Cluster& target = state.clusters[targets[k]];
        if (target.triangles + state.faceTriangles[face] > std::max<size_t>(state.limits.maxTriangles, target.keptTriangles)) continue;
        const double sinAfter = state.usable[face]
                                    ? sinAfterAdding(target.cap, glm::dot(state.geometry.normals[face], target.cap.axis))
                                    : sinOf(target.cap);
        const double gain = expectedCulledTriangles(double(target.triangles) + state.faceTriangles[face], sinAfter) -
                            valueOf(target.triangles, target.cap);
        byGain[count++] = {-gain, uint32_t(k)};
    }
    std::sort(byGain, byGain + count);
    for (size_t i = 0; i < count; ++i)
        if (fits(state, face, targets[byGain[i].second])) {
            if (gainOut) *gainOut = -byGain[i].first;
            return targets[byGain[i].second];
        }
    if (gainOut) *gainOut = -kInfinity;
    return kNone;
}

namespace {

// Empties a cluster by handing each of its faces, from its border inwards, to the neighbouring
// cluster where the objective loses least; a full neighbour first passes one of its own border
// faces on. Caps are grown approximately on the way and recomputed at the end. Undone (returns
// false) if some face finds no room.
bool dissolve(State& state, uint32_t cluster, Handovers& handovers) {
    if (state.clusters[cluster].faces.empty()) return false;
    ++handovers.epoch;
    handovers.dissolveEpoch = handovers.epoch;
    handovers.savedCaps.clear();
    state.undo.clear();
    std::vector<uint32_t>& queue = state.queue;
    uint32_t queued = 0;  // faceStamp of faces in the queue (other checks may overwrite some: harmless)
    auto refill = [&]() {
        queued = ++state.stamp;
        queue.clear();
        for (uint32_t f : state.clusters[cluster].faces)
            for (const uint32_t* g = state.acrossEdge.begin(f); g != state.acrossEdge.end(f); ++g)
                if (state.clusterOf[*g] != cluster && state.faceStamp[f] != queued) state.faceStamp[f] = queued, queue.push_back(f);
    };
    refill();
    for (int round = 0; round < 4 && !state.clusters[cluster].faces.empty(); ++round) {
        const bool pushing = round >= 2;  // plain moves everywhere first, then make room
        for (size_t i = 0; i < queue.size(); ++i) {
            const uint32_t face = queue[i];
            if (state.clusterOf[face] != cluster) continue;
            uint32_t targets[8];
            const size_t targetCount = neighbourClusters(state, face, targets);
            uint32_t bestTarget = cheapestHome(state, face, targets, targetCount);
            for (size_t k = 0; k < targetCount && bestTarget == kNone && pushing; ++k)
                if (makeRoom(state, face, targets[k], cluster, handovers)) bestTarget = targets[k];
            if (bestTarget == kNone && round == 3) break;  // last round: one stuck face fails it all
            if (bestTarget == kNone) continue;
            handOver(state, handovers, face, bestTarget);
            for (const uint32_t* g = state.acrossEdge.begin(face); g != state.acrossEdge.end(face); ++g)
                if (state.clusterOf[*g] == cluster && state.faceStamp[*g] != queued) state.faceStamp[*g] = queued, queue.push_back(*g);
        }
        refill();
    }
    if (!state.clusters[cluster].faces.empty()) {  // every face back in its place, every cap as it was
        undoMoves(state);
        for (const auto& [c, cap] : handovers.savedCaps) state.clusters[c].cap = cap;
        return false;
    }
    recomputeTouchedCaps(state);  // lists the touched clusters in state.members
    --state.liveClusters;
    return true;
}

// Moves that save a vertex: a border face whose corners the neighbour already uses, and one of
// which only it uses in its own cluster. Full clusters get room that way for the reduction.
size_t compact(State& state, Changes& changes) {
    size_t moves = 0;
    const uint32_t committedBefore = changes.commits;
    for (uint32_t face = 0; face < state.faceCount; ++face) {
        const uint32_t from = state.clusterOf[face];
        if (state.clusters[from].faces.size() <= 1 || ownVertices(state, face) == 0) continue;
        uint32_t targets[8];
        const size_t targetCount = neighbourClusters(state, face, targets);
        for (size_t i = 0; i < targetCount; ++i) {
            const uint32_t to = targets[i];
            if (newVertices(state, face, to) != 0 || state.clusters[to].triangles + state.faceTriangles[face] > state.limits.maxTriangles)
                continue;
            if (!staysConnectedWithout(state, face)) break;
            move(state, face, to);
            changes.commit({from, to});
            ++moves;
            break;
        }
    }
    for (uint32_t c = 0; c < state.clusters.size(); ++c)  // exact caps where faces moved
        if (changes.at[c] > committedBefore && !state.clusters[c].faces.empty()) state.clusters[c].cap = exactCap(state, c);
    return moves;
}

// Dissolving, smallest clusters first, while above the target. A failed try costs as much as a
// success and is undone; where most fail (full neighbours all round), the pass stops after a few
// times as many failures as there are clusters still to remove, and the steps after it (three into
// two, merges) take over.
void dissolveSmallest(State& state, size_t target, Changes& changes, Handovers& handovers) {
    if (state.liveClusters <= target) return;
    size_t failuresLeft = kFailuresPerRemoval * (state.liveClusters - target) + kFailuresAtLeast;
    for (uint32_t c : clustersBySize(state)) {
        if (state.liveClusters <= target) return;
        // A failure known in advance counts as one, so the pass ends where it did before.
        const bool emptied = !unchangedSince(state, changes, c, changes.dissolveFailed[c], 2) && dissolve(state, c, handovers);
        if (emptied) changes.commit(state.members);  // the clusters recomputeTouchedCaps listed
        else changes.dissolveFailed[c] = changes.commits;
        if (!emptied && --failuresLeft == 0) return;
    }
}

// Three into two for each cluster, smallest first, while above the target.
void splitThreeIntoTwo(State& state, size_t target, Changes& changes) {
    for (uint32_t c : clustersBySize(state)) {
        if (state.liveClusters <= target) break;
        if (state.clusters[c].faces.empty() || unchangedSince(state, changes, c, changes.splitFailed[c], 1)) continue;
        if (threeIntoTwo(state, c)) changes.commit(state.members);
        else changes.splitFailed[c] = changes.commits;
    }
}

}  // namespace

void reduceTo(State& state, size_t target) {
    Changes changes(state.clusters.size());
    Handovers handovers(state.clusters.size());
    dissolveSmallest(state, target, changes, handovers);
    if (state.liveClusters > target) mergeCheapest(state, state.liveClusters - target, 0, changes);
    // Where every neighbour is full, three clusters become two, which frees room for more dissolving.
    for (int round = 0; round < 4 && state.liveClusters > target; ++round) {
        const size_t before = state.liveClusters;
        compact(state, changes);
        dissolveSmallest(state, target, changes, handovers);
        splitThreeIntoTwo(state, target, changes);
        dissolveSmallest(state, target, changes, handovers);
        if (state.liveClusters == before) break;
    }
    // Still above: separate pieces (each at least one cluster) or clusters boxed in by full
    // neighbours. The nearest ones merge across the gap, cheapest first.
    for (size_t nearest : kNearestAcrossGaps) {
        if (state.liveClusters > target) mergeCheapest(state, state.liveClusters - target, nearest, changes);
        if (state.liveClusters <= target) break;
        // No whole pair fits: the smallest clusters go face by face into their nearest ones.
        dissolveSmallestAcrossGaps(state, target, nearest, [] { return true; });
    }
}

}  // namespace conescope::optimizer
