#include "MeshChecks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "Adjacency.h"
#include "LargeArrays.h"

namespace conescope {

namespace {

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
    // Neighbours across manifold edges, (other face, same direction?), in rows per face: counted
    // first, then filled, so millions of faces do not mean millions of small vectors.
    std::vector<uint32_t> starts(faceCount + 1, 0);
    auto forEachManifoldPair = [&](auto visit) {
        for (size_t i = 0; i < edges.size();) {
            size_t j = i;
            while (j < edges.size() && edges[j].key() == edges[i].key()) ++j;
            if (j - i == 2 && edges[i].face != edges[i + 1].face) visit(edges[i], edges[i + 1]);
            i = j;
        }
    };
    forEachManifoldPair([&](const HalfEdge& a, const HalfEdge& b) { ++starts[a.face + 1], ++starts[b.face + 1]; });
    for (size_t f = 0; f < faceCount; ++f) starts[f + 1] += starts[f];
    // Each neighbour as (other face << 1 | same direction): half the memory of a pair.
    std::vector<uint32_t> neighbours(starts[faceCount]);
    std::vector<uint32_t> cursor(starts.begin(), starts.end() - 1);
    forEachManifoldPair([&](const HalfEdge& a, const HalfEdge& b) {
        const uint32_t same = a.forward == b.forward;
        neighbours[cursor[a.face]++] = uint32_t(b.face) << 1 | same;
        neighbours[cursor[b.face]++] = uint32_t(a.face) << 1 | same;
    });
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
            for (uint32_t n = starts[f]; n < starts[f + 1]; ++n) {
                const uint32_t g = neighbours[n] >> 1, same = neighbours[n] & 1;
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

// A triangle with three different corners: most faces, and those whose duplicates the sorted
// half-edges find (countDuplicateTriangles). No other face can have such a triangle's vertex set.
bool simpleTriangle(const Mesh& mesh, size_t face) {
    if (mesh.faceSize(face) != 3) return false;
    const uint32_t* v = mesh.faceBegin(face);
    return v[0] != v[1] && v[1] != v[2] && v[0] != v[2];
}

std::array<uint32_t, 3> cornersOf(const Mesh& mesh, size_t face) {
    const uint32_t* v = mesh.faceBegin(face);
    return sortedCorners(v[0], v[1], v[2]);
}

// Faces with the same vertex set as an earlier face, and those of them wound against it.
struct Duplicates {
    size_t faces = 0, reversed = 0;
};

// Whether face `g`, of the same vertices as `f`, runs them the other way round.
bool woundAgainst(const Mesh& mesh, size_t f, size_t g) {
    const size_t n = mesh.faceSize(f);
    const uint32_t *a = mesh.faceBegin(f), *b = mesh.faceBegin(g);
    const size_t at = size_t(std::find(b, b + n, a[0]) - b);
    return at < n && b[(at + 1) % n] != a[1] && b[(at + n - 1) % n] == a[1];
}

// Simple triangles whose corners an earlier simple triangle already has. Two such triangles run the
// same three edges, so an earlier twin is among the half-edges of the face's two lowest corners,
// which come in face order: a look along one edge per face instead of a table of every face.
Duplicates countDuplicateTriangles(const Mesh& mesh, const std::vector<HalfEdge>& edges) {
    Duplicates duplicates;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].key() == edges[i].key()) ++j;
        for (size_t k = i + 1; k < j; ++k) {  // the edge's first face has no earlier twin here
            const uint32_t f = edges[k].face;
            if (!simpleTriangle(mesh, f)) continue;
            const std::array<uint32_t, 3> corners = cornersOf(mesh, f);
            if (edgeKey(corners[0], corners[1]) != edges[i].key()) continue;  // f's twins are looked for along its lowest edge
            bool twin = false, reversed = false;
            for (size_t h = i; h < k && !reversed; ++h)
                if (edges[h].face != f && simpleTriangle(mesh, edges[h].face) && cornersOf(mesh, edges[h].face) == corners)
                    twin = true, reversed = woundAgainst(mesh, f, edges[h].face);
            duplicates.faces += twin;
            duplicates.reversed += reversed;
        }
        i = j;
    }
    return duplicates;
}

// A face's vertex set: its vertices sorted, so any rotation or winding of a face gives the same.
void sortedVertices(const Mesh& mesh, size_t face, std::vector<uint32_t>& out) {
    out.assign(mesh.faceBegin(face), mesh.faceBegin(face) + mesh.faceSize(face));
    std::sort(out.begin(), out.end());
}

