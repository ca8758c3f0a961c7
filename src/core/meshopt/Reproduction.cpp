// meshopt_buildMeshlets of meshoptimizer 0.18 (MIT licence, (c) Arseny Kapoulkine), made again:
// the same decisions, faster. The library visits every triangle around the meshlet at each step;
// here they are kept in five buckets by the library's first rank (vertices added), so a step scores
// only the lowest non-empty bucket and breaks ties by the library's visiting order, and a scan
// stands in for the k-d tree's few searches while it is cheap (docs/dev/architecture.md, "meshoptimizer
// in one folder", has the whole argument). Everything that decides is the library's float
// arithmetic in the library's order, compiled without contracted multiply-adds.
#include "Meshopt.h"
#include "Reproduction.h"
#include "KdTree.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <thread>

namespace conescope {

namespace {

using meshoptkd::centreDistance;
using meshoptkd::KdNode;
using meshoptkd::Spread;

constexpr uint32_t kNone = ~0u;
constexpr uint8_t kUnused = 0xff;  // used[v]: the vertex is not in the meshlet
constexpr int kRanks = 5;          // 0: adds no vertex, 1: left alone at a vertex, 2..4: adds 1..3
// Below this distance a scan does not stand in for the tree: squares of its terms could fall below
// the float range, where the rounded square root of a square may be less than the number.
constexpr float kLeastScannedDistance = 0x1p-60f;
// How many times the triangles scans may look at in all before the tree is built instead. A scan
// costs about a third of what making the tree costs per triangle and level; meshes below 2^15
// triangles have few dead ends, larger ones hundreds, where scans only delay the tree
// (docs/benchmarks.md, "Why the constants are what they are").
constexpr size_t kManyScansBelow = size_t(1) << 15;
constexpr size_t kScannedTimesSmall = 16, kScannedTimesLarge = 2;

struct Cone {
    float px, py, pz;
    float nx, ny, nz;
};

// --- meshoptimizer's own pieces, unchanged in arithmetic -------------------------------------

float meshletScore(float distance2, float spread, float coneWeight, float expectedRadius) {
    float cone = 1.f - spread * coneWeight;
    float coneClamped = cone < 1e-3f ? 1e-3f : cone;
    return (1 + sqrtf(distance2) / expectedRadius * (1 - coneWeight)) * coneClamped;
}

// The same at cone weight 1 (every default run), where the distance's term is multiplied by 0: the
// score is the clamped cone term, exactly, whenever that term is finite. It is when every centre is
// finite and within kFarthestPlainCentre of the origin (a meshlet's centre, a mean of theirs, is
// too, so a squared distance stays below FLT_MAX) and the expected radius is at least
// kLeastPlainRadius. No distance, square root or division per candidate then.
float coneScore(float spread) {
    float cone = 1.f - spread;
    return cone < 1e-3f ? 1e-3f : cone;
}
// sqrt(FLT_MAX) / this is below FLT_MAX: the distance's term stays finite for finite distances.
constexpr float kLeastPlainRadius = 1e-19f;
// Three squared differences of coordinates this large sum to about 5e37, below FLT_MAX.
constexpr float kFarthestPlainCentre = 1e18f;

bool centresWithin(const Cone* triangles, size_t count, float reach) {
    for (size_t i = 0; i < count; ++i)
        if (!(std::fabs(triangles[i].px) <= reach && std::fabs(triangles[i].py) <= reach && std::fabs(triangles[i].pz) <= reach)) return false;
    return true;
}

Cone meshletCone(const Cone& acc, unsigned int triangleCount) {
    Cone result = acc;
    float centerScale = triangleCount == 0 ? 0.f : 1.f / float(triangleCount);
    result.px *= centerScale;
    result.py *= centerScale;
    result.pz *= centerScale;
    float axisLength = result.nx * result.nx + result.ny * result.ny + result.nz * result.nz;
    float axisScale = axisLength == 0.f ? 0.f : 1.f / sqrtf(axisLength);
    result.nx *= axisScale;
    result.ny *= axisScale;
    result.nz *= axisScale;
    return result;
}

// Each triangle's centre and unit normal; returns the mesh's area (twice it, as the library sums).
float triangleCones(Cone* triangles, const uint32_t* indices, size_t triangleCount, const float* positions, size_t strideFloats) {
    float meshArea = 0;
    for (size_t i = 0; i < triangleCount; ++i) {
        const float* p0 = positions + strideFloats * indices[i * 3 + 0];
        const float* p1 = positions + strideFloats * indices[i * 3 + 1];
        const float* p2 = positions + strideFloats * indices[i * 3 + 2];
        float p10[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
        float p20[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
        float normalx = p10[1] * p20[2] - p10[2] * p20[1];
        float normaly = p10[2] * p20[0] - p10[0] * p20[2];
        float normalz = p10[0] * p20[1] - p10[1] * p20[0];
        float area = sqrtf(normalx * normalx + normaly * normaly + normalz * normalz);
        float invarea = (area == 0.f) ? 0.f : 1.f / area;
        triangles[i].px = (p0[0] + p1[0] + p2[0]) / 3.f;
        triangles[i].py = (p0[1] + p1[1] + p2[1]) / 3.f;
        triangles[i].pz = (p0[2] + p1[2] + p2[2]) / 3.f;
        triangles[i].nx = normalx * invarea;
        triangles[i].ny = normaly * invarea;
        triangles[i].nz = normalz * invarea;
        meshArea += area;
    }
    return meshArea;
}

// --- the builder ---------------------------------------------------------------------------------

struct Builder {
    const uint32_t* indices;
    size_t triangleCount;
    size_t maxVertices, maxTriangles;
    float coneWeight, expectedRadius;
    bool distanceFree = false;  // scoreOf is coneScore (cone weight 1, the distance's term always finite)

    // The library's state: the unplaced triangles around each vertex (counts[v] of them from
    // offsets[v]; placed ones are swapped out with the last), which vertex of the meshlet each
    // vertex is (kUnused: none), which triangles are placed.
    std::vector<uint32_t> counts, offsets, around;
    // Where each corner's triangle sits in `around` (index t * 3 + k): ties in bestAround find
    // the library's visiting order there at once, where searching lists of hundreds of triangles
    // at each tie was a quarter of a leafy prop's build.
    std::vector<uint32_t> slot;
    std::vector<Cone> cones;
    std::vector<KdNode> nodes;       // empty until built (nearestUnplaced)
    std::vector<uint8_t> deadNodes;  // subtrees holding only placed triangles (kdNearest)
    size_t placedCount = 0, scanned = 0, searched = 0, treesBuilt = 0;
    std::vector<uint8_t> used, emitted;

    // The meshlet being built.
    std::vector<uint32_t> vertices;
    uint32_t triangles = 0;
    Cone sum{};

    // The triangles around it: listed[t] == meshlet + 1 when t is, at rank rank[t], in bucket
    // rank[t] (older entries of t elsewhere are stale and dropped when met).
    uint32_t meshlet = 0;
    std::vector<uint32_t> listed;
    std::vector<uint8_t> rank;
    std::vector<uint32_t> buckets[kRanks];

    const uint32_t* corners(uint32_t t) const { return indices + size_t(t) * 3; }

    // The library's priority: vertices the triangle adds, 0 first, and one left alone at one of
    // its vertices (its last unplaced triangle) just after.
    uint8_t rankOf(uint32_t t) const {
        const uint32_t* c = corners(t);
        unsigned int extra = (used[c[0]] == kUnused) + (used[c[1]] == kUnused) + (used[c[2]] == kUnused);
        if (extra != 0) {
            if (counts[c[0]] == 1 || counts[c[1]] == 1 || counts[c[2]] == 1) extra = 0;
            extra++;
        }
        return uint8_t(extra);
    }

    float scoreOf(uint32_t t, const Cone& cone) const {
        const Cone& tri = cones[t];
        float distance2 = (tri.px - cone.px) * (tri.px - cone.px) + (tri.py - cone.py) * (tri.py - cone.py) + (tri.pz - cone.pz) * (tri.pz - cone.pz);
        float spread = tri.nx * cone.nx + tri.ny * cone.ny + tri.nz * cone.nz;
        if (distanceFree) return coneScore(spread);
        return meshletScore(distance2, spread, coneWeight, expectedRadius);
    }

    // Where the library's visit meets t first: (place of the meshlet vertex, place in its list).
    uint64_t firstVisit(uint32_t t) const {
        uint64_t first = ~uint64_t(0);
        for (int k = 0; k < 3; ++k) {  // a corner repeated in t: the first of its places, as a search finds
            const uint32_t v = corners(t)[k];
            if (used[v] != kUnused) first = std::min(first, uint64_t(used[v]) << 32 | (slot[size_t(t) * 3 + k] - offsets[v]));
        }
        return first;
    }

    // (Re)ranks a triangle around the meshlet; a new rank gets a new bucket entry.
    void rerank(uint32_t t) {
        const uint8_t now = rankOf(t);
        if (listed[t] == meshlet + 1 && rank[t] == now) return;
        listed[t] = meshlet + 1;
        rank[t] = now;
        buckets[now].push_back(t);
    }

    // The triangle the library would pick among those around the meshlet: the lowest rank, then
    // the lowest score, then the first visited. kNone when there is none; `visitInstead` when a
    // score in the lowest rank is not a number (the library's comparisons then depend on order).
    uint32_t bestAround(const Cone& cone, bool& visitInstead) {
        for (int r = 0; r < kRanks; ++r) {
            std::vector<uint32_t>& bucket = buckets[r];
            uint32_t best = kNone;
            float bestScore = 0.f;
            uint64_t bestVisit = 0;  // firstVisit(best), once a tie needs it
            for (size_t i = 0; i < bucket.size();) {
                const uint32_t t = bucket[i];
                if (emitted[t] || listed[t] != meshlet + 1 || rank[t] != r) {
                    bucket[i] = bucket.back();
                    bucket.pop_back();
                    continue;
                }
                ++i;
                const float score = scoreOf(t, cone);
                if (score != score) {
                    visitInstead = true;
                    return kNone;
                }
                if (best == kNone || score < bestScore) {
                    best = t, bestScore = score, bestVisit = 0;
                } else if (score == bestScore) {
                    if (bestVisit == 0) bestVisit = firstVisit(best) + 1;
                    const uint64_t visit = firstVisit(t) + 1;
                    if (visit < bestVisit) best = t, bestVisit = visit;
                }
            }
            if (best != kNone) return best;
        }
        return kNone;
    }

    // The library's own visit of every triangle around every meshlet vertex.
    uint32_t bestByVisiting(const Cone& cone) const {
        uint32_t best = kNone;
        unsigned int bestExtra = kRanks;
        float bestScore = FLT_MAX;
        for (uint32_t v : vertices)
            for (uint32_t j = 0; j < counts[v]; ++j) {
                const uint32_t t = around[offsets[v] + j];
                const unsigned int extra = rankOf(t);
                if (extra > bestExtra) continue;
                const float score = scoreOf(t, cone);
                if (extra < bestExtra || score < bestScore) best = t, bestExtra = extra, bestScore = score;
            }
        return best;
    }

    // The library's k-d tree, made the first time a scan cannot stand in for it (treeReady), or
    // at once on another thread (startTree).
    std::vector<unsigned int> kdIndices;
    std::thread treeMaker;
    bool treeReady = false;

    ~Builder() {
        if (treeMaker.joinable()) treeMaker.join();
    }

    void allocateTree() {
        kdIndices.resize(triangleCount);
        for (size_t i = 0; i < triangleCount; ++i) kdIndices[i] = unsigned(i);
        nodes.resize(triangleCount * 2);
        deadNodes.assign(nodes.size(), 0);
    }

    void makeTree() { meshoptkd::kdBuild(nodes.data(), &cones[0].px, sizeof(Cone) / sizeof(float), kdIndices.data(), triangleCount, 8); }

    // Large meshes need the tree after a few dead ends nearly always (all of CGAL's and the props
    // tried): it is made on a thread of its own, held on `cores` (if any), while this one places
    // the first triangles, so that it is ready sooner. Made the same way, it answers the same.
    // Its second half is made on this thread's cores, which wait for the tree on most props.
    void startTree(const Cores& cores) {
        allocateTree();
        // Without a thread (not joinable) the tree is made here when needed.
        treeMaker = threadOnCores(cores, [this, builderCores = coresOf(thisThread())] {
            meshoptkd::kdBuildInTwo(nodes.data(), &cones[0].px, sizeof(Cone) / sizeof(float), kdIndices.data(), triangleCount, 8,
                                    builderCores);
        });
    }

    // The unplaced triangle the tree's search would find, by a scan: the search finds the nearest
    // centre, as it never skips a subtree holding it (the split's distance from the position, |delta|,
    // is at most the centre's distance along that axis, both rounded alike, and the rounded square
    // root of a sum of rounded squares is at least that, so |delta| <= limit when the search gets
    // there); among centres exactly as near, the search's order decides (firstInSearchOrder, while
    // its searches have split no more than four times the triangles in all). False
    // when distances are not finite, or so small that squares of their terms could lose precision
    // below the float range: the tree decides then.
    bool nearestByScan(const Cone& cone, uint32_t& nearest) {
        const float position[3] = {cone.px, cone.py, cone.pz};
        float best = FLT_MAX;
        uint32_t bestIndex = kNone, ties = 0;
        for (uint32_t t = 0; t < triangleCount; ++t) {
            if (emitted[t]) continue;
            const float distance = centreDistance(&cones[t].px, position);
            if (!(distance < FLT_MAX)) return false;  // not a number, or too far for the search's first limit
            if (distance < best) best = distance, bestIndex = t, ties = 0;
            else if (distance == best) ++ties;
        }
        nearest = bestIndex;  // kNone: every triangle is placed, as the search would find
        if (bestIndex == kNone || ties == 0) return bestIndex == kNone || best >= kLeastScannedDistance;
        if (best < kLeastScannedDistance || searched > 4 * triangleCount) return false;
        nearest = firstInSearchOrder(position, best);
        return true;
    }

    // Of the unplaced centres at exactly `distance` from `position`, the one the tree's search meets
    // first: it visits the nearer side of each split first and a leaf's centres in order. Only the
    // nodes on the way to it are made, as the library would make them (each node's points split at
    // their mean on the axis of largest spread, in the order its parent's split left them).
    uint32_t firstInSearchOrder(const float* position, float distance) {
        constexpr size_t kLeafSize = 8;
        const float* points = &cones[0].px;
        constexpr size_t stride = sizeof(Cone) / sizeof(float);
        auto tied = [&](unsigned int t) { return !emitted[t] && centreDistance(points + t * stride, position) == distance; };
        std::vector<unsigned int> order(triangleCount);
        for (size_t i = 0; i < triangleCount; ++i) order[i] = unsigned(i);
        // Returns the first tied centre of the node holding order[begin, begin + count), or kNone.
        auto search = [&](auto& self, size_t begin, size_t count) -> uint32_t {
            unsigned int* indices = order.data() + begin;
            searched += count;
            const meshoptkd::KdSplit node = meshoptkd::kdSplit(points, stride, indices, count, kLeafSize,
                                                               count > kLeafSize ? meshoptkd::spreadOf(points, stride, indices, count) : Spread{});
            if (node.leaf) {
                for (size_t i = 0; i < count; ++i)
                    if (tied(indices[i])) return indices[i];
                return kNone;
            }
            const size_t middle = node.middle;
            const bool leftFirst = position[node.axis] - node.split <= 0;
            const size_t firstBegin = leftFirst ? begin : begin + middle, firstCount = leftFirst ? middle : count - middle;
            const size_t secondBegin = leftFirst ? begin + middle : begin, secondCount = count - firstCount;
            if (std::any_of(order.begin() + long(firstBegin), order.begin() + long(firstBegin + firstCount), tied))
                return self(self, firstBegin, firstCount);
            return self(self, secondBegin, secondCount);
        };
        return search(search, 0, triangleCount);
    }

    // Where the tree is not built yet, scans stand in for it while they have looked at no more
    // than kScannedTimes the triangles in all; the tree is built once they would look at more.
    uint32_t nearestUnplaced(const Cone& cone) {
        if (!treeReady) {
            const size_t unplaced = triangleCount - placedCount;
            uint32_t nearest = kNone;
            const size_t scannedTimes = triangleCount < kManyScansBelow ? kScannedTimesSmall : kScannedTimesLarge;
            if (scanned + unplaced <= scannedTimes * triangleCount) {
                scanned += unplaced;
                if (nearestByScan(cone, nearest)) return nearest;
            }
            if (treeMaker.joinable()) {
                treeMaker.join();
            } else {
                if (nodes.empty()) allocateTree();
                makeTree();
            }
            treeReady = true;
            ++treesBuilt;
        }
        float position[3] = {cone.px, cone.py, cone.pz};
        unsigned int index = kNone;
        float limit = FLT_MAX;
        meshoptkd::kdNearest(nodes.data(), 0, &cones[0].px, sizeof(Cone) / sizeof(float), emitted.data(), position, index, limit, deadNodes.data());
        return index;
    }

    // Places t: in the meshlet if its new vertices and one more triangle fit, else in a new one.
    void place(uint32_t t, std::vector<uint32_t>& meshletOfTriangle) {
        const uint32_t* c = corners(t);
        const unsigned int extra = (used[c[0]] == kUnused) + (used[c[1]] == kUnused) + (used[c[2]] == kUnused);
        if (vertices.size() + extra > maxVertices || triangles >= maxTriangles) {
            for (uint32_t v : vertices) used[v] = kUnused;
            vertices.clear();
            triangles = 0;
            sum = Cone{};
            ++meshlet;
            for (std::vector<uint32_t>& bucket : buckets) bucket.clear();
        }
        uint32_t joined[3];
        size_t joinedCount = 0;
        for (int k = 0; k < 3; ++k)
            if (used[c[k]] == kUnused) {
                used[c[k]] = uint8_t(vertices.size());
                vertices.push_back(c[k]);
                joined[joinedCount++] = c[k];
            }
        ++triangles;
        meshletOfTriangle[t] = meshlet;
        bool removed[3] = {false, false, false};
        for (int k = 0; k < 3; ++k) {  // out of the lists of its corners, the last taking its place
            // The first place of t in the list (a repeated corner has two), as a search finds.
            int first = -1;
            for (int j = 0; j < 3; ++j)
                if (c[j] == c[k] && !removed[j] && (first < 0 || slot[size_t(t) * 3 + j] < slot[size_t(t) * 3 + first])) first = j;
            removed[first] = true;
            const uint32_t at = slot[size_t(t) * 3 + first], last = offsets[c[k]] + --counts[c[k]];
            const uint32_t moved = around[last];
            around[at] = moved;
            for (int j = 0; j < 3; ++j)
                if (corners(moved)[j] == c[k] && slot[size_t(moved) * 3 + j] == last) {
                    slot[size_t(moved) * 3 + j] = at;
                    break;
                }
        }
        const Cone& cone = cones[t];
        sum.px += cone.px;
        sum.py += cone.py;
        sum.pz += cone.pz;
        sum.nx += cone.nx;
        sum.ny += cone.ny;
        sum.nz += cone.nz;
        emitted[t] = 1;
        ++placedCount;
        // Ranks that changed: the triangles around a vertex that joined (one vertex fewer to add),
        // and the last triangle left at a corner (now alone there).
        for (size_t j = 0; j < joinedCount; ++j)
            for (uint32_t i = 0; i < counts[joined[j]]; ++i) rerank(around[offsets[joined[j]] + i]);
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = c[k];
            if (counts[v] == 1 && listed[around[offsets[v]]] == meshlet + 1) rerank(around[offsets[v]]);
        }
    }
};

}  // namespace

void reproduceMeshoptMeshlets(MeshoptMeshlets& result, const uint32_t* indices, size_t indexCount, const float* positions,
                              size_t vertexCount, size_t positionStride, size_t maxVertices, size_t maxTriangles, float coneWeight,
                              const MeshletClosed& closed, const Cores& treeCores) {
    result = MeshoptMeshlets{};
    const size_t triangleCount = indexCount / 3;
    if (triangleCount == 0) {
        if (closed) closed(0, 0);
        return;
    }
    Builder b;
    b.indices = indices;
    b.triangleCount = triangleCount;
    b.maxVertices = maxVertices;
    b.maxTriangles = maxTriangles;
    b.coneWeight = coneWeight;

    // Triangles around each vertex, in triangle order (the library's visiting order).
    b.counts.assign(vertexCount, 0);
    for (size_t i = 0; i < indexCount; ++i) b.counts[indices[i]]++;
    b.offsets.resize(vertexCount);
    uint32_t offset = 0;
    for (size_t v = 0; v < vertexCount; ++v) b.offsets[v] = offset, offset += b.counts[v];
    b.around.resize(indexCount);
    b.slot.resize(triangleCount * 3);
    for (size_t t = 0; t < triangleCount; ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t at = b.offsets[indices[t * 3 + k]]++;
            b.around[at] = uint32_t(t);
            b.slot[t * 3 + k] = at;
        }
    for (size_t v = 0; v < vertexCount; ++v) b.offsets[v] -= b.counts[v];

    b.cones.resize(triangleCount);
    const float meshArea = triangleCones(b.cones.data(), indices, triangleCount, positions, positionStride / sizeof(float));
    const float triangleAreaAverage = meshArea / float(triangleCount) * 0.5f;
    b.expectedRadius = sqrtf(triangleAreaAverage * maxTriangles) * 0.5f;
    b.distanceFree = coneWeight == 1.f && b.expectedRadius >= kLeastPlainRadius &&
                     centresWithin(b.cones.data(), triangleCount, kFarthestPlainCentre);

    if (triangleCount >= kManyScansBelow) b.startTree(treeCores);
    b.used.assign(vertexCount, kUnused);
    b.emitted.assign(triangleCount, 0);
    b.listed.assign(triangleCount, 0);
    b.rank.assign(triangleCount, 0);
    b.vertices.reserve(maxVertices);
    result.meshletOfTriangle.assign(triangleCount, kNone);
    result.placementOrder.assign(triangleCount, kNone);
    size_t placed = 0;
    for (;;) {
        const Cone cone = meshletCone(b.sum, b.triangles);
        bool visitInstead = false;
        uint32_t best = b.bestAround(cone, visitInstead);
        if (visitInstead) best = b.bestByVisiting(cone);
        if (best == kNone) best = b.nearestUnplaced(cone);
        if (best == kNone) break;
        const uint32_t meshletBefore = b.meshlet;
        b.place(best, result.meshletOfTriangle);
        if (b.meshlet != meshletBefore && closed && !closed(b.meshlet, placed)) {
            result.builtTree = b.treesBuilt > 0;
            result.placementOrder.resize(placed);
            result.count = b.meshlet;
            return;
        }
        result.placementOrder[placed++] = best;
    }
    result.placementOrder.resize(placed);
    result.count = b.meshlet + (b.triangles > 0 ? 1 : 0);
    result.builtTree = b.treesBuilt > 0;
    if (closed) closed(result.count, placed);
}

MeshoptMeshlets reproduceMeshoptMeshlets(const uint32_t* indices, size_t indexCount, const float* positions, size_t vertexCount,
                                         size_t positionStride, size_t maxVertices, size_t maxTriangles, float coneWeight) {
    MeshoptMeshlets result;
    reproduceMeshoptMeshlets(result, indices, indexCount, positions, vertexCount, positionStride, maxVertices, maxTriangles, coneWeight);
    return result;
}

}  // namespace conescope
