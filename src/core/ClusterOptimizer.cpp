#include "ClusterOptimizer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

#include "Adjacency.h"
#include "Cones.h"
#include "Parallel.h"
#include "SphericalCaps.h"

namespace conescope {

namespace {
constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// Growth score = cone cost (objective lost per triangle) + these weights times the distance from
// the cluster centre (in expected cluster radii) and the number of vertices the face adds.
// Measured on the CGAL meshes: weighing added vertices against the cone, instead of ranking them
// first as meshoptimizer does, lets clusters follow the normals (about 10% more culled after the
// search); weight 1 keeps the pieces compact enough for the reduction to reach the budget.
constexpr double kDistanceWeight = 0.05;
constexpr double kVertexWeight = 1.0;
// The default budget fills clusters to this fraction of what a round patch holds: at 64/124 that
// is 84 triangles, about what meshoptimizer's builder reaches at cone weight 1 (84-87 on the CGAL
// meshes) and a budget the reduction reaches on all of them.
constexpr double kDefaultFill = 0.68;
// Growth stops a cluster at this multiple of the budget's mean size (or the triangle limit). At
// exactly the mean, every cluster ends up the same size and the reduction can get stuck a few
// clusters above the budget on regular meshes; the margin lets some grow larger instead.
constexpr double kGrowthCap = 1.25;
// Annealing temperatures, in triangles of objective: a sweep takes a move whose gain exceeds
// -T * Exp(1). Hot enough to cross the ridges single moves cannot, cooling to plain descent.
constexpr double kStartTemperature = 1.0;
constexpr double kEndTemperature = 0.15;
// Sweeps over all faces: the most a small mesh gets, and the face visits the budget allows below
// that (each visit costs well under a microsecond). Fewer than kMinSweeps cool too fast to pay:
// measured on armadillo subdivided to 0.8M and 3.3M triangles, 6 and 4 sweeps added 0.7% and
// 0.4% to the objective for 1.4 s and 2.9 s, half the whole preparation; such meshes get none.
constexpr size_t kMaxSweeps = 100;
constexpr size_t kMinSweeps = 8;
constexpr double kSweepFaceVisits = 5.0e6;
// Larger meshes are cut into parts of at most this many faces, optimised independently (and at
// once on several cores): each part's data stays in cache, and one run of this size takes about a
// second. A part keeps at least kMinPartClusters of the budget.
constexpr size_t kPartFaces = size_t(1) << 17;
constexpr size_t kMinPartClusters = 16;
// Greedy local search stops after this many passes over the faces near the last moves.
constexpr size_t kRefinementPasses = 30;

// The objective's share of one cluster.
double valueOf(double triangles, const Cap& cap) { return expectedCulledTriangles(triangles, sinOf(cap)); }

// ---------------------------------------------------------------------------------------------
// The clustering being optimised.

struct Cluster {
    std::vector<uint32_t> faces;
    uint32_t vertices = 0;
    uint32_t triangles = 0;
    Cap cap;
};

class Optimizer {
public:
    Optimizer(const Mesh& mesh, const FaceGeometry& geometry, const MeshletLimits& limits);

    void grow(double triangleCap);
    void clear();
    void reduceTo(size_t target);
    void refine();
    void anneal(size_t sweeps);
    size_t clusterCount() const { return liveClusters_; }
    Partition result() const;

private:
    // --- membership -------------------------------------------------------------------------
    bool clusterUsesVertex(uint32_t cluster, uint32_t vertex, uint32_t exceptFace = kNone) const {
        for (const uint32_t* g = aroundVertex_.begin(vertex); g != aroundVertex_.end(vertex); ++g)
            if (*g != exceptFace && clusterOf_[*g] == cluster) return true;
        return false;
    }
    bool repeatsEarlierVertex(uint32_t face, size_t k) const {
        const uint32_t* vertices = mesh_.faceBegin(face);
        for (size_t j = 0; j < k; ++j)
            if (vertices[j] == vertices[k]) return true;
        return false;
    }
    // Vertices of `face` the cluster does not use yet.
    uint32_t newVertices(uint32_t face, uint32_t cluster) const {
        uint32_t added = 0;
        for (size_t k = 0; k < mesh_.faceSize(face); ++k)
            added += !repeatsEarlierVertex(face, k) && !clusterUsesVertex(cluster, mesh_.faceBegin(face)[k]);
        return added;
    }
    // Vertices only `face` uses in its cluster.
    uint32_t ownVertices(uint32_t face) const {
        uint32_t own = 0;
        for (size_t k = 0; k < mesh_.faceSize(face); ++k)
            own += !repeatsEarlierVertex(face, k) && !clusterUsesVertex(clusterOf_[face], mesh_.faceBegin(face)[k], face);
        return own;
    }
    bool fits(uint32_t face, uint32_t cluster) const {
        const Cluster& target = clusters_[cluster];
        return target.triangles + triangles_[face] <= limits_.maxTriangles &&
               target.vertices + newVertices(face, cluster) <= limits_.maxVertices;
    }
    void attach(uint32_t face, uint32_t cluster) {
        Cluster& target = clusters_[cluster];
        target.vertices += newVertices(face, cluster);
        target.triangles += triangles_[face];
        clusterOf_[face] = cluster;
        slotOf_[face] = uint32_t(target.faces.size());
        target.faces.push_back(face);
    }
    void detach(uint32_t face) {
        Cluster& source = clusters_[clusterOf_[face]];
        source.vertices -= ownVertices(face);
        source.triangles -= triangles_[face];
        const uint32_t slot = slotOf_[face];
        source.faces[slot] = source.faces.back();
        slotOf_[source.faces[slot]] = slot;
        source.faces.pop_back();
        clusterOf_[face] = kNone;
    }
    void move(uint32_t face, uint32_t to) {
        detach(face);
        attach(face, to);
    }
    // Different clusters across the edges of `face`, at most 8.
    size_t neighbourClusters(uint32_t face, uint32_t* out) const {
        size_t count = 0;
        const uint32_t own = clusterOf_[face];
        for (const uint32_t* g = acrossEdge_.begin(face); g != acrossEdge_.end(face); ++g) {
            const uint32_t c = clusterOf_[*g];
            if (c != own && c != kNone && count < 8 && std::find(out, out + count, c) == out + count) out[count++] = c;
        }
        return count;
    }

