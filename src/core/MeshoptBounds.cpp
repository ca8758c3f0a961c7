#include "MeshoptBounds.h"

#include <meshoptimizer.h>

#include <algorithm>

namespace conescope {

namespace {

// meshoptimizer asserts on more (kMeshletMaxTriangles in clusterizer.cpp, 0.18).
constexpr size_t kLibraryMaxTriangles = 512;
// It squares coordinates in float: from about 1e19 on that overflows and trips its assertion.
constexpr float kLibraryLargestCoordinate = 1e18f;

MeshletBounds fromLibrary(const meshopt_Bounds& b) {
    MeshletBounds bounds;
    std::copy(b.center, b.center + 3, bounds.center.begin());
    bounds.radius = b.radius;
    std::copy(b.cone_apex, b.cone_apex + 3, bounds.coneApex.begin());
    std::copy(b.cone_axis, b.cone_axis + 3, bounds.coneAxis.begin());
    bounds.coneCutoff = b.cone_cutoff;
    std::copy(b.cone_axis_s8, b.cone_axis_s8 + 3, bounds.coneAxisS8.begin());
    bounds.coneCutoffS8 = b.cone_cutoff_s8;
    return bounds;
}

}  // namespace

MeshletBounds meshoptMeshletBounds(const MeshletArrays& arrays, size_t meshlet, const std::vector<glm::vec3>& positions) {
    const auto [vertexOffset, triangleOffset, vertexCount, triangleCount] = arrays.meshlets[meshlet];
    if (triangleCount > kLibraryMaxTriangles || positions.empty()) return MeshletBounds{};
    for (uint32_t i = vertexOffset; i < vertexOffset + vertexCount; ++i) {
        const glm::vec3 p = glm::abs(positions[arrays.vertices[i]]);
        if (std::max({p.x, p.y, p.z}) > kLibraryLargestCoordinate) return MeshletBounds{};
    }
    return fromLibrary(meshopt_computeMeshletBounds(&arrays.vertices[vertexOffset], &arrays.triangles[triangleOffset], triangleCount,
                                                    &positions[0].x, positions.size(), sizeof(glm::vec3)));
}

std::vector<MeshletBounds> meshoptBoundsOfMeshlets(const MeshletArrays& arrays, const std::vector<glm::vec3>& positions) {
    std::vector<MeshletBounds> bounds(arrays.meshlets.size());
    for (size_t m = 0; m < bounds.size(); ++m) bounds[m] = meshoptMeshletBounds(arrays, m, positions);
    return bounds;
}

}  // namespace conescope