uint32_t hashOf(const std::vector<uint32_t>& vertices) {
    uint64_t hash = vertices.size();
    for (uint32_t v : vertices) hash = (hash ^ v) * 0x9E3779B97F4A7C15ull;
    return uint32_t(hash >> 32);
}

// The other faces (polygons, triangles repeating a corner) whose vertex set an earlier such face
// already has. An open-addressing table of (hash, face) holds one entry per distinct set; equal
// hashes are compared exactly. A node-based hash set of strings cost a heap allocation per face and
// most of the check's time on millions of faces.
Duplicates countDuplicateOtherFaces(const Mesh& mesh) {
    const size_t faceCount = mesh.faceCount();
    size_t others = 0;
    for (size_t f = 0; f < faceCount; ++f) others += !simpleTriangle(mesh, f);
    if (others < 2) return {};
    size_t capacity = 16;
    while (capacity < others + others / 3) capacity *= 2;  // load at most 3/4
    constexpr uint64_t kEmpty = ~uint64_t(0);
    std::vector<uint64_t> slots;  // hash << 32 | face
    reserveLarge(slots, capacity);
    slots.assign(capacity, kEmpty);
    std::vector<uint32_t> vertices, other;
    Duplicates duplicates;
    for (size_t f = 0; f < faceCount; ++f) {
        if (simpleTriangle(mesh, f)) continue;
        sortedVertices(mesh, f, vertices);
        const uint32_t hash = hashOf(vertices);
        for (size_t i = hash & (capacity - 1);; i = (i + 1) & (capacity - 1)) {
            if (slots[i] == kEmpty) {
                slots[i] = uint64_t(hash) << 32 | f;
                break;
            }
            if (uint32_t(slots[i] >> 32) != hash) continue;
            sortedVertices(mesh, uint32_t(slots[i]), other);
            if (other == vertices) {
                ++duplicates.faces;
                duplicates.reversed += woundAgainst(mesh, f, uint32_t(slots[i]));
                break;
            }
        }
    }
    return duplicates;
}

// Per component, judged with the faces flipped as `flip` says: closed (every edge of its faces
// shared by exactly two faces) and consistently wound (no shared edge run twice the same way).
struct ComponentEdges {
    std::vector<uint8_t> closed, consistent;
};

ComponentEdges componentEdges(const std::vector<HalfEdge>& edges, const Orientation& orientation,
                              const std::vector<uint8_t>& flip) {
    ComponentEdges result{std::vector<uint8_t>(orientation.components, 1), std::vector<uint8_t>(orientation.components, 1)};
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].key() == edges[i].key()) ++j;
        const HalfEdge& a = edges[i];
        if (j - i != 2 || a.face == edges[i + 1].face) {
            for (size_t k = i; k < j; ++k) result.closed[orientation.component[edges[k].face]] = 0;
        } else {
            const HalfEdge& b = edges[i + 1];
            if ((a.forward != bool(flip[a.face])) == (b.forward != bool(flip[b.face])))
                result.consistent[orientation.component[a.face]] = 0;
        }
        i = j;
    }
    return result;
}

// Six times the volume each component encloses, by the divergence theorem over the faces' fan
// triangles with `flip` applied, in world orientation (a mirroring model matrix turns it over).
// Each term is measured from the component's first vertex, which keeps the terms small; the sum of
// their magnitudes tells a real sign from rounding.
struct ComponentVolumes {
    std::vector<double> signedVolume, magnitude;
};

ComponentVolumes componentVolumes(const Mesh& mesh, const Orientation& orientation, const std::vector<uint8_t>& flip) {
    ComponentVolumes result{std::vector<double>(orientation.components, 0.0), std::vector<double>(orientation.components, 0.0)};
    const uint32_t unset = ~0u;
    std::vector<uint32_t> origin(orientation.components, unset);
    const double mirror = glm::determinant(mesh.model) < 0.0 ? -1.0 : 1.0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t c = orientation.component[f];
        const uint32_t* face = mesh.faceBegin(f);
        if (origin[c] == unset) origin[c] = face[0];
        const glm::dvec3 o(mesh.positions[origin[c]]);
        const glm::dvec3 first = glm::dvec3(mesh.positions[face[0]]) - o;
        for (size_t k = 1; k + 1 < mesh.faceSize(f); ++k) {
            const glm::dvec3 b = glm::dvec3(mesh.positions[face[k]]) - o;
            const glm::dvec3 d = glm::dvec3(mesh.positions[face[k + 1]]) - o;
            const double term = glm::dot(first, glm::cross(b, d));
            result.signedVolume[c] += flip[f] ? -term : term;
            result.magnitude[c] += std::abs(term);
        }
    }
    for (double& volume : result.signedVolume) volume *= mirror;
    return result;
}

