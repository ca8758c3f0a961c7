#include "io/PositionMerging.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "core/LargeArrays.h"

namespace conescope {

namespace {

// The bits of a position with -0 made +0, so positions equal as floats have equal keys.
std::array<uint32_t, 3> positionKey(const glm::vec3& position) {
    std::array<uint32_t, 3> key{};
    for (int k = 0; k < 3; ++k) {
        const float coordinate = position[k] == 0.0f ? 0.0f : position[k];
        std::memcpy(&key[k], &coordinate, 4);
    }
    return key;
}

// Mixes all three coordinates, so points on a grid (many equal x or z) do not collide.
uint64_t hashOf(const std::array<uint32_t, 3>& key) {
    uint64_t h = (uint64_t(key[0]) << 32 | key[1]) ^ (uint64_t(key[2]) * 0x9e3779b97f4a7c15ull);
    h ^= h >> 29;
    return h * 0xbf58476d1ce4e5b9ull;
}

using HashedVertex = std::pair<uint64_t, uint32_t>;  // (hash of its position, vertex)

// Sorts pairs made in vertex order as std::sort would: by hash, then vertex. A stable radix sort
// on the hash's 11-bit digits keeps the vertex order within a hash; linear where std::sort was
// about a fifth of reading a mesh. Short lists are left to std::sort.
void sortByHash(std::vector<HashedVertex>& order) {
    if (order.size() < 2048) return std::sort(order.begin(), order.end());
    std::vector<HashedVertex> other;
    resizeLarge(other, order.size());
    for (int shift = 0; shift < 64; shift += 11) {
        std::array<size_t, 2049> starts{};
        for (const HashedVertex& pair : order) ++starts[((pair.first >> shift) & 2047) + 1];
        for (size_t d = 0; d < 2048; ++d) starts[d + 1] += starts[d];
        for (const HashedVertex& pair : order) other[starts[(pair.first >> shift) & 2047]++] = pair;
        order.swap(other);
    }
}

// Of (float position, exact key) pairs, one per vertex: how many exact positions there are beyond
// one per float position, the file's positions rounding made into others.
size_t lostPositionsIn(std::vector<std::pair<uint32_t, uint64_t>>& pairs, size_t floatPositions) {
    std::sort(pairs.begin(), pairs.end());
    return size_t(std::unique(pairs.begin(), pairs.end()) - pairs.begin()) - floatPositions;
}

}  // namespace

uint64_t exactPositionKey(const glm::dvec3& position) {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int k = 0; k < 3; ++k) {
        const double coordinate = position[k] == 0.0 ? 0.0 : position[k];
        uint64_t bits = 0;
        std::memcpy(&bits, &coordinate, 8);
        // splitmix64's finaliser over the running hash and each coordinate's bits.
        h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
        h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
        h ^= h >> 31;
    }
    return h;
}

void addExactPosition(std::vector<uint64_t>* keys, const glm::dvec3& position) {
    if (keys) keys->push_back(exactPositionKey(position));
}

std::string lostPositionsWarning(const Mesh& merged, size_t vertices, const MergedPositions& merge) {
    if (merge.lostPositions == 0) return "";
    float largest = 0.0f;
    for (const glm::vec3& p : merged.positions) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const float step = std::nextafter(largest, std::numeric_limits<float>::infinity()) - largest;
    char figures[96];
    std::snprintf(figures, sizeof figures, "at coordinates up to %.3g float32 steps by %.3g", double(largest), double(step));
    const bool one = merge.lostPositions == 1;
    return "Warning: " + std::to_string(vertices) + " vertices read, " + std::to_string(merged.positions.size()) +
           " kept: float32, which ConeScope computes in, merged " + std::to_string(merge.lostPositions) +
           (one ? " position" : " positions") + " the file holds apart (" + figures +
           "), so faces collapse and the numbers describe another mesh; move the mesh near the origin (subtract its centre) and read it again";
}

// Merges as vtkMergePoints does (exact equality) but keeps every face: vtkSTLReader's own merging
// drops each triangle two of whose corners merge, so an STL's degenerate triangles never reached
// degenerate_faces. Vertices are sorted by a hash of their position rather than put in a hash
// table: one pass over millions of vertices, and nothing changes when no two positions are equal.
MergedPositions mergeEqualPositions(Mesh& mesh, const std::vector<uint64_t>& exactKeys) {
    const size_t count = mesh.positions.size();
    const bool exact = exactKeys.size() == count;
    std::vector<std::pair<uint32_t, uint64_t>> exactOfRun;  // (float position's vertex, exact key) of a run
    MergedPositions result;
    std::vector<HashedVertex> order;  // equal positions adjacent
    reserveLarge(order, count);
    for (size_t i = 0; i < count; ++i) order.emplace_back(hashOf(positionKey(mesh.positions[i])), uint32_t(i));
    sortByHash(order);
    // Each vertex's representative: the first vertex (lowest index) at its position.
    std::vector<uint32_t> first, distinct;  // distinct: the run's vertices at positions not seen before in it
    size_t repeats = 0;
    for (size_t run = 0; run < order.size();) {
        size_t end = run + 1;
        while (end < order.size() && order[end].first == order[run].first) ++end;
        distinct.assign(1, order[run].second);
        if (exact) exactOfRun.assign(1, {order[run].second, exactKeys[order[run].second]});
        for (size_t i = run + 1; i < end; ++i) {
            const uint32_t v = order[i].second;
            const auto same = std::find_if(distinct.begin(), distinct.end(), [&](uint32_t d) {
                return positionKey(mesh.positions[d]) == positionKey(mesh.positions[v]);
            });
            if (exact) exactOfRun.emplace_back(same == distinct.end() ? v : *same, exactKeys[v]);
            if (same == distinct.end()) {
                distinct.push_back(v);
                continue;
            }
            if (first.empty()) {
                first.resize(count);
                for (uint32_t u = 0; u < count; ++u) first[u] = u;
            }
            first[v] = *same;
            ++repeats;
        }
        if (exact && end - run > 1) result.lostPositions += lostPositionsIn(exactOfRun, distinct.size());
        run = end;
    }
    result.merged = repeats;
    if (repeats == 0) return result;
    // Number the kept vertices in the order first seen, as before.
    std::vector<uint32_t> mergedIndexOf(count);
    std::vector<glm::vec3> merged;
    merged.reserve(count - repeats);
    for (uint32_t v = 0; v < count; ++v) {
        if (first[v] == v) {
            mergedIndexOf[v] = uint32_t(merged.size());
            merged.push_back(mesh.positions[v]);
        } else {
            mergedIndexOf[v] = mergedIndexOf[first[v]];
        }
    }
    for (uint32_t& vertex : mesh.faceVertices) vertex = mergedIndexOf[vertex];
    mesh.positions = std::move(merged);
    // Files that index vertices (meshlet files) count them as the file stored them.
    if (mesh.fileVertices.empty()) mesh.fileVertices = std::move(mergedIndexOf);
    else for (uint32_t& vertex : mesh.fileVertices) vertex = mergedIndexOf[vertex];
    return result;
}

}  // namespace conescope