    // --- cones ------------------------------------------------------------------------------
    size_t gatherNormals(uint32_t cluster, uint32_t exceptFace) {
        scratch_.clear();
        for (uint32_t f : clusters_[cluster].faces)
            if (f != exceptFace && usable_[f]) scratch_.push_back(geometry_.normals[f]);
        return scratch_.size();
    }
    // gatherNormals fills scratch_ first: its data() is only valid after that call.
    Cap exactCap(uint32_t cluster) {
        const size_t count = gatherNormals(cluster, kNone);
        return minimalCap(scratch_.data(), count);
    }
    // The cap once `face` joins `cluster`.
    Cap capAdding(uint32_t cluster, uint32_t face) {
        const Cap& current = clusters_[cluster].cap;
        if (!usable_[face] || contains(current, geometry_.normals[face])) return current;
        if (current.cosRadius > 1.0) return capThrough(geometry_.normals[face]);
        if (!(current.cosRadius > 0.0)) return current;  // already no cone
        const size_t count = gatherNormals(cluster, kNone);
        return minimalCapWith(scratch_.data(), count, geometry_.normals[face]);
    }
    // Whether removing `face` can change its cluster's cap (its normal bounds the cap).
    bool bindsCap(uint32_t face) const {
        const Cap& current = clusters_[clusterOf_[face]].cap;
        return usable_[face] && !(current.cosRadius > 0.0 && glm::dot(geometry_.normals[face], current.axis) > current.cosRadius + 1e-9);
    }
    // The cap once `face` leaves its cluster.
    Cap capRemoving(uint32_t face) {
        const uint32_t cluster = clusterOf_[face];
        if (!bindsCap(face)) return clusters_[cluster].cap;
        const size_t count = gatherNormals(cluster, face);
        return minimalCap(scratch_.data(), count);
    }

    // --- connectivity -----------------------------------------------------------------------
    // True when the cluster of `face` stays edge-connected without it.
    bool staysConnectedWithout(uint32_t face);

    // --- moves ------------------------------------------------------------------------------
    // Best move of `face` to a neighbouring cluster if its gain exceeds `threshold`.
    bool tryMove(uint32_t face, double threshold);
    bool dissolve(uint32_t cluster);
    bool makeRoom(uint32_t face, uint32_t cluster, uint32_t from);
    bool threeIntoTwo(uint32_t cluster);
    size_t compact();
    void mergeCheapest(size_t count);
    double mergeLoss(uint32_t a, uint32_t b, Cap* merged);
    void mergeInto(uint32_t into, uint32_t from, const Cap& merged);
    std::vector<uint32_t> clustersBySize() const;

