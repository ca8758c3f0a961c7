// Which faces touch which: faces around each vertex and faces across each side, in compressed rows
// (one array of items and one of row starts, no vector per row), for the builders that grow
// clusters over the surface and for the optimized builder's moves.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "Mesh.h"

namespace conescope {

// Row i is items[starts[i], starts[i + 1]).
struct Rows {
    std::vector<uint32_t> starts;
    std::vector<uint32_t> items;
    const uint32_t* begin(size_t i) const { return items.data() + starts[i]; }
    const uint32_t* end(size_t i) const { return items.data() + starts[i + 1]; }
};

// The sides of a face in winding order, as (a, b); a side whose two ends are one vertex (a face
// that repeats a vertex) is no side and is skipped.
template <class Visit>
void forEachSide(const Mesh& mesh, size_t face, Visit visit) {
    // The last side closes the loop; no division per side (a tenth of the adjacency's time).
    const uint32_t* vertices = mesh.faceBegin(face);
    const size_t size = mesh.faceSize(face);
    for (size_t k = 0; k < size; ++k) {
        const uint32_t a = vertices[k], b = vertices[k + 1 < size ? k + 1 : 0];
        if (a != b) visit(a, b);
    }
}

// One key per edge whatever the direction a face runs it: (smaller vertex << 32) | larger vertex.
inline uint64_t edgeKey(uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); }

// Faces around each vertex, in face order; a face that repeats a vertex is listed once.
Rows facesAroundVertices(const Mesh& mesh);

// A side of a face as a half-edge: the edge it runs along, the face, and which way the face runs it.
// Twelve bytes: the checks sort one per side of every face, and each fresh page of them is a fault.
struct HalfEdge {
    uint32_t low, high;     // the edge's smaller and larger vertex
    uint32_t face : 31;     // faces number below 2^31 (sortedHalfEdges checks)
    uint32_t forward : 1;   // the face runs the edge from its smaller to its larger vertex
    uint64_t key() const { return uint64_t(low) << 32 | high; }  // edgeKey
};

// Every side of every face (forEachSide), sorted by edge key, the sides of one edge in face order.
// `sideOf`, when given, gets for each half-edge its side as an index into mesh.faceVertices (the
// face's start plus the side's number among the face's sides).
std::vector<HalfEdge> sortedHalfEdges(const Mesh& mesh, std::vector<uint32_t>* sideOf = nullptr);

// Faces that run a side of each face too, in the order of the face's sides and, along one side, of
// the faces; every face once per row.
Rows facesAcrossEdges(const Mesh& mesh);

}  // namespace conescope
