// Whole-cluster merges and dissolving across gaps: how the reduction places separate pieces (each
// at least one cluster after growth) and clusters boxed in by full neighbours.
#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <vector>

#include "NearestCentres.h"
#include "Reduction.h"

namespace conescope::optimizer {

namespace {

// The minimal cap of two clusters' normals together. The cap of both caps' bounding normals is a
// subset's: where it has no cone (or either cluster has none) the merged cluster has none either,
// without the search over every normal that is slowest on sets wider than a hemisphere; else the
// whole set's cap grows from it.
Cap mergedCap(State& state, const Cluster& first, const Cluster& second) {
    if (first.cap.cosRadius > 1.0) return second.cap;
    if (second.cap.cosRadius > 1.0) return first.cap;
    if (!(first.cap.cosRadius > 0.0)) return first.cap;
    if (!(second.cap.cosRadius > 0.0)) return second.cap;
    glm::dvec3 supports[6];
    size_t count = 0;
    for (const Cap* cap : {&first.cap, &second.cap})
        for (uint32_t i = 0; i < cap->supportCount; ++i) supports[count++] = cap->support[i];
    const Cap bound = minimalCap(supports, count);
    if (!(bound.cosRadius > 0.0)) return bound;
    state.gathered.clear();
    for (const Cluster* part : {&first, &second})
        for (uint32_t f : part->faces)
            if (state.usable[f]) state.gathered.push_back(state.geometry.normals[f]);
    return minimalCapFromSubset(state.gathered.data(), state.gathered.size(), bound);
}

// The objective lost by merging two clusters, with the merged cap in *merged; infinity when the
// merged cluster breaks a limit.
double mergeLoss(State& state, uint32_t a, uint32_t b, Cap* merged) {
    const Cluster& first = state.clusters[a];
    const Cluster& second = state.clusters[b];
    if (first.triangles + second.triangles > state.limits.maxTriangles) return kInfinity;
    // The first cluster's vertices stamped, then the second's counted where not stamped yet.
    const uint32_t inFirst = ++state.stamp, seen = ++state.stamp;
    for (uint32_t f : first.faces)
        for (size_t k = 0; k < state.mesh.faceSize(f); ++k) state.vertexStamp[state.mesh.faceBegin(f)[k]] = inFirst;
    uint32_t vertices = first.vertices;
    for (uint32_t f : second.faces)
        for (size_t k = 0; k < state.mesh.faceSize(f); ++k) {
            uint32_t& stamp = state.vertexStamp[state.mesh.faceBegin(f)[k]];
            if (stamp == inFirst || stamp == seen) continue;
            stamp = seen;
            if (++vertices > state.limits.maxVertices) return kInfinity;
        }
    *merged = mergedCap(state, first, second);
    return valueOf(first.triangles, first.cap) + valueOf(second.triangles, second.cap) -
           valueOf(double(first.triangles) + double(second.triangles), *merged);
}

void mergeInto(State& state, uint32_t into, uint32_t from, const Cap& merged) {
    state.members = state.clusters[from].faces;
    for (uint32_t f : state.members) move(state, f, into);
    state.clusters[into].cap = merged;
    state.clusters[from].cap = Cap{};
    --state.liveClusters;
}

constexpr double kSprawlWeight = 0.05;

// The diagonal of the box around the face centroids: the scale distances are weighed against.
double meshDiagonal(const State& state) {
    glm::dvec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
    for (const glm::dvec3& c : state.geometry.centroids) low = glm::min(low, c), high = glm::max(high, c);
    return state.faceCount ? glm::length(high - low) : 0.0;
}

// Triangle-weighted centre of each cluster's face centroids.
glm::dvec3 clusterCentre(const State& state, uint32_t cluster) {
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (uint32_t f : state.clusters[cluster].faces) {
        sum += double(state.faceTriangles[f]) * state.geometry.centroids[f];
        weight += state.faceTriangles[f];
    }
    return weight > 0.0 ? sum / weight : sum;
}

// The live clusters as NearestCentres takes them.
std::vector<bool> liveClusters(const State& state) {
    std::vector<bool> live(state.clusters.size());
    for (uint32_t c = 0; c < state.clusters.size(); ++c) live[c] = !state.clusters[c].faces.empty();
    return live;
}

// A lower bound on the objective lost by merging two clusters, without their normals: the merged
// cap is at least as wide as either cap, and wider than half the widest angle between their
// bounding normals (less a margin for rounding); infinity when the triangles alone break the limit.
double mergeLossBound(const State& state, uint32_t a, uint32_t b) {
    const Cluster& first = state.clusters[a];
    const Cluster& second = state.clusters[b];
    if (first.triangles + second.triangles > state.limits.maxTriangles) return kInfinity;
    const double apart = valueOf(first.triangles, first.cap) + valueOf(second.triangles, second.cap);
    const double triangles = double(first.triangles) + double(second.triangles);
    if (first.cap.cosRadius > 1.0 || second.cap.cosRadius > 1.0)  // no normals on one side: the other's cap
        return apart - valueOf(triangles, first.cap.cosRadius > 1.0 ? second.cap : first.cap) - 1e-9 * triangles;
    double lowestCos = 1.0;  // the widest angle between two bounding normals, one of each cap
    for (uint32_t i = 0; i < first.cap.supportCount; ++i)
        for (uint32_t j = 0; j < second.cap.supportCount; ++j)
            lowestCos = std::min(lowestCos, glm::dot(first.cap.support[i], second.cap.support[j]));
    const double sinHalf = std::sqrt(std::max(0.0, 0.5 * (1.0 - lowestCos)));
    const double sinAtLeast = std::max({sinOf(first.cap), sinOf(second.cap), sinHalf});
    return apart - expectedCulledTriangles(triangles, sinAtLeast) - 1e-9 * triangles;
}

// Whether `targets` have room for the cluster's triangles and for those of its vertices none of
// them uses yet: a dissolve that fails this fails at its last faces, after moving the others.
bool roomFor(State& state, uint32_t cluster, const std::vector<uint32_t>& nearest) {
    const Cluster& leaving = state.clusters[cluster];
    size_t freeTriangles = 0, freeVertices = 0;
    for (uint32_t t : nearest) {
        const Cluster& target = state.clusters[t];
        freeTriangles += std::max<size_t>(state.limits.maxTriangles, target.keptTriangles) - std::min<size_t>(target.triangles, std::max<size_t>(state.limits.maxTriangles, target.keptTriangles));
        freeVertices += std::max<size_t>(state.limits.maxVertices, target.keptVertices) - std::min<size_t>(target.vertices, std::max<size_t>(state.limits.maxVertices, target.keptVertices));
    }
    if (freeTriangles < leaving.triangles) return false;
    std::vector<uint32_t>& targets = state.neighbours;  // sorted, for the look-ups below
    targets.assign(nearest.begin(), nearest.end());
    std::sort(targets.begin(), targets.end());
    size_t unused = 0;
    ++state.stamp;
    for (uint32_t f : leaving.faces)
        for (size_t k = 0; k < state.mesh.faceSize(f); ++k) {
            const uint32_t v = state.mesh.faceBegin(f)[k];
            if (state.vertexStamp[v] == state.stamp) continue;
            state.vertexStamp[v] = state.stamp;
            bool used = false;
            for (const uint32_t* g = state.aroundVertex.begin(v); g != state.aroundVertex.end(v) && !used; ++g)
                used = std::binary_search(targets.begin(), targets.end(), state.clusterOf[*g]);
            unused += !used;
        }
    return freeVertices >= unused;
}

// Empties a cluster into the clusters nearest to it, touching or not, each face where the objective
// loses least: when whole clusters are too full to merge, their faces still fit one by one.
// Undone (false, every cluster and cap as it was) if some face fits nowhere.
bool dissolveAcrossGaps(State& state, uint32_t cluster, NearestCentres& nearby, size_t nearest) {
    std::vector<uint32_t> targets;
    nearby.nearest(cluster, nearest, targets);
    if (!roomFor(state, cluster, targets)) return false;
    state.undo.clear();
    std::vector<std::pair<uint32_t, Cap>> saved{{cluster, state.clusters[cluster].cap}};
    state.members = state.clusters[cluster].faces;
    for (uint32_t face : state.members) {
        const uint32_t to = cheapestHome(state, face, targets.data(), targets.size());
        if (to == kNone) {
            undoMoves(state);
            for (const auto& [c, cap] : saved) state.clusters[c].cap = cap;
            return false;
        }
        if (std::none_of(saved.begin(), saved.end(), [to](const auto& entry) { return entry.first == to; }))
            saved.emplace_back(to, state.clusters[to].cap);
        moveGrowingCap(state, face, to);
    }
    recomputeTouchedCaps(state);
    --state.liveClusters;
    return true;
}

}  // namespace

// Whole-cluster merges, cheapest objective loss first (lazy heap: an entry is stale once either
// cluster changed since it was pushed). Between clusters that share an edge (acrossGaps 0), or
// between each cluster and its acrossGaps nearest: what lets a mesh of many pieces reach any budget.
// A pair enters the heap with a lower bound on its loss (mergeLossBound) and is weighed exactly
// only when that bound comes first: most pairs never do, and the merges and their order are those
// of exact losses.
void mergeCheapest(State& state, size_t count, size_t acrossGaps, Changes& changes) {
    struct MergeCandidate {
        double loss;
        uint32_t a, b, versionA, versionB;
        bool exact;
        bool operator<(const MergeCandidate& other) const {
            if (loss != other.loss) return loss > other.loss;
            if (a != other.a) return a > other.a;
            if (b != other.b) return b > other.b;
            return exact && !other.exact;  // at the same loss a bound is weighed before an exact entry is taken
        }
    };
    std::vector<uint32_t> version(state.clusters.size(), 0);
    std::priority_queue<MergeCandidate> heap;
    std::vector<uint32_t> neighbours;
    std::vector<glm::dvec3> centres(state.clusters.size());
    if (acrossGaps)
        for (uint32_t c = 0; c < state.clusters.size(); ++c) centres[c] = clusterCentre(state, c);
    NearestCentres nearby(acrossGaps ? centres : std::vector<glm::dvec3>(), liveClusters(state));
    const double diagonal = std::max(meshDiagonal(state), 1e-300);
    // Across a gap the farther pair pays for its sprawl (what frustum and occlusion culling see):
    // 5% of its triangles per mesh diagonal apart, so near pieces merge first.
    auto sprawl = [&](uint32_t a, uint32_t b) {
        return acrossGaps ? kSprawlWeight * double(state.clusters[a].triangles + state.clusters[b].triangles) *
                                glm::length(centres[a] - centres[b]) / diagonal
                          : 0.0;
    };
    auto pushPairs = [&](uint32_t a) {
        if (acrossGaps)
            nearby.nearest(a, acrossGaps, neighbours);
        else
            clustersAround(state, a, std::numeric_limits<size_t>::max(), neighbours);
        for (uint32_t b : neighbours) {
            const double bound = mergeLossBound(state, a, b);
            const uint32_t low = std::min(a, b), high = std::max(a, b);
            if (std::isfinite(bound)) heap.push({bound + sprawl(a, b), low, high, version[low], version[high], false});
        }
    };
    for (uint32_t a = 0; a < state.clusters.size(); ++a)
        if (!state.clusters[a].faces.empty()) pushPairs(a);
    size_t done = 0;
    while (done < count && !heap.empty()) {
        MergeCandidate top = heap.top();
        heap.pop();
        if (version[top.a] != top.versionA || version[top.b] != top.versionB) continue;
        if (state.clusters[top.a].faces.empty() || state.clusters[top.b].faces.empty()) continue;
        Cap merged;
        const double loss = mergeLoss(state, top.a, top.b, &merged);
        if (!std::isfinite(loss)) continue;
        if (!top.exact) {  // weighed now: back in the heap at its exact loss
            top.loss = loss + sprawl(top.a, top.b), top.exact = true;
            heap.push(top);
            continue;
        }
        mergeInto(state, top.a, top.b, merged);
        changes.commit({top.a, top.b});
        ++version[top.a];
        ++version[top.b];
        ++done;
        if (acrossGaps) {
            centres[top.a] = clusterCentre(state, top.a);
            nearby.move(top.a, centres[top.a]);
            nearby.remove(top.b);
        }
        pushPairs(top.a);
    }
}
// Dissolving across gaps (into the `nearest` clusters nearest by centre), smallest clusters first,
// while above the target; a dissolve `accept` refuses is put back.
void dissolveSmallestAcrossGaps(State& state, size_t target, size_t nearest, const std::function<bool()>& accept) {
    std::vector<glm::dvec3> centres(state.clusters.size());
    for (uint32_t c = 0; c < state.clusters.size(); ++c) centres[c] = clusterCentre(state, c);
    NearestCentres nearby(centres, liveClusters(state));
    for (uint32_t c : clustersBySize(state)) {
        if (state.liveClusters <= target) break;
        if (!dissolveAcrossGaps(state, c, nearby, nearest)) continue;
        state.members.clear();  // the clusters it touched
        for (const State::Moved& moved : state.undo) state.members.push_back(moved.from), state.members.push_back(state.clusterOf[moved.face]);
        std::sort(state.members.begin(), state.members.end());
        state.members.erase(std::unique(state.members.begin(), state.members.end()), state.members.end());
        if (!accept()) {
            undoMoves(state);
            for (uint32_t m : state.members) state.clusters[m].cap = state.clusters[m].faces.empty() ? Cap{} : exactCap(state, m);
            ++state.liveClusters;
            continue;
        }
        nearby.remove(c);
        // The clusters that took faces move their centres.
        for (uint32_t m : state.members)
            if (!state.clusters[m].faces.empty()) nearby.move(m, clusterCentre(state, m));
    }
}
void overfillTo(State& state, size_t target, const Overfill& allowed) {
    if (state.liveClusters <= target || state.liveClusters - target > allowed.clusters) return;
    const MeshletLimits limits = state.limits;
    auto over = [&](const Cluster& c) { return !c.faces.empty() && (c.triangles > limits.maxTriangles || c.vertices > limits.maxVertices); };
    auto overCount = [&]() { return size_t(std::count_if(state.clusters.begin(), state.clusters.end(), over)); };
    state.limits = allowed.limits;
    for (size_t nearest : kNearestAcrossGaps) {
        // Too many over the limits: that dissolve is put back.
        if (state.liveClusters > target) dissolveSmallestAcrossGaps(state, target, nearest, [&] { return overCount() <= allowed.clusters; });
    }
    state.limits = limits;
    for (Cluster& cluster : state.clusters)
        if (over(cluster))
            cluster.keptVertices = std::max(cluster.keptVertices, cluster.vertices),
            cluster.keptTriangles = std::max(cluster.keptTriangles, cluster.triangles);
}

}  // namespace conescope::optimizer