    const Mesh& mesh_;
    const FaceGeometry& geometry_;
    MeshletLimits limits_;
    size_t faceCount_;
    Rows aroundVertex_, acrossEdge_;
    std::vector<uint32_t> clusterOf_, slotOf_, triangles_;
    std::vector<uint8_t> usable_;
    std::vector<Cluster> clusters_;
    size_t liveClusters_ = 0;
    // Scratch, reused to keep the inner loops free of allocations.
    std::vector<uint32_t> faceStamp_, vertexStamp_, faceMark_;
    uint32_t stamp_ = 0;
    std::vector<glm::dvec3> scratch_;
    std::vector<uint32_t> walk_, queue_, members_, pool_, bestPool_, bestHalf_;
    std::vector<std::pair<uint32_t, uint32_t>> undo_;
    struct Corner {
        uint32_t users = 0;  // 0, 1 or 2 (two or more)
        uint32_t soleUser = kNone;
    };
    std::vector<Corner> corners_;
};

Optimizer::Optimizer(const Mesh& mesh, const FaceGeometry& geometry, const MeshletLimits& limits)
    : mesh_(mesh), geometry_(geometry), limits_(limits), faceCount_(mesh.faceCount()) {
    aroundVertex_ = facesAroundVertices(mesh);
    acrossEdge_ = facesAcrossEdges(mesh, aroundVertex_);
    clusterOf_.assign(faceCount_, kNone);
    slotOf_.assign(faceCount_, 0);
    faceStamp_.assign(faceCount_, 0);
    faceMark_.assign(faceCount_, 0);
    vertexStamp_.assign(mesh.positions.size(), 0);
    triangles_.resize(faceCount_);
    usable_.resize(faceCount_);
    for (size_t f = 0; f < faceCount_; ++f) {
        triangles_[f] = uint32_t(mesh.faceSize(f) - 2);
        usable_[f] = !geometry.degenerate[f];
    }
}

bool Optimizer::staysConnectedWithout(uint32_t face) {
    const uint32_t cluster = clusterOf_[face];
    uint32_t first = kNone, neighboursInCluster = 0;
    for (const uint32_t* g = acrossEdge_.begin(face); g != acrossEdge_.end(face); ++g)
        if (clusterOf_[*g] == cluster) {
            ++neighboursInCluster;
            if (first == kNone) first = *g;
        }
    if (neighboursInCluster <= 1) return true;
    // Usually the cluster's faces around the corners of `face` already join its edge neighbours.
    uint32_t ring[48];
    size_t ringCount = 0;
    for (size_t k = 0; k < mesh_.faceSize(face); ++k) {
        const uint32_t v = mesh_.faceBegin(face)[k];
        for (const uint32_t* g = aroundVertex_.begin(v); g != aroundVertex_.end(v); ++g)
            if (*g != face && clusterOf_[*g] == cluster && ringCount < 48 && std::find(ring, ring + ringCount, *g) == ring + ringCount)
                ring[ringCount++] = *g;
    }
    if (ringCount < 48) {
        bool reachedRing[48] = {};
        size_t stack[48], top = 0, reachedNeighbours = 1;
        const size_t start = size_t(std::find(ring, ring + ringCount, first) - ring);
        reachedRing[start] = true;
        stack[top++] = start;
        while (top > 0) {
            const uint32_t f = ring[stack[--top]];
            for (const uint32_t* g = acrossEdge_.begin(f); g != acrossEdge_.end(f); ++g) {
                const size_t i = size_t(std::find(ring, ring + ringCount, *g) - ring);
                if (i == ringCount || reachedRing[i]) continue;
                reachedRing[i] = true;
                stack[top++] = i;
                for (const uint32_t* h = acrossEdge_.begin(face); h != acrossEdge_.end(face); ++h) reachedNeighbours += *h == *g;
            }
        }
        if (reachedNeighbours == neighboursInCluster) return true;
    }
    // Walk the cluster from one neighbour without crossing `face`; every face must be reached.
    ++stamp_;
    faceStamp_[face] = stamp_;
    faceStamp_[first] = stamp_;
    walk_.assign(1, first);
    size_t reached = 1;
    while (!walk_.empty()) {
        const uint32_t f = walk_.back();
        walk_.pop_back();
        for (const uint32_t* g = acrossEdge_.begin(f); g != acrossEdge_.end(f); ++g)
            if (clusterOf_[*g] == cluster && faceStamp_[*g] != stamp_) {
                faceStamp_[*g] = stamp_;
                walk_.push_back(*g);
                ++reached;
            }
    }
    return reached + 1 == clusters_[cluster].faces.size();
}

// ---------------------------------------------------------------------------------------------
// Growth: one cluster at a time over edge neighbours, taking the face with the lowest score until
// none fits the limits or the triangle cap (kGrowthCap times the budget's mean size). Clusters end
// where the normals turn, so growth makes more of them than the budget, many small; the
// reduction then places those pieces.

void Optimizer::grow(double triangleCap) {
    std::vector<uint32_t> candidates, leftovers;
    std::vector<uint32_t> candidateOf(faceCount_, kNone);
    double totalArea = 0.0;
    for (double area : geometry_.areas) totalArea += area;
    const double facesPerCluster = std::min<double>(double(faceCount_), double(limits_.maxTriangles));
    const double expectedRadius =
        std::sqrt(std::max(totalArea / double(std::max<size_t>(faceCount_, 1)) * facesPerCluster / M_PI, 1e-300));
    size_t nextUnassigned = 0;
    // vertexStamp_[v] == cluster + 1: the growing cluster uses v (cluster ids only increase).
    std::fill(vertexStamp_.begin(), vertexStamp_.end(), 0);

    while (true) {
        // Seed in the corner the last cluster left: the leftover face with the fewest free
        // neighbours, so holes get filled before they close.
        uint32_t seed = kNone, fewest = kNone;
        for (uint32_t f : leftovers) {
            if (clusterOf_[f] != kNone) continue;
            uint32_t free = 0;
            for (const uint32_t* g = acrossEdge_.begin(f); g != acrossEdge_.end(f); ++g) free += clusterOf_[*g] == kNone;
            if (free < fewest) fewest = free, seed = f;
        }
        if (seed == kNone) {
            while (nextUnassigned < faceCount_ && clusterOf_[nextUnassigned] != kNone) ++nextUnassigned;
            if (nextUnassigned == faceCount_) break;
            seed = uint32_t(nextUnassigned);
        }
        clusters_.emplace_back();
        ++liveClusters_;
        const uint32_t cluster = uint32_t(clusters_.size() - 1);
        Cluster& grown = clusters_[cluster];
        const uint32_t mark = cluster + 1;
        candidates.clear();
        glm::dvec3 centroidSum(0.0);
        auto addedVertices = [&](uint32_t f) {
            uint32_t added = 0;
            for (size_t k = 0; k < mesh_.faceSize(f); ++k)
                added += vertexStamp_[mesh_.faceBegin(f)[k]] != mark && !repeatsEarlierVertex(f, k);
            return added;
        };
        auto add = [&](uint32_t f) {
            grown.vertices += addedVertices(f);
            grown.triangles += triangles_[f];
            clusterOf_[f] = cluster;
            slotOf_[f] = uint32_t(grown.faces.size());
            grown.faces.push_back(f);
            for (size_t k = 0; k < mesh_.faceSize(f); ++k) vertexStamp_[mesh_.faceBegin(f)[k]] = mark;
            centroidSum += geometry_.centroids[f];
            if (usable_[f] && !contains(grown.cap, geometry_.normals[f])) {
                if (grown.cap.cosRadius > 1.0) grown.cap = capThrough(geometry_.normals[f]);
                else if (grown.cap.cosRadius > 0.0) {
                    const size_t count = gatherNormals(cluster, f);
                    grown.cap = minimalCapWith(scratch_.data(), count, geometry_.normals[f]);
                }
            }
            for (const uint32_t* g = acrossEdge_.begin(f); g != acrossEdge_.end(f); ++g)
                if (clusterOf_[*g] == kNone && candidateOf[*g] != cluster) candidateOf[*g] = cluster, candidates.push_back(*g);
        };
        add(seed);

        while (true) {
            const glm::dvec3 center = centroidSum / double(grown.faces.size());
            const double sinNow = sinOf(grown.cap);
            // The least cone cost any face can have. Adding a normal to a cap of half-angle at
            // most 60 degrees (or to no cone) never lowers sinAfterAdding below sinNow, and the
            // cost is then at least sinNow (less a margin for rounding in its division by t).
            // Wider caps and caps without normals can give lower, even negative, costs: no floor.
            const bool costAtLeastSinNow = grown.cap.cosRadius <= 1.0 && !(grown.cap.cosRadius > 0.0 && grown.cap.cosRadius < 0.5);
            const double coneCostFloor = costAtLeastSinNow ? sinNow * (1.0 - 1e-9) : -std::numeric_limits<double>::infinity();
            uint32_t chosen = kNone;
            double bestScore = std::numeric_limits<double>::infinity();
            for (size_t i = 0; i < candidates.size();) {
                const uint32_t f = candidates[i];
                if (clusterOf_[f] != kNone) {  // taken since it was listed
                    candidates[i] = candidates.back();
                    candidates.pop_back();
                    continue;
                }
                ++i;
                const uint32_t added = addedVertices(f);
                if (grown.vertices + added > limits_.maxVertices || grown.triangles + triangles_[f] > triangleCap) continue;
                // A face whose added vertices alone lose to the best so far is skipped unscored.
                if (kVertexWeight * double(added) + coneCostFloor >= bestScore) continue;
                // Objective lost: the cluster's triangles on the wider cone, and the face itself.
                const double sinAfter = usable_[f] ? sinAfterAdding(grown.cap, glm::dot(geometry_.normals[f], grown.cap.axis)) : sinNow;
                const double t = double(triangles_[f]);
                const double coneCost = (double(grown.triangles) * (sinAfter - sinNow) + t * sinAfter) / t;
                const double distance = glm::length(geometry_.centroids[f] - center) / expectedRadius;
                const double score = coneCost + kDistanceWeight * distance + kVertexWeight * double(added);
                if (score < bestScore) bestScore = score, chosen = f;
            }
            if (chosen == kNone) break;
            add(chosen);
        }
        leftovers.swap(candidates);
    }
    std::fill(vertexStamp_.begin(), vertexStamp_.end(), 0);  // other passes stamp with stamp_
}

void Optimizer::clear() {
    clusters_.clear();
    std::fill(clusterOf_.begin(), clusterOf_.end(), kNone);
    liveClusters_ = 0;
}

// ---------------------------------------------------------------------------------------------
// Reduction to the budget.

std::vector<uint32_t> Optimizer::clustersBySize() const {
    std::vector<uint32_t> order;
    for (uint32_t c = 0; c < clusters_.size(); ++c)
        if (!clusters_[c].faces.empty()) order.push_back(c);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return clusters_[a].triangles < clusters_[b].triangles; });
    return order;
}

