// meshoptimizer's meshlets of a mesh as a partition of its faces: the limits it takes, the fan
// triangles it is given, and the choice between the reproduction and the library.
#include "Meshopt.h"
#include "Reproduction.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace conescope {

namespace {

constexpr uint32_t kUnplaced = ~0u;

MeshoptMeshlets reproduce(const Mesh& mesh, const std::vector<uint32_t>& indices, const MeshletLimits& limits, float coneWeight) {
    return reproduceMeshoptMeshlets(indices.data(), indices.size(), &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3),
                                    limits.maxVertices, limits.maxTriangles, coneWeight);
}

}  // namespace

bool meshoptTakesLimits(const MeshletLimits& limits) {
    return limits.maxVertices >= 3 && limits.maxVertices <= 255 && limits.maxTriangles >= 1 && limits.maxTriangles <= 512 &&
           limits.maxTriangles % 4 == 0;
}

void requireMeshoptLimits(const MeshletLimits& limits) {
    if (!meshoptTakesLimits(limits))
        throw std::invalid_argument("meshoptimizer needs 3 <= max vertices <= 255 and max triangles <= 512, divisible by 4 (got " +
                                    std::to_string(limits.maxVertices) + "/" + std::to_string(limits.maxTriangles) + ")");
}

std::vector<uint32_t> fanTriangles(const Mesh& mesh) {
    std::vector<uint32_t> indices;
    indices.reserve(triangleCount(mesh) * 3);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* face = mesh.faceBegin(f);
        for (size_t k = 1; k + 1 < mesh.faceSize(f); ++k) {
            indices.push_back(face[0]);
            indices.push_back(face[k]);
            indices.push_back(face[k + 1]);
        }
    }
    return indices;
}

Partition meshletsAsPartition(std::vector<uint32_t> meshletOfFace) {
    uint32_t last = 0;
    for (uint32_t& id : meshletOfFace) {
        if (id == kUnplaced) id = last;
        last = id;
    }
    return renumberClusters(std::move(meshletOfFace));
}

Partition facesOfMeshlets(const Mesh& mesh, const MeshoptMeshlets& meshlets) {
    std::vector<uint32_t> clusterOfFace(mesh.faceCount(), kUnplaced);
    size_t triangle = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 1; k + 1 < mesh.faceSize(f); ++k, ++triangle)
            clusterOfFace[f] = std::min(clusterOfFace[f], meshlets.meshletOfTriangle[triangle]);
    return meshletsAsPartition(std::move(clusterOfFace));
}

Partition meshoptReproducedMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight) {
    requireMeshoptLimits(limits);
    const std::vector<uint32_t> indices = fanTriangles(mesh);
    if (indices.empty()) return renumberClusters(std::vector<uint32_t>(mesh.faceCount(), 0));
    return facesOfMeshlets(mesh, reproduce(mesh, indices, limits, coneWeight));
}

Partition buildMeshoptMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight) {
    return reproducesLinkedMeshopt() ? meshoptReproducedMeshlets(mesh, limits, coneWeight) : meshoptLibraryMeshlets(mesh, limits, coneWeight);
}

size_t meshoptMeshletCount(const Mesh& mesh, const MeshletLimits& limits, float coneWeight) {
    if (!reproducesLinkedMeshopt()) return meshoptLibraryMeshletCount(mesh, limits, coneWeight);
    requireMeshoptLimits(limits);
    const std::vector<uint32_t> indices = fanTriangles(mesh);
    if (indices.empty()) return 0;
    const MeshoptMeshlets meshlets = reproduce(mesh, indices, limits, coneWeight);
    // A meshlet holding only triangles of polygons that earlier ones took is no cluster of faces.
    return indices.size() == 3 * mesh.faceCount() ? meshlets.count : facesOfMeshlets(mesh, meshlets).clusterCount;
}

}  // namespace conescope
