// The mesh as the culling core sees it: positions, polygon faces of any size >= 3,
// a model matrix, and any per-face arrays a reader found (e.g. "cluster_id").
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "FileClusters.h"

namespace conescope {

struct Mesh {
    std::vector<glm::vec3> positions;
    // Face f uses faceVertices[faceStarts[f] .. faceStarts[f + 1]); faceStarts has faceCount()+1 entries.
    std::vector<uint32_t> faceStarts{0};
    std::vector<uint32_t> faceVertices;
    // Model-to-world transform; culling happens in world space.
    glm::dmat4 model{1.0};
    // Per-face scalar arrays carried over from the file (one value per face).
    std::map<std::string, std::vector<double>> faceArrays;
    // For each vertex of the file as read, the vertex it became (readers merge equal positions);
    // empty when they are the same. Meshlet files index the file's vertices.
    std::vector<uint32_t> fileVertices;
    // Partitions read from cluster files with the mesh (io's ClusterFiles.h), by the file's path.
    std::map<std::string, FileClusters> fileClusters;

    size_t faceCount() const { return faceStarts.empty() ? 0 : faceStarts.size() - 1; }
    size_t faceSize(size_t f) const { return faceStarts[f + 1] - faceStarts[f]; }
    const uint32_t* faceBegin(size_t f) const { return faceVertices.data() + faceStarts[f]; }
    void addFace(std::initializer_list<uint32_t> vertices);
    void addFace(const uint32_t* vertices, size_t count);
};

// Throws std::runtime_error naming the first structural problem (face with < 3 vertices, index out of
// range, non-finite coordinate, array of wrong length). Readers call it so no bad mesh reaches culling.
void validateMesh(const Mesh& mesh);

// Triangles a face contributes when drawn as a fan: size - 2.
size_t triangleCount(const Mesh& mesh);

// A triangle's vertex set: its three corners in increasing order, whatever its winding and first
// corner. Three compare-and-swaps, where a sort call cost most of the duplicate-face check.
inline std::array<uint32_t, 3> sortedCorners(uint32_t a, uint32_t b, uint32_t c) {
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return {a, b, c};
}

// Positions after the model matrix.
std::vector<glm::vec3> worldPositions(const Mesh& mesh);

// Per-face geometry in world space. Normals are unit length in double precision so the exact
// per-face oracle and the cone construction read the same numbers.
struct FaceGeometry {
    std::vector<glm::dvec3> normals;    // unit; zero for degenerate faces
    std::vector<glm::dvec3> centroids;  // p_mean, the average of the face's vertices
    std::vector<double> areas;          // polygon area (half the Newell vector's length)
    std::vector<uint8_t> degenerate;    // 1 when the face has no normal (zero area)
    size_t degenerateCount = 0;
};

// Newell's method (seed 003): the components are the signed areas of the polygon projected onto the
// YZ, ZX and XY planes, times two. For a triangle it equals the cross product (b-a)x(c-a).
glm::dvec3 newellNormal(const glm::vec3* positions, const uint32_t* face, size_t count);

// Normals by Newell in model space, then each face's plane [n, d] carried to world space by
// (M^-1)^T and flipped when det M < 0 (seed 003), so the normal keeps pointing out of the surface as
// the winding of the transformed vertices defines it.
FaceGeometry computeFaceGeometry(const Mesh& mesh);

struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    float halfDiagonal() const { return 0.5f * glm::length(max - min); }
};
Aabb computeAabb(const std::vector<glm::vec3>& points);

}  // namespace conescope