// Frees room for `face` in `cluster` by passing one of the cluster's border faces on to a third
// cluster (not `from`, where `face` comes from). Cheap tests first (would `face` fit without it,
// does it fit elsewhere), the connectivity walk last. The move is recorded in undo_. (Chains of
// two such hand-overs reached tight budgets slightly more often at twice the cost: not worth it.)
bool Optimizer::makeRoom(uint32_t face, uint32_t cluster, uint32_t from) {
    const Cluster& full = clusters_[cluster];
    // Who in the cluster uses each corner of `face` (none, one face, or more), so that what
    // arrives without g is a lookup per corner rather than a walk around it for every g.
    corners_.clear();
    for (size_t k = 0; k < mesh_.faceSize(face); ++k) {
        if (repeatsEarlierVertex(face, k)) continue;
        const uint32_t v = mesh_.faceBegin(face)[k];
        Corner corner;
        for (const uint32_t* g = aroundVertex_.begin(v); g != aroundVertex_.end(v) && corner.users < 2; ++g)
            if (clusterOf_[*g] == cluster) corner.soleUser = *g, ++corner.users;
        corners_.push_back(corner);
    }
    members_ = full.faces;
    for (uint32_t g : members_) {
        if (g == face || clusterOf_[g] != cluster || full.triangles - triangles_[g] + triangles_[face] > limits_.maxTriangles) continue;
        // Only a border face has somewhere to go; most members are inside, so ask that first.
        uint32_t others[8];
        const size_t otherCount = neighbourClusters(g, others);
        if (std::count(others, others + otherCount, from) == long(otherCount)) continue;
        // Vertices once g is gone: g's own ones leave, face's ones not used by the rest arrive.
        uint32_t arriving = 0;
        for (const Corner& corner : corners_) arriving += corner.users == 0 || (corner.users == 1 && corner.soleUser == g);
        if (full.vertices - ownVertices(g) + arriving > limits_.maxVertices) continue;
        bool touches = false;  // `face` must still border the cluster without g
        for (const uint32_t* k = acrossEdge_.begin(face); k != acrossEdge_.end(face); ++k) touches |= *k != g && clusterOf_[*k] == cluster;
        if (!touches) continue;
        for (size_t i = 0; i < otherCount; ++i) {
            const uint32_t other = others[i];
            if (other == from || !fits(g, other)) continue;
            if (!staysConnectedWithout(g)) break;
            move(g, other);
            undo_.emplace_back(g, cluster);
            if (usable_[g]) clusters_[other].cap = growCap(clusters_[other].cap, geometry_.normals[g]);
            return true;
        }
    }
    return false;
}

// Empties a cluster by handing each of its faces, from its border inwards, to the neighbouring
// cluster where the objective loses least; a full neighbour first passes one of its own border
// faces on. Caps are grown approximately on the way and recomputed at the end. Undone (returns
// false) if some face finds no room.
bool Optimizer::dissolve(uint32_t cluster) {
    if (clusters_[cluster].faces.empty()) return false;
    undo_.clear();
    std::vector<uint32_t>& queue = queue_;
    uint32_t queued = 0;  // faceStamp_ value of faces in the queue (other checks may overwrite some: harmless)
    auto refill = [&]() {
        queued = ++stamp_;
        queue.clear();
        for (uint32_t f : clusters_[cluster].faces)
            for (const uint32_t* g = acrossEdge_.begin(f); g != acrossEdge_.end(f); ++g)
                if (clusterOf_[*g] != cluster && faceStamp_[f] != queued) faceStamp_[f] = queued, queue.push_back(f);
    };
    refill();
    for (int round = 0; round < 4 && !clusters_[cluster].faces.empty(); ++round) {
        const bool pushing = round >= 2;  // plain moves everywhere first, then make room
        for (size_t i = 0; i < queue.size(); ++i) {
            const uint32_t face = queue[i];
            if (clusterOf_[face] != cluster) continue;
            uint32_t targets[8];
            const size_t targetCount = neighbourClusters(face, targets);
            double bestGain = -std::numeric_limits<double>::infinity();
            uint32_t bestTarget = kNone;
            for (size_t k = 0; k < targetCount; ++k) {
                const uint32_t to = targets[k];
                if (!fits(face, to)) continue;
                const Cluster& target = clusters_[to];
                const double sinAfter = usable_[face] ? sinAfterAdding(target.cap, glm::dot(geometry_.normals[face], target.cap.axis)) : sinOf(target.cap);
                const double gain = expectedCulledTriangles(double(target.triangles) + triangles_[face], sinAfter) - valueOf(target.triangles, target.cap);
                if (gain > bestGain) bestGain = gain, bestTarget = to;
            }
            for (size_t k = 0; k < targetCount && bestTarget == kNone && pushing; ++k)
                if (makeRoom(face, targets[k], cluster)) bestTarget = targets[k];
            if (bestTarget == kNone && round == 3) break;  // last round: one stuck face fails it all
            if (bestTarget == kNone) continue;
            undo_.emplace_back(face, cluster);
            move(face, bestTarget);
            if (usable_[face]) clusters_[bestTarget].cap = growCap(clusters_[bestTarget].cap, geometry_.normals[face]);
            for (const uint32_t* g = acrossEdge_.begin(face); g != acrossEdge_.end(face); ++g)
                if (clusterOf_[*g] == cluster && faceStamp_[*g] != queued) faceStamp_[*g] = queued, queue.push_back(*g);
        }
        refill();
    }
    const bool emptied = clusters_[cluster].faces.empty();
    if (!emptied)
        for (size_t i = undo_.size(); i-- > 0;) move(undo_[i].first, undo_[i].second);
    // Exact caps for every cluster that changed.
    members_.clear();
    for (const auto& [face, from] : undo_) members_.push_back(from), members_.push_back(clusterOf_[face]);
    std::sort(members_.begin(), members_.end());
    members_.erase(std::unique(members_.begin(), members_.end()), members_.end());
    for (uint32_t c : members_) clusters_[c].cap = clusters_[c].faces.empty() ? Cap{} : exactCap(c);
    if (emptied) --liveClusters_;
    return emptied;
}