// Closed, consistently wound components whose volume is clearly negative: their normals point in.
std::vector<uint8_t> insideOutComponents(const Mesh& mesh, const std::vector<HalfEdge>& edges,
                                         const Orientation& orientation, const std::vector<uint8_t>& flip) {
    const ComponentEdges shape = componentEdges(edges, orientation, flip);
    const ComponentVolumes volumes = componentVolumes(mesh, orientation, flip);
    std::vector<uint8_t> insideOut(orientation.components, 0);
    for (size_t c = 0; c < orientation.components; ++c)
        insideOut[c] = shape.closed[c] && shape.consistent[c] && volumes.signedVolume[c] < -1e-6 * volumes.magnitude[c];
    return insideOut;
}

}  // namespace

MeshReport checkMesh(const Mesh& mesh, const FaceGeometry& faces) {
    MeshReport report;
    report.degenerateFaces = faces.degenerateCount;
    const std::vector<HalfEdge> edges = sortedHalfEdges(mesh);
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j].key() == edges[i].key()) ++j;
        if (j - i == 1) ++report.openEdges;
        else if (j - i >= 3) ++report.nonManifoldEdges;
        else if (edges[i].forward == edges[i + 1].forward) ++report.inconsistentEdges;
        i = j;
    }
    const Orientation orientation = orientFaces(mesh, edges);
    report.components = orientation.components;
    report.orientable = orientation.orientable;
    const Duplicates triangles = countDuplicateTriangles(mesh, edges), others = countDuplicateOtherFaces(mesh);
    report.duplicateFaces = triangles.faces + others.faces;
    report.doubleSidedFaces = triangles.reversed + others.reversed;
    const std::vector<uint8_t> asTheyStand(mesh.faceCount(), 0);
    for (uint8_t insideOut : insideOutComponents(mesh, edges, orientation, asTheyStand)) report.insideOutComponents += insideOut;
    return report;
}

size_t fixWinding(Mesh& mesh) {
    const std::vector<HalfEdge> edges = sortedHalfEdges(mesh);
    const Orientation orientation = orientFaces(mesh, edges);
    // Keep the winding most faces of each component already have.
    std::vector<size_t> flips(orientation.components, 0), sizes(orientation.components, 0);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        flips[orientation.component[f]] += orientation.flip[f];
        ++sizes[orientation.component[f]];
    }
    std::vector<uint8_t> flip(mesh.faceCount());
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t c = orientation.component[f];
        flip[f] = bool(orientation.flip[f]) != (2 * flips[c] > sizes[c]);
    }
    // Then turn over, whole, each closed component that the agreed winding leaves inside out.
    const std::vector<uint8_t> insideOut = insideOutComponents(mesh, edges, orientation, flip);
    size_t flipped = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        if (insideOut[orientation.component[f]]) flip[f] ^= 1;
        if (!flip[f]) continue;
        std::reverse(mesh.faceVertices.begin() + mesh.faceStarts[f], mesh.faceVertices.begin() + mesh.faceStarts[f + 1]);
        ++flipped;
    }
    return flipped;
}

bool windingNeedsFixing(const MeshReport& report) { return report.inconsistentEdges > 0 || report.insideOutComponents > 0; }

std::string doubleSidedWarning(const MeshReport& report) {
    if (report.doubleSidedFaces == 0) return {};
    const size_t n = report.doubleSidedFaces;
    return "the mesh is double-sided: " + std::to_string(n) + " face" + (n == 1 ? " lies" : "s lie") +
           " back to back with a face of the same corners wound the other way; from any eye one of each pair faces it, so "
           "back-face culling can remove neither side (nor a cluster holding both)";
}

std::string windingWarning(const MeshReport& report) {
    if (!windingNeedsFixing(report)) return {};
    std::string found;
    if (report.inconsistentEdges > 0)
        found = std::to_string(report.inconsistentEdges) + " edge" + (report.inconsistentEdges == 1 ? "" : "s") +
                " whose two faces are wound against each other";
    if (report.insideOutComponents > 0)
        found += (found.empty() ? "" : " and ") + std::to_string(report.insideOutComponents) + " closed component" +
                 (report.insideOutComponents == 1 ? "" : "s") + " turned inside out";
    return "the mesh has " + found + ": some face normals point inwards, so the culling numbers are wrong for those faces";
}

}  // namespace conescope
