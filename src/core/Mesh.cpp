#include "Mesh.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "LargeArrays.h"
#include "Parallel.h"

namespace conescope {

void Mesh::addFace(std::initializer_list<uint32_t> vertices) { addFace(vertices.begin(), vertices.size()); }

void Mesh::addFace(const uint32_t* vertices, size_t count) {
    if (faceStarts.empty()) faceStarts.push_back(0);
    faceVertices.insert(faceVertices.end(), vertices, vertices + count);
    faceStarts.push_back(static_cast<uint32_t>(faceVertices.size()));
}

void validateMesh(const Mesh& mesh) {
    auto fail = [](const std::string& message) { throw std::runtime_error(message); };
    if (mesh.faceStarts.empty() || mesh.faceStarts.front() != 0) fail("face offsets must start at 0");
    if (mesh.faceStarts.back() != mesh.faceVertices.size()) fail("face offsets do not cover the index list");
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            std::ostringstream out;
            out << "vertex " << i << " has a non-finite coordinate (" << p.x << ", " << p.y << ", " << p.z << ")";
            fail(out.str());
        }
    }
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        if (mesh.faceStarts[f + 1] < mesh.faceStarts[f]) fail("face offsets decrease at face " + std::to_string(f));
        if (mesh.faceSize(f) < 3)
            fail("face " + std::to_string(f) + " has " + std::to_string(mesh.faceSize(f)) + " vertices (needs 3 or more)");
        const uint32_t* face = mesh.faceBegin(f);
        for (size_t k = 0; k < mesh.faceSize(f); ++k)
            if (face[k] >= mesh.positions.size())
                fail("face " + std::to_string(f) + " uses vertex " + std::to_string(face[k]) + " but there are only " +
                     std::to_string(mesh.positions.size()) + " vertices");
    }
    for (const auto& [name, values] : mesh.faceArrays)
        if (values.size() != mesh.faceCount())
            fail("per-face array '" + name + "' has " + std::to_string(values.size()) + " values for " +
                 std::to_string(mesh.faceCount()) + " faces");
    for (const auto& [path, clusters] : mesh.fileClusters)
        if (clusters.clusterOfFace.size() != mesh.faceCount())
            fail("cluster file '" + path + "' gives " + std::to_string(clusters.clusterOfFace.size()) + " faces a cluster, the mesh has " +
                 std::to_string(mesh.faceCount()));
    for (uint32_t v : mesh.fileVertices)
        if (v >= mesh.positions.size()) fail("a file vertex maps past the mesh's " + std::to_string(mesh.positions.size()) + " vertices");
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(mesh.model[c][r])) fail("model matrix has a non-finite entry");
    if (std::abs(glm::determinant(mesh.model)) == 0.0) fail("model matrix is singular");
}

size_t triangleCount(const Mesh& mesh) {
    size_t total = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) total += mesh.faceSize(f) - 2;
    return total;
}

static bool isIdentity(const glm::dmat4& m) { return m == glm::dmat4(1.0); }

std::vector<glm::vec3> worldPositions(const Mesh& mesh) {
    std::vector<glm::vec3> world;
    reserveLarge(world, mesh.positions.size());  // written once, not zeroed first
    if (isIdentity(mesh.model)) {
        world.assign(mesh.positions.begin(), mesh.positions.end());
        return world;
    }
    for (const glm::vec3& position : mesh.positions)
        world.push_back(glm::vec3(mesh.model * glm::dvec4(glm::dvec3(position), 1.0)));
    return world;
}