// This cluster and two of its neighbours are cut again into two compact halves grown from their
// two farthest faces; the count drops by one when both halves fit. For when no neighbour has
// room to take the cluster face by face. The best pair by objective wins.
bool Optimizer::threeIntoTwo(uint32_t cluster) {
    uint32_t neighbours[64];
    size_t neighbourCount = 0;
    for (uint32_t f : clusters_[cluster].faces) {
        uint32_t around[8];
        const size_t count = neighbourClusters(f, around);
        for (size_t i = 0; i < count; ++i)
            if (neighbourCount < 64 && std::find(neighbours, neighbours + neighbourCount, around[i]) == neighbours + neighbourCount)
                neighbours[neighbourCount++] = around[i];
    }
    std::sort(neighbours, neighbours + neighbourCount);
    double bestValue = -std::numeric_limits<double>::infinity();
    uint32_t bestPair[2] = {kNone, kNone};
    struct Entry {
        double distance;
        uint32_t face, side;
        bool operator<(const Entry& other) const {
            if (distance != other.distance) return distance > other.distance;
            return face > other.face;
        }
    };
    std::priority_queue<Entry> heap;
    for (size_t i = 0; i < neighbourCount; ++i)
        for (size_t j = i + 1; j < neighbourCount; ++j) {
            const uint32_t a = neighbours[i], b = neighbours[j];
            const double total = double(clusters_[cluster].triangles) + clusters_[a].triangles + clusters_[b].triangles;
            if (total > 2.0 * double(limits_.maxTriangles)) continue;
            pool_ = clusters_[cluster].faces;
            pool_.insert(pool_.end(), clusters_[a].faces.begin(), clusters_[a].faces.end());
            pool_.insert(pool_.end(), clusters_[b].faces.begin(), clusters_[b].faces.end());
            glm::dvec3 center(0.0);
            for (uint32_t f : pool_) center += geometry_.centroids[f];
            center /= double(pool_.size());
            uint32_t seeds[2] = {pool_[0], pool_[0]};
            double farthest = -1.0;
            for (uint32_t f : pool_)
                if (glm::length(geometry_.centroids[f] - center) > farthest) farthest = glm::length(geometry_.centroids[f] - center), seeds[0] = f;
            farthest = -1.0;
            for (uint32_t f : pool_) {
                const double distance = glm::length(geometry_.centroids[f] - geometry_.centroids[seeds[0]]);
                if (distance > farthest) farthest = distance, seeds[1] = f;
            }
            // Balanced flood: each half takes its nearest faces until it holds half the triangles.
            ++stamp_;
            const uint32_t member = stamp_;
            for (uint32_t f : pool_) faceStamp_[f] = member;
            ++stamp_;
            const uint32_t taken = stamp_;
            for (uint32_t s = 0; s < 2; ++s) heap.push({0.0, seeds[s], s});
            double sideTriangles[2] = {0.0, 0.0};
            size_t assigned = 0;
            while (!heap.empty()) {
                const Entry top = heap.top();
                heap.pop();
                if (faceStamp_[top.face] == taken) continue;
                if (sideTriangles[top.side] + triangles_[top.face] > 0.5 * total + 2.0 && sideTriangles[1 - top.side] < 0.5 * total)
                    continue;  // this half is full; the other may still reach the face
                faceStamp_[top.face] = taken;
                faceMark_[top.face] = top.side;
                sideTriangles[top.side] += triangles_[top.face];
                ++assigned;
                for (const uint32_t* g = acrossEdge_.begin(top.face); g != acrossEdge_.end(top.face); ++g)
                    if (faceStamp_[*g] == member)
                        heap.push({glm::length(geometry_.centroids[*g] - geometry_.centroids[seeds[top.side]]), *g, top.side});
            }
            if (assigned != pool_.size()) continue;
            double value = 0.0;
            bool feasible = true;
            for (uint32_t s = 0; s < 2 && feasible; ++s) {
                ++stamp_;
                uint32_t vertices = 0;
                scratch_.clear();
                for (uint32_t f : pool_) {
                    if (faceMark_[f] != s) continue;
                    if (usable_[f]) scratch_.push_back(geometry_.normals[f]);
                    for (size_t k = 0; k < mesh_.faceSize(f); ++k) {
                        const uint32_t v = mesh_.faceBegin(f)[k];
                        if (vertexStamp_[v] != stamp_) vertexStamp_[v] = stamp_, ++vertices;
                    }
                }
                feasible = vertices <= limits_.maxVertices && sideTriangles[s] <= double(limits_.maxTriangles);
                if (feasible) value += valueOf(sideTriangles[s], minimalCap(scratch_.data(), scratch_.size()));
            }
            if (!feasible || value <= bestValue) continue;
            bestValue = value;
            bestPool_ = pool_;
            bestHalf_.clear();
            for (uint32_t f : pool_)
                if (faceMark_[f] == 0) bestHalf_.push_back(f);
            bestPair[0] = a, bestPair[1] = b;
        }
    if (bestPair[0] == kNone) return false;
    // Half 0 goes to the first neighbour, half 1 to the second; this cluster empties.
    ++stamp_;
    for (uint32_t f : bestHalf_) faceStamp_[f] = stamp_;
    for (uint32_t f : bestPool_) {
        const uint32_t want = faceStamp_[f] == stamp_ ? bestPair[0] : bestPair[1];
        if (clusterOf_[f] != want) move(f, want);
    }
    clusters_[bestPair[0]].cap = exactCap(bestPair[0]);
    clusters_[bestPair[1]].cap = exactCap(bestPair[1]);
    clusters_[cluster].cap = Cap{};
    --liveClusters_;
    return true;
}

