// meshoptimizer 0.18's meshlet builder (meshopt_buildMeshlets), made again decision for decision:
// the same meshlets, triangle for triangle and in the same order, in about half the time, and
// with the meshlet of every input triangle (the library reorders triangles and returns only their
// corners, which then have to be matched back to faces). The default budget is meshoptimizer's
// count and the fast effort levels start from its meshlets, so this is on every default run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace conescope {

// The meshoptimizer version whose builder reproduceMeshoptMeshlets makes again; with any other
// version linked, buildMeshoptMeshlets and meshoptMeshletCount call the library instead.
constexpr int kReproducedMeshoptVersion = 180;

// What meshopt_buildMeshlets makes of the same arguments.
struct MeshoptMeshlets {
    std::vector<uint32_t> meshletOfTriangle;  // per input triangle
    std::vector<uint32_t> placementOrder;     // the triangles in the order the builder placed them
    size_t count = 0;                         // meshlets
    // Whether the library's k-d tree of triangle centres was built: scans stand in for its few
    // searches where they can (same answers; the tests see both ways taken).
    bool builtTree = false;
};

// Hears (meshlets closed, triangles placed) each time a meshlet is closed, the last one included,
// from the building thread: every triangle placed so far is in a closed meshlet or the open one,
// and the result's entries for them are final. Returning false stops the building (the result
// then holds what was placed).
using MeshletClosed = std::function<bool(size_t closedMeshlets, size_t placedTriangles)>;

// The arguments are meshopt_buildMeshlets' (positionStride in bytes); the limits must be ones it
// takes (meshoptTakesLimits). Indices must be below vertexCount. `result`'s vectors are sized
// before the first triangle is placed, so that a listener may read placed entries while it runs.
void reproduceMeshoptMeshlets(MeshoptMeshlets& result, const uint32_t* indices, size_t indexCount, const float* positions,
                              size_t vertexCount, size_t positionStride, size_t maxVertices, size_t maxTriangles, float coneWeight,
                              const MeshletClosed& closed = {});

// The same, returned.
MeshoptMeshlets reproduceMeshoptMeshlets(const uint32_t* indices, size_t indexCount, const float* positions, size_t vertexCount,
                                         size_t positionStride, size_t maxVertices, size_t maxTriangles, float coneWeight);

}  // namespace conescope
