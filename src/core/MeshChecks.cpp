#include "MeshChecks.h"

#include <algorithm>
#include <unordered_set>
#include <vector>

namespace conescope {

namespace {

struct HalfEdge {
    uint64_t key;    // (smaller vertex << 32) | larger vertex
    uint32_t face;
    bool forward;    // the face runs the edge from smaller to larger vertex
};

std::vector<HalfEdge> sortedHalfEdges(const Mesh& mesh) {
    std::vector<HalfEdge> edges;
    edges.reserve(mesh.faceVertices.size());
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* face = mesh.faceBegin(f);
        const size_t count = mesh.faceSize(f);
        for (size_t k = 0; k < count; ++k) {
            const uint32_t a = face[k], b = face[(k + 1) % count];
            if (a == b) continue;
            const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            edges.push_back({key, uint32_t(f), a < b});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) { return x.key < y.key; });
    return edges;
}

// Walks faces across manifold edges choosing for each face whether it must flip to agree with the
// face it was reached from. Returns flip flags, component ids and whether any cycle contradicted.
struct Orientation {
    std::vector<uint8_t> flip;
    std::vector<uint32_t> component;
    size_t components = 0;
    bool orientable = true;
};

Orientation orientFaces(const Mesh& mesh, const std::vector<HalfEdge>& edges) {
    const size_t faceCount = mesh.faceCount();
    // Neighbours across manifold edges: (other face, same direction?).
    std::vector<std::vector<std::pair<uint32_t, bool>>> neighbours(faceCount);
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].key == edges[i].key) ++j;
        if (j - i == 2 && edges[i].face != edges[i + 1].face) {
            const bool same = edges[i].forward == edges[i + 1].forward;
            neighbours[edges[i].face].push_back({edges[i + 1].face, same});
            neighbours[edges[i + 1].face].push_back({edges[i].face, same});
        }
        i = j;
    }
    Orientation result;
    result.flip.assign(faceCount, 0);
    const uint32_t unvisited = ~0u;
    result.component.assign(faceCount, unvisited);
    std::vector<uint32_t> queue;
    for (size_t start = 0; start < faceCount; ++start) {
        if (result.component[start] != unvisited) continue;
        const uint32_t id = uint32_t(result.components++);
        result.component[start] = id;
        queue.assign(1, uint32_t(start));
        while (!queue.empty()) {
            const uint32_t f = queue.back();
            queue.pop_back();
            for (const auto& [g, same] : neighbours[f]) {
                // Two faces running a shared edge the same way disagree: one of them must flip.
                const uint8_t wanted = result.flip[f] ^ uint8_t(same);
                if (result.component[g] == unvisited) {
                    result.component[g] = id;
                    result.flip[g] = wanted;
                    queue.push_back(g);
                } else if (result.flip[g] != wanted) {
                    result.orientable = false;
                }
            }
        }
    }
    return result;
}

}  // namespace

MeshReport checkMesh(const Mesh& mesh, const FaceGeometry& faces) {
    MeshReport report;
    report.degenerateFaces = faces.degenerateCount;
    const std::vector<HalfEdge> edges = sortedHalfEdges(mesh);
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].key == edges[i].key) ++j;
        if (j - i == 1) ++report.openEdges;
        else if (j - i >= 3) ++report.nonManifoldEdges;
        else if (edges[i].forward == edges[i + 1].forward) ++report.inconsistentEdges;
        i = j;
    }
    const Orientation orientation = orientFaces(mesh, edges);
    report.components = orientation.components;
    report.orientable = orientation.orientable;
    std::unordered_set<std::string> seen;
    std::vector<uint32_t> sorted;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        sorted.assign(mesh.faceBegin(f), mesh.faceBegin(f) + mesh.faceSize(f));
        std::sort(sorted.begin(), sorted.end());
        if (!seen.emplace(reinterpret_cast<const char*>(sorted.data()), sorted.size() * sizeof(uint32_t)).second)
            ++report.duplicateFaces;
    }
    return report;
}

size_t fixWinding(Mesh& mesh) {
    Orientation orientation = orientFaces(mesh, sortedHalfEdges(mesh));
    // Keep the winding most faces of each component already have.
    std::vector<size_t> flips(orientation.components, 0), sizes(orientation.components, 0);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        flips[orientation.component[f]] += orientation.flip[f];
        ++sizes[orientation.component[f]];
    }
    size_t flipped = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t c = orientation.component[f];
        const bool invert = 2 * flips[c] > sizes[c];
        if (bool(orientation.flip[f]) != invert) {
            std::reverse(mesh.faceVertices.begin() + mesh.faceStarts[f], mesh.faceVertices.begin() + mesh.faceStarts[f + 1]);
            ++flipped;
        }
    }
    return flipped;
}

}  // namespace conescope
