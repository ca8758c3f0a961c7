#include "Adjacency.h"

#include <algorithm>

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

namespace {

bool faceHasVertex(const Mesh& mesh, uint32_t face, uint32_t vertex) {
    const uint32_t* vertices = mesh.faceBegin(face);
    return std::find(vertices, vertices + mesh.faceSize(face), vertex) != vertices + mesh.faceSize(face);
}

}  // namespace

Rows facesAcrossEdges(const Mesh& mesh, const Rows& aroundVertex) {
    Rows rows;
    rows.starts.assign(mesh.faceCount() + 1, 0);
    rows.items.reserve(mesh.faceVertices.size());
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const size_t rowStart = rows.items.size();
        forEachSide(mesh, f, [&](uint32_t a, uint32_t b) {
            for (const uint32_t* g = aroundVertex.begin(a); g != aroundVertex.end(a); ++g) {
                if (*g == f || !faceHasVertex(mesh, *g, b)) continue;
                if (std::find(rows.items.begin() + long(rowStart), rows.items.end(), *g) == rows.items.end())
                    rows.items.push_back(*g);
            }
        });
        rows.starts[f + 1] = uint32_t(rows.items.size());
    }
    return rows;
}

}  // namespace conescope
