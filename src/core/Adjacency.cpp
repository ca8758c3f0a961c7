#include "Adjacency.h"

#include <algorithm>
#include <stdexcept>

#include "LargeArrays.h"

namespace conescope {

Rows facesAroundVertices(const Mesh& mesh) {
    Rows rows;
    rows.starts.assign(mesh.positions.size() + 1, 0);
    for (uint32_t v : mesh.faceVertices) ++rows.starts[v + 1];
    for (size_t v = 0; v < mesh.positions.size(); ++v) rows.starts[v + 1] += rows.starts[v];
    rows.items.resize(mesh.faceVertices.size());
    std::vector<uint32_t> cursor(rows.starts.begin(), rows.starts.end() - 1);
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 0; k < mesh.faceSize(f); ++k) {
            const uint32_t v = mesh.faceBegin(f)[k];
            if (cursor[v] > rows.starts[v] && rows.items[cursor[v] - 1] == f) continue;
            rows.items[cursor[v]++] = uint32_t(f);
        }
    // Close the gaps the repeated corners left.
    size_t write = 0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const uint32_t start = rows.starts[v];
        rows.starts[v] = uint32_t(write);
        for (uint32_t i = start; i < cursor[v]; ++i) rows.items[write++] = rows.items[i];
    }
    rows.starts[mesh.positions.size()] = uint32_t(write);
    rows.items.resize(write);
    return rows;
}

std::vector<HalfEdge> sortedHalfEdges(const Mesh& mesh, std::vector<uint32_t>* sideOf) {
    // A counting sort by the smaller vertex, then each vertex's few half-edges sorted by key in
    // place (stably: the face order they were filled in stays within an edge). Linear where a
    // sort of all half-edges by key is not, and it was most of the mesh checks' time.
    if (mesh.faceCount() >= (size_t(1) << 31)) throw std::length_error("sortedHalfEdges: 2^31 faces or more");
    std::vector<uint32_t> starts(mesh.positions.size() + 1, 0);
    for (size_t f = 0; f < mesh.faceCount(); ++f) forEachSide(mesh, f, [&](uint32_t a, uint32_t b) { ++starts[std::min(a, b) + 1]; });
    for (size_t v = 0; v + 1 < starts.size(); ++v) starts[v + 1] += starts[v];
    std::vector<HalfEdge> edges;
    resizeLarge(edges, starts.back());
    std::vector<uint32_t> sides;
    if (sideOf) resizeLarge(sides, edges.size());
    std::vector<uint32_t> cursor(starts.begin(), starts.end() - 1);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        uint32_t side = mesh.faceStarts[f];
        forEachSide(mesh, f, [&](uint32_t a, uint32_t b) {
            const uint32_t at = cursor[std::min(a, b)]++;
            edges[at] = HalfEdge{std::min(a, b), std::max(a, b), uint32_t(f), a < b};
            if (sideOf) sides[at] = side;
            ++side;
        });
    }
    std::vector<uint32_t> order;
    std::vector<HalfEdge> movedEdges;
    std::vector<uint32_t> movedSides;
    for (size_t v = 0; v + 1 < starts.size(); ++v) {
        const uint32_t begin = starts[v], end = starts[v + 1];
        if (end - begin < 2) continue;
        if (end - begin <= 32) {  // insertion sort, carrying the sides along
            for (uint32_t i = begin + 1; i < end; ++i)
                for (uint32_t j = i; j > begin && edges[j - 1].high > edges[j].high; --j) {  // one bucket: one low vertex
                    std::swap(edges[j - 1], edges[j]);
                    if (sideOf) std::swap(sides[j - 1], sides[j]);
                }
            continue;
        }
        order.resize(end - begin);  // a vertex of many edges (a fan's centre)
        for (uint32_t i = 0; i < order.size(); ++i) order[i] = begin + i;
        std::stable_sort(order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return edges[x].high < edges[y].high; });
        movedEdges.clear(), movedSides.clear();
        for (uint32_t i : order) {
            movedEdges.push_back(edges[i]);
            if (sideOf) movedSides.push_back(sides[i]);
        }
        std::copy(movedEdges.begin(), movedEdges.end(), edges.begin() + begin);
        if (sideOf) std::copy(movedSides.begin(), movedSides.end(), sides.begin() + begin);
    }
    if (sideOf) *sideOf = std::move(sides);
    return edges;
}

Rows facesAcrossEdges(const Mesh& mesh) {
    std::vector<uint32_t> sideOf;
    const std::vector<HalfEdge> edges = sortedHalfEdges(mesh, &sideOf);
    // Where each side's edge starts among the sorted half-edges.
    std::vector<uint32_t> edgeOfSide(mesh.faceVertices.size(), 0);
    for (size_t i = 0, first = 0; i < edges.size(); ++i) {
        if (edges[i].key() != edges[first].key()) first = i;
        edgeOfSide[sideOf[i]] = uint32_t(first);
    }
    Rows rows;
    rows.starts.assign(mesh.faceCount() + 1, 0);
    rows.items.reserve(edges.size());
    // Per face: the last row it went into, so each row holds a face once without searching the
    // row (quadratic where edges carry many faces: a tenth of white_lily's run).
    std::vector<uint32_t> inRowOf(mesh.faceCount(), ~0u);  // ~0u: none yet
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        uint32_t side = mesh.faceStarts[f];
        forEachSide(mesh, f, [&](uint32_t, uint32_t) {
            const uint32_t first = edgeOfSide[side++];
            for (uint32_t i = first; i < edges.size() && edges[i].key() == edges[first].key(); ++i) {
                const uint32_t g = edges[i].face;
                if (g != f && inRowOf[g] != f) inRowOf[g] = uint32_t(f), rows.items.push_back(g);
            }
        });
        rows.starts[f + 1] = uint32_t(rows.items.size());
    }
    return rows;
}

}  // namespace conescope