glm::dvec3 newellNormal(const glm::vec3* positions, const uint32_t* face, size_t count) {
    if (count == 3) {
        // The cross product of edges from one corner: fewer roundings than Newell's sum for triangles.
        glm::dvec3 a(positions[face[0]]), b(positions[face[1]]), c(positions[face[2]]);
        return glm::cross(b - a, c - a);
    }
    glm::dvec3 normal(0.0);
    // Centre the loop first so large coordinates do not swamp the projected areas.
    glm::dvec3 mean(0.0);
    for (size_t i = 0; i < count; ++i) mean += glm::dvec3(positions[face[i]]);
    mean /= double(count);
    for (size_t i = 0; i < count; ++i) {
        glm::dvec3 p = glm::dvec3(positions[face[i]]) - mean;
        glm::dvec3 q = glm::dvec3(positions[face[(i + 1) % count]]) - mean;
        normal.x += (p.y - q.y) * (p.z + q.z);
        normal.y += (p.z - q.z) * (p.x + q.x);
        normal.z += (p.x - q.x) * (p.y + q.y);
    }
    return normal;
}

FaceGeometry computeFaceGeometry(const Mesh& mesh) {
    const size_t faceCount = mesh.faceCount();
    FaceGeometry geometry;
    // Fresh memory costs more to touch the first time than the loop below costs (a page fault per
    // 4 KiB), so large meshes get their arrays sized on two threads, half the bytes each, and
    // filled on all cores.
    constexpr size_t kFacesPerThread = size_t(1) << 16;
    auto sizeHalf = [&](size_t half) {
        if (half == 0) {
            resizeLarge(geometry.normals, faceCount);
            resizeLarge(geometry.areas, faceCount);
            resizeLarge(geometry.degenerate, faceCount);
        } else {
            resizeLarge(geometry.centroids, faceCount);
        }
    };
    if (faceCount < 2 * kFacesPerThread) sizeHalf(0), sizeHalf(1);
    else forEachInParallel(2, [&](size_t half, size_t) { sizeHalf(half); });
    const bool transformed = !isIdentity(mesh.model);
    const glm::dmat4 normalMatrix = glm::transpose(glm::inverse(mesh.model));
    const double orientation = glm::determinant(mesh.model) < 0.0 ? -1.0 : 1.0;
    const double areaScale = std::abs(glm::determinant(glm::dmat3(mesh.model)));
    std::atomic<size_t> degenerateCount{0};
    forRangesInParallel(faceCount, kFacesPerThread, [&](size_t begin, size_t end) {
        size_t degenerateHere = 0;
        for (size_t f = begin; f < end; ++f) {
            const uint32_t* face = mesh.faceBegin(f);
            const size_t count = mesh.faceSize(f);
            glm::dvec3 mean(0.0);
            for (size_t i = 0; i < count; ++i) mean += glm::dvec3(mesh.positions[face[i]]);
            mean /= double(count);
            glm::dvec3 normal = newellNormal(mesh.positions.data(), face, count);
            double length = glm::length(normal);
            if (transformed) {
                // Seed 003: the plane [n, -n.p_mean] goes through (M^-1)^T, flipped when det M < 0.
                glm::dvec4 plane = orientation * (normalMatrix * glm::dvec4(normal, -glm::dot(normal, mean)));
                normal = glm::dvec3(plane);
                mean = glm::dvec3(mesh.model * glm::dvec4(mean, 1.0));
                // Area in world space: the cofactor matrix scales the Newell vector by |det M| along n.
                length = glm::length(normal) * areaScale;
            }
            const double normalLength = glm::length(normal);
            const bool degenerate = !(normalLength > 0.0) || !std::isfinite(normalLength);
            geometry.degenerate[f] = degenerate ? 1 : 0;
            degenerateHere += degenerate ? 1 : 0;
            geometry.normals[f] = degenerate ? glm::dvec3(0.0) : normal / normalLength;
            geometry.centroids[f] = mean;
            geometry.areas[f] = degenerate ? 0.0 : 0.5 * length;
        }
        degenerateCount += degenerateHere;
    });
    geometry.degenerateCount = degenerateCount;
    return geometry;
}

Aabb computeAabb(const std::vector<glm::vec3>& points) {
    Aabb box;
    if (points.empty()) return box;
    box.min = box.max = points.front();
    for (const glm::vec3& p : points) {
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return box;
}

}  // namespace conescope