double Optimizer::mergeLoss(uint32_t a, uint32_t b, Cap* merged) {
    const Cluster& first = clusters_[a];
    const Cluster& second = clusters_[b];
    if (first.triangles + second.triangles > limits_.maxTriangles) return std::numeric_limits<double>::infinity();
    ++stamp_;
    uint32_t vertices = first.vertices;
    for (uint32_t f : second.faces)
        for (size_t k = 0; k < mesh_.faceSize(f); ++k) {
            const uint32_t v = mesh_.faceBegin(f)[k];
            if (vertexStamp_[v] == stamp_) continue;
            vertexStamp_[v] = stamp_;
            if (!clusterUsesVertex(a, v)) ++vertices;
        }
    if (vertices > limits_.maxVertices) return std::numeric_limits<double>::infinity();
    scratch_.clear();
    for (const Cluster* part : {&first, &second})
        for (uint32_t f : part->faces)
            if (usable_[f]) scratch_.push_back(geometry_.normals[f]);
    *merged = minimalCap(scratch_.data(), scratch_.size());
    return valueOf(first.triangles, first.cap) + valueOf(second.triangles, second.cap) -
           valueOf(double(first.triangles) + double(second.triangles), *merged);
}

void Optimizer::mergeInto(uint32_t into, uint32_t from, const Cap& merged) {
    members_ = clusters_[from].faces;
    for (uint32_t f : members_) move(f, into);
    clusters_[into].cap = merged;
    clusters_[from].cap = Cap{};
    --liveClusters_;
}

// Whole-cluster merges, cheapest objective loss first (lazy heap: an entry is stale once either
// cluster changed since it was pushed).
void Optimizer::mergeCheapest(size_t count) {
    struct Entry {
        double loss;
        uint32_t a, b, versionA, versionB;
        bool operator<(const Entry& other) const {
            if (loss != other.loss) return loss > other.loss;
            if (a != other.a) return a > other.a;
            return b > other.b;
        }
    };
    std::vector<uint32_t> version(clusters_.size(), 0);
    std::priority_queue<Entry> heap;
    std::vector<uint32_t> neighbours;
    auto pushPairs = [&](uint32_t a) {
        neighbours.clear();
        for (uint32_t f : clusters_[a].faces) {
            uint32_t around[8];
            const size_t n = neighbourClusters(f, around);
            for (size_t i = 0; i < n; ++i)
                if (std::find(neighbours.begin(), neighbours.end(), around[i]) == neighbours.end()) neighbours.push_back(around[i]);
        }
        std::sort(neighbours.begin(), neighbours.end());
        for (uint32_t b : neighbours) {
            Cap merged;
            const double loss = mergeLoss(a, b, &merged);
            const uint32_t low = std::min(a, b), high = std::max(a, b);
            if (std::isfinite(loss)) heap.push({loss, low, high, version[low], version[high]});
        }
    };
    for (uint32_t a = 0; a < clusters_.size(); ++a)
        if (!clusters_[a].faces.empty()) pushPairs(a);
    size_t done = 0;
    while (done < count && !heap.empty()) {
        const Entry top = heap.top();
        heap.pop();
        if (version[top.a] != top.versionA || version[top.b] != top.versionB) continue;
        if (clusters_[top.a].faces.empty() || clusters_[top.b].faces.empty()) continue;
        Cap merged;
        if (!std::isfinite(mergeLoss(top.a, top.b, &merged))) continue;
        mergeInto(top.a, top.b, merged);
        ++version[top.a];
        ++version[top.b];
        ++done;
        pushPairs(top.a);
    }
}


// Moves that save a vertex: a border face whose corners the neighbour already uses, and one of
// which only it uses in its own cluster. Full clusters get room that way for the reduction.
size_t Optimizer::compact() {
    size_t moves = 0;
    for (uint32_t face = 0; face < faceCount_; ++face) {
        const uint32_t from = clusterOf_[face];
        if (clusters_[from].faces.size() <= 1 || ownVertices(face) == 0) continue;
        uint32_t targets[8];
        const size_t targetCount = neighbourClusters(face, targets);
        for (size_t i = 0; i < targetCount; ++i) {
            const uint32_t to = targets[i];
            if (newVertices(face, to) != 0 || clusters_[to].triangles + triangles_[face] > limits_.maxTriangles) continue;
            if (!staysConnectedWithout(face)) break;
            move(face, to);
            if (usable_[face]) clusters_[to].cap = growCap(clusters_[to].cap, geometry_.normals[face]);
            ++moves;
            break;
        }
    }
    if (moves > 0)
        for (uint32_t c = 0; c < clusters_.size(); ++c)
            if (!clusters_[c].faces.empty()) clusters_[c].cap = exactCap(c);
    return moves;
}

void Optimizer::reduceTo(size_t target) {
    auto dissolveSmallest = [&]() {
        for (uint32_t c : clustersBySize()) {
            if (liveClusters_ <= target) return;
            dissolve(c);
        }
    };
    dissolveSmallest();
    if (liveClusters_ > target) mergeCheapest(liveClusters_ - target);
    // Where every neighbour is full, three clusters become two, which frees room for more dissolving.
    for (int round = 0; round < 4 && liveClusters_ > target; ++round) {
        const size_t before = liveClusters_;
        compact();
        dissolveSmallest();
        for (uint32_t c : clustersBySize()) {
            if (liveClusters_ <= target) break;
            if (!clusters_[c].faces.empty()) threeIntoTwo(c);
        }
        dissolveSmallest();
        if (liveClusters_ == before) break;
    }
}

// ---------------------------------------------------------------------------------------------
// Local search on the objective.

bool Optimizer::tryMove(uint32_t face, double threshold) {
    const uint32_t from = clusterOf_[face];
    const Cluster& source = clusters_[from];
    if (source.faces.size() <= 1) return false;
    uint32_t targets[8];
    const size_t targetCount = neighbourClusters(face, targets);
    if (targetCount == 0) return false;
    const double t = double(triangles_[face]);
    const double valueFrom = valueOf(source.triangles, source.cap);
    const bool binds = bindsCap(face);
    // Upper bound on what the source can gain: its cap shrinks at most to its other bounding points.
    const double boundFrom = valueOf(double(source.triangles) - t, binds ? supportCapRemoving(source.cap, geometry_.normals[face]) : source.cap);
    Cap capFrom{};
    bool capFromKnown = !binds;
    if (!binds) capFrom = source.cap;
    double bestGain = threshold;
    uint32_t bestTarget = kNone;
    Cap bestCap{};
    for (size_t i = 0; i < targetCount; ++i) {
        const uint32_t to = targets[i];
        const Cluster& target = clusters_[to];
        if (!fits(face, to)) continue;
        const double valueTo = valueOf(target.triangles, target.cap);
        const bool inside = !usable_[face] || contains(target.cap, geometry_.normals[face]);
        // Cheap bound first: the target's cap grows at least to hold its bounding points and the face.
        if (target.cap.cosRadius > 1.0) {
            // no normals yet: nothing cheap to bound with
        } else if (!inside) {
            const double bound = boundFrom + valueOf(double(target.triangles) + t, supportCapAdding(target.cap, geometry_.normals[face])) -
                                 valueFrom - valueTo;
            if (bound <= bestGain) continue;
        } else if (boundFrom + valueOf(double(target.triangles) + t, target.cap) - valueFrom - valueTo <= bestGain) {
            continue;
        }
        if (!capFromKnown) capFrom = capRemoving(face), capFromKnown = true;
        const Cap capTo = capAdding(to, face);
        const double gain = valueOf(double(source.triangles) - t, capFrom) + valueOf(double(target.triangles) + t, capTo) - valueFrom - valueTo;
        if (gain > bestGain) bestGain = gain, bestTarget = to, bestCap = capTo;
    }
    if (bestTarget == kNone || !staysConnectedWithout(face)) return false;
    move(face, bestTarget);
    clusters_[from].cap = capFrom;
    clusters_[bestTarget].cap = bestCap;
    return true;
}

