// src/core/meshopt/'s own workings, for the folder and its tests (the rest of the core asks
// Meshopt.h): which meshoptimizer is linked, and its 0.18 builder made again decision for decision.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "Meshopt.h"

namespace conescope {

// --- Which library ------------------------------------------------------------------------------

// The meshoptimizer version (MESHOPTIMIZER_VERSION) whose builder reproduceMeshoptMeshlets makes again.
constexpr int kReproducedMeshoptVersion = 180;
// The version of the meshoptimizer ConeScope was built with.
int linkedMeshoptVersion();
// The one check: whether the linked library is the version reproduced. Where it is not, the
// builder and the stream call the library instead (slower, and the stream's meshlets come as one
// part), and the tests of the reproduction skip while one test fails to say so.
bool reproducesLinkedMeshopt();
// Empty where the reproduction runs; else a sentence that says which version is linked and that
// the library's builder runs instead (what the tests of the reproduction skip with).
std::string meshoptFallbackNote();

// The same from the reproduction, whatever library is linked.
Partition meshoptReproducedMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// The same from the library itself, its output triangles matched back to faces by their corners
// (of faces with the same corners, each takes the next one not yet matched).
Partition meshoptLibraryMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// How many clusters the library's own builder makes. Throws as requireMeshoptLimits.
size_t meshoptLibraryMeshletCount(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);

// A meshlet per face (~0u for a face in none) as a partition: a face in no meshlet goes with the
// face before it (the first with meshlet 0), then the ids are renumbered in order of first use.
Partition meshletsAsPartition(std::vector<uint32_t> meshletOfFace);

// --- The reproduction: meshopt_buildMeshlets of 0.18, decision for decision ----------------------
// The same meshlets, triangle for triangle and in the same order, in about half the time, and with
// the meshlet of every input triangle (the library reorders triangles and returns only corners).

struct MeshoptMeshlets {
    std::vector<uint32_t> meshletOfTriangle;  // per input triangle; ~0u for one never placed
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
// takes. Indices must be below vertexCount. `result`'s vectors are sized before the first triangle
// is placed, so that a listener may read placed entries while it runs. On large meshes the k-d tree
// is made on a thread of its own, held on `treeCores` where given (a core that would idle).
void reproduceMeshoptMeshlets(MeshoptMeshlets& result, const uint32_t* indices, size_t indexCount, const float* positions,
                              size_t vertexCount, size_t positionStride, size_t maxVertices, size_t maxTriangles, float coneWeight,
                              const MeshletClosed& closed = {}, const Cores& treeCores = {});
MeshoptMeshlets reproduceMeshoptMeshlets(const uint32_t* indices, size_t indexCount, const float* positions, size_t vertexCount,
                                         size_t positionStride, size_t maxVertices, size_t maxTriangles, float coneWeight);

// The partition of faces that meshlets made from fanTriangles(mesh) give (as buildMeshoptMeshlets).
Partition facesOfMeshlets(const Mesh& mesh, const MeshoptMeshlets& meshlets);

// --- In parts ------------------------------------------------------------------------------------

// How many of `triangles` placed triangles close part `part` of `partCount` (2 or more): equal
// shares, the last share in two halves, so that the last part, which only begins once the builder
// is done, is short. The last part ends at `triangles`.
size_t placedThroughPart(size_t part, size_t partCount, size_t triangles);

}  // namespace conescope