void Optimizer::refine() {
    std::vector<uint32_t> work, next;
    std::vector<uint8_t> queued(faceCount_, 0);
    for (uint32_t f = 0; f < faceCount_; ++f) {
        uint32_t around[8];
        if (neighbourClusters(f, around) > 0) work.push_back(f), queued[f] = 1;
    }
    for (size_t pass = 0; pass < kRefinementPasses && !work.empty(); ++pass) {
        next.clear();
        for (uint32_t f : work) queued[f] = 0;
        for (uint32_t f : work) {
            if (!tryMove(f, 1e-9)) continue;
            // The neighbourhood changed: its faces may now have a better place.
            for (const uint32_t* g = acrossEdge_.begin(f); g != acrossEdge_.end(f); ++g)
                if (!queued[*g]) queued[*g] = 1, next.push_back(*g);
            if (!queued[f]) queued[f] = 1, next.push_back(f);
        }
        work.swap(next);
    }
}

// Annealing in sweeps: every border face in turn is offered its best move, taken when the gain
// beats -T * Exp(1), with T falling geometrically from sweep to sweep. It crosses the ridges
// where a group of faces must move together but each single move loses. Walking faces in order
// keeps memory access local; the generator is fixed, so the result is deterministic.
void Optimizer::anneal(size_t sweeps) {
    uint64_t state = 0x853C49E6748FEA9Bull;
    auto uniform = [&]() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return (double(state >> 11) + 0.5) / 9007199254740992.0;  // (0, 1)
    };
    for (size_t sweep = 0; sweep < sweeps; ++sweep) {
        const double progress = sweeps > 1 ? double(sweep) / double(sweeps - 1) : 1.0;
        const double temperature = kStartTemperature * std::pow(kEndTemperature / kStartTemperature, progress);
        for (uint32_t face = 0; face < faceCount_; ++face) {
            const uint32_t own = clusterOf_[face];
            bool border = false;
            for (const uint32_t* g = acrossEdge_.begin(face); g != acrossEdge_.end(face) && !border; ++g) border = clusterOf_[*g] != own;
            if (border) tryMove(face, temperature * std::log(uniform()));
        }
    }
}

Partition Optimizer::result() const {
    std::vector<uint32_t> renumber(clusters_.size(), kNone);
    Partition partition;
    partition.clusterOfFace.resize(faceCount_);
    for (size_t f = 0; f < faceCount_; ++f) {
        uint32_t& id = renumber[clusterOf_[f]];
        if (id == kNone) id = partition.clusterCount++;
        partition.clusterOfFace[f] = id;
    }
    return partition;
}

}  // namespace

size_t defaultClusterBudget(const Mesh& mesh, const MeshletLimits& limits) {
    const double roundPatch = double(std::min(limits.maxTriangles, 2 * limits.maxVertices));
    const double perCluster = std::max(1.0, kDefaultFill * roundPatch);
    return std::max<size_t>(1, size_t(std::ceil(double(triangleCount(mesh)) / perCluster)));
}

namespace {

// One run of the whole optimisation on a mesh, `sweeps` annealing sweeps (0: none).
Partition optimizeClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t target,
                           size_t sweeps) {
    Optimizer optimizer(mesh, faces, limits);
    const double triangles = double(triangleCount(mesh));
    optimizer.grow(std::min(double(limits.maxTriangles), kGrowthCap * triangles / double(target)));
    if (optimizer.clusterCount() < target) {  // a generous budget: grow again at its mean size
        optimizer.clear();
        optimizer.grow(std::min(double(limits.maxTriangles), triangles / double(target)));
    }
    optimizer.reduceTo(target);
    optimizer.refine();
    if (sweeps > 0) {
        optimizer.anneal(sweeps);
        optimizer.refine();
    }
    return optimizer.result();
}

// Some faces of a mesh as a mesh of their own, vertices renumbered in order of first use (which
// also keeps a part's data close together in memory).
struct MeshPart {
    Mesh mesh;
    FaceGeometry faces;
};

// newIndex: one kNone per mesh vertex, left so again, reused from part to part.
MeshPart extractPart(const Mesh& mesh, const FaceGeometry& faces, const uint32_t* faceIds, size_t faceCount,
                     std::vector<uint32_t>& newIndex) {
    MeshPart part;
    part.mesh.faceStarts.reserve(faceCount + 1);
    part.mesh.faceVertices.reserve(3 * faceCount);
    part.mesh.positions.reserve(faceCount / 2 + 16);
    for (const uint32_t* face = faceIds; face != faceIds + faceCount; ++face) {
        const uint32_t* vertices = mesh.faceBegin(*face);
        for (size_t k = 0; k < mesh.faceSize(*face); ++k) {
            uint32_t& index = newIndex[vertices[k]];
            if (index == kNone) index = uint32_t(part.mesh.positions.size()), part.mesh.positions.push_back(mesh.positions[vertices[k]]);
            part.mesh.faceVertices.push_back(index);
        }
        part.mesh.faceStarts.push_back(uint32_t(part.mesh.faceVertices.size()));
    }
    for (const uint32_t* face = faceIds; face != faceIds + faceCount; ++face)
        for (size_t k = 0; k < mesh.faceSize(*face); ++k) newIndex[mesh.faceBegin(*face)[k]] = kNone;
    auto pick = [&](const auto& values) {
        std::remove_const_t<std::remove_reference_t<decltype(values)>> picked(faceCount);
        for (size_t i = 0; i < faceCount; ++i) picked[i] = values[faceIds[i]];
        return picked;
    };
    part.faces.normals = pick(faces.normals);
    part.faces.planeOffsets = pick(faces.planeOffsets);
    part.faces.centroids = pick(faces.centroids);
    part.faces.areas = pick(faces.areas);
    part.faces.degenerate = pick(faces.degenerate);
    for (uint8_t d : part.faces.degenerate) part.faces.degenerateCount += d;
    return part;
}

// Splits faces [begin, end) in place at their median centroid along their box's longest axis.
// Ties go by face index, so the halves are the same sets whatever order the faces came in.
uint32_t* splitAtMedian(const FaceGeometry& faces, uint32_t* begin, uint32_t* end) {
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (const uint32_t* f = begin; f != end; ++f) low = glm::min(low, faces.centroids[*f]), high = glm::max(high, faces.centroids[*f]);
    const glm::dvec3 extent = high - low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    uint32_t* middle = begin + (end - begin) / 2;
    std::nth_element(begin, middle, end, [&](uint32_t a, uint32_t b) {
        const double ca = faces.centroids[a][axis], cb = faces.centroids[b][axis];
        return ca < cb || (ca == cb && a < b);
    });
    return middle;
}

// Faces of each part in one array: part i is faces[starts[i], starts[i + 1]), in mesh order.
struct Parts {
    std::vector<uint32_t> faces, starts;
    size_t count() const { return starts.size() - 1; }
    size_t size(size_t i) const { return starts[i + 1] - starts[i]; }
    const uint32_t* begin(size_t i) const { return faces.data() + starts[i]; }
};

// Halves of halves until every part has at most kPartFaces faces (and a part still gets a few
// clusters of the budget). The halving runs in place, the parts of one level at once; part 2i and
// 2i + 1 of a level are the halves of part i of the level before.
Parts splitIntoParts(const FaceGeometry& faces, size_t target) {
    Parts parts;
    parts.faces.resize(faces.centroids.size());
    for (uint32_t f = 0; f < parts.faces.size(); ++f) parts.faces[f] = f;
    parts.starts = {0, uint32_t(parts.faces.size())};
    while (parts.size(0) > kPartFaces && target >= 2 * parts.count() * kMinPartClusters) {
        std::vector<uint32_t> middles(parts.count());
        forEachInParallel(parts.count(), [&](size_t i, size_t) {
            uint32_t* begin = parts.faces.data() + parts.starts[i];
            middles[i] = uint32_t(splitAtMedian(faces, begin, begin + parts.size(i)) - parts.faces.data());
        });
        std::vector<uint32_t> finer(1, 0);
        for (size_t i = 0; i < parts.count(); ++i) finer.push_back(middles[i]), finer.push_back(parts.starts[i + 1]);
        parts.starts.swap(finer);
    }
    // Only the final parts need the mesh's own order back: one counting pass over part labels,
    // cheaper than sorting each part.
    std::vector<uint32_t> partOf(parts.faces.size());
    for (uint32_t i = 0; i < parts.count(); ++i)
        for (size_t k = 0; k < parts.size(i); ++k) partOf[parts.begin(i)[k]] = i;
    std::vector<uint32_t> next(parts.starts.begin(), parts.starts.end() - 1);
    for (uint32_t f = 0; f < partOf.size(); ++f) parts.faces[next[partOf[f]]++] = f;
    return parts;
}

}  // namespace

Partition buildOptimizedClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                                 size_t targetClusters, const ProgressCallback& progress) {
    const size_t faceCount = mesh.faceCount();
    if (faceCount == 0) return {};
    const size_t target = targetClusters > 0 ? targetClusters : defaultClusterBudget(mesh, limits);
    // The face-visit budget buys annealing sweeps; too few to cool slowly are not worth their time.
    size_t sweeps = std::min<size_t>(size_t(kSweepFaceVisits / double(faceCount)), kMaxSweeps);
    if (sweeps < kMinSweeps) sweeps = 0;
    const Parts parts = splitIntoParts(faces, target);
    if (parts.count() == 1) {
        Partition whole = optimizeClusters(mesh, faces, limits, target, sweeps);
        if (progress && !progress(1.0, "clusters")) throw OperationCancelled();
        return whole;
    }

    // Parts are optimised independently, as many at once as the machine has cores; the result does
    // not depend on that number. The budget is shared by triangles (rounded cumulatively, so the
    // shares add up to it), and no cluster crosses a cut.
    std::vector<size_t> targets(parts.count());
    const double triangles = double(triangleCount(mesh));
    double before = 0.0;
    for (size_t i = 0; i < parts.count(); ++i) {
        double partTriangles = 0.0;
        for (size_t k = 0; k < parts.size(i); ++k) partTriangles += double(mesh.faceSize(parts.begin(i)[k]) - 2);
        const auto share = [&](double t) { return size_t(std::llround(double(target) * t / triangles)); };
        targets[i] = std::max<size_t>(1, share(before + partTriangles) - share(before));
        before += partTriangles;
    }
    std::vector<Partition> results(parts.count());
    std::vector<std::vector<uint32_t>> newIndex(threadsFor(parts.count()));  // per thread: kNone per mesh vertex
    // Progress is reported by the calling thread (worker 0) only, so the callback needs no lock; a
    // cancel stops the parts not yet started.
    std::atomic<size_t> partsDone{0};
    std::atomic<bool> cancelled{false};
    forEachInParallel(parts.count(), [&](size_t i, size_t worker) {
        if (cancelled) return;
        if (newIndex[worker].empty()) newIndex[worker].assign(mesh.positions.size(), kNone);
        const MeshPart part = extractPart(mesh, faces, parts.begin(i), parts.size(i), newIndex[worker]);
        results[i] = optimizeClusters(part.mesh, part.faces, limits, targets[i], sweeps);
        const size_t done = ++partsDone;
        if (worker == 0 && progress && !progress(double(done) / double(parts.count()), "clusters")) cancelled = true;
    });
    if (cancelled || (progress && !progress(1.0, "clusters"))) throw OperationCancelled();

    Partition partition;
    partition.clusterOfFace.resize(faceCount);
    for (size_t i = 0; i < parts.count(); ++i) {
        for (size_t k = 0; k < parts.size(i); ++k) partition.clusterOfFace[parts.begin(i)[k]] = partition.clusterCount + results[i].clusterOfFace[k];
        partition.clusterCount += results[i].clusterCount;
    }
    return partition;
}

}  // namespace conescope
