// meshoptimizer in ConeScope: everything that knows the library lives in src/core/meshopt/, and
// this is the folder's one header. Upgrading meshoptimizer is a decision about this folder alone.
//   Which library    the version reproduced and one check of the linked one (reproducesLinkedMeshopt)
//   Meshlets         meshopt_buildMeshlets as a partition of faces, by the reproduction or the library
//   The reproduction meshoptimizer 0.18's builder made again, on the library's own arguments
//   In parts         the meshlets handed over as they are made, on a thread of their own (MeshletStream)
//   Bounds           meshopt_computeClusterBounds for one cluster of faces
//   Engine records   meshopt_Bounds as engines ship them, tested as their shaders test them
//   Simplification   meshopt_simplify with the border locked, for cluster LOD hierarchies
// Only Library.cpp includes <meshoptimizer.h>, and a new call into the library goes there too,
// declared here in its section; the reproduction (Reproduction.cpp, KdTree.h) and the stream
// (MeshletStream.cpp, CoreAffinity.h) are ConeScope's own code. docs/dev/architecture.md has the why.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "CoreAffinity.h"
#include "core/Cones.h"
#include "core/Mesh.h"
#include "core/MeshletArrays.h"
#include "core/Partition.h"
#include "core/Views.h"

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

// --- meshoptimizer's meshlets of a mesh, as a partition of its faces -----------------------------

// Whether meshoptimizer's builder takes these limits (3..255 vertices, at most 512 triangles, a
// multiple of 4); requireMeshoptLimits throws std::invalid_argument naming them otherwise.
bool meshoptTakesLimits(const MeshletLimits& limits);
void requireMeshoptLimits(const MeshletLimits& limits);

// The faces as fan triangles, in face order: what meshoptimizer's builder takes.
std::vector<uint32_t> fanTriangles(const Mesh& mesh);

// meshopt_buildMeshlets on the fan triangulation: the reproduction where it reproduces the linked
// library, else the library. A polygon goes to the first meshlet holding one of its fan
// triangles; a face the library leaves unplaced (centres near the float range, where its k-d tree
// finds nothing) goes with the face before it. Throws as requireMeshoptLimits.
Partition buildMeshoptMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// The same from the reproduction, whatever library is linked.
Partition meshoptReproducedMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// The same from the library itself, its output triangles matched back to faces by their corners
// (of faces with the same corners, each takes the next one not yet matched).
Partition meshoptLibraryMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// How many clusters buildMeshoptMeshlets makes (the optimized builder's default budget), without
// mapping the meshlets back to faces where every face is a triangle, and how many the library's
// make. Throw as requireMeshoptLimits.
size_t meshoptMeshletCount(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
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

// --- In parts, as they are made ------------------------------------------------------------------
// The builder sweeps the surface meshlet by meshlet, so consecutive meshlets make a part of the
// mesh: part i holds the meshlets closed once placedThroughPart(i - 1) triangles were placed and
// before placedThroughPart(i) were. The optimized builder refines the first parts on one core
// while the last triangles are placed on the other (core/ClusterOptimizer.h).

// One part: its faces in ascending order, and each one's meshlet numbered from 0 within the part.
struct MeshletPart {
    std::vector<uint32_t> faces;
    Partition meshlets;  // clusterOfFace[k] is the meshlet of faces[k]
};

// How many parts the meshlets of a mesh of this many faces come in: one below 2,048 faces, then
// shares of about 640 faces each (at least two, at most 64) with the last share in two halves.
// Fixed by the face count alone, so the partitions do not depend on the machine.
size_t meshletPartsFor(size_t faceCount);

// How many of `triangles` placed triangles close part `part` of `partCount` (2 or more): equal
// shares, the last share in two halves, so that the last part, which only begins once the builder
// is done, is short. The last part ends at `triangles`.
size_t placedThroughPart(size_t part, size_t partCount, size_t triangles);

// buildMeshoptMeshlets at cone weight 1, on a thread of its own, handed over in parts. A face goes
// with the meshlet of its first placed fan triangle (the lowest, as buildMeshoptMeshlets does).
// Where the linked library is not the one reproduced, the library builds them as one part.
class MeshletStream {
public:
    // Starts the builder in `partCount` parts (meshletPartsFor). Limits meshoptimizer does not take
    // come back as std::invalid_argument from part(), meshletCount() and whole().
    MeshletStream(std::shared_ptr<const Mesh> mesh, const MeshletLimits& limits, size_t partCount);
    // Stops the builder at its next meshlet if it still runs, and waits for its thread.
    ~MeshletStream();
    MeshletStream(const MeshletStream&) = delete;
    MeshletStream& operator=(const MeshletStream&) = delete;

    const Mesh& mesh() const;
    const MeshletLimits& limits() const;
    size_t partCount() const;

    // Part i, once it is made (waits for it; rethrows what the builder threw).
    const MeshletPart& part(size_t i);
    // Every part made: the number of meshlets, and buildMeshoptMeshlets' partition.
    size_t meshletCount();
    Partition whole();

    // Runs `work` on the stream's thread once every meshlet is made (at once if they are), so that
    // the core it ran on goes on with what the meshlets are for; finishWork waits for it and
    // rethrows what it threw. One piece at a time: each build that shares the stream (the climb's
    // steps) hands over its own after the last one's finishWork; std::logic_error before that.
    void runAfterwards(std::function<void()> work);
    void finishWork();

    // While the builder runs it is kept off the core its creator ran on; a thread that refines the
    // parts holds that core meanwhile (CoreAffinity.h), until every part is made.
    CoreHold holdConsumerCore() const;
    bool allPartsMade();

private:
    struct State;
    std::unique_ptr<State> state_;
};

// --- Cluster bounds ------------------------------------------------------------------------------

// meshopt_computeClusterBounds for one cluster (its faces as fan triangles, at most 512). Its float
// cone is widened to the exact cone around the same axis (coneAroundAxis of `normals`, the
// cluster's face normals) when rounding made it too narrow; the caller still pushes the apex behind
// the face planes. `usable` is false when the library gives no cone narrower than a hemisphere.
struct MeshoptClusterBounds {
    ConeOfNormals cone;
    glm::dvec3 center{0.0};
    glm::dvec3 apex{0.0};
    bool usable = false;
};
MeshoptClusterBounds meshoptClusterBounds(const Mesh& mesh, const std::vector<glm::vec3>& world, const uint32_t* clusterFaces,
                                          size_t faceCount, const std::vector<glm::dvec3>& normals);

// --- Engine records: meshopt_Bounds as engines ship and test them ----------------------------------
// The record is the library's own (meshopt_computeMeshletBounds, 0.18), or a meshlet file's, tested
// in float as shaders test it and NOT made conservative, so its false culls can be counted
// (CullTest::MeshoptApexF32, MeshoptSphereS8; Records.cpp):
//   apex-f32:  dot(normalize(cone_apex - eye), cone_axis) >= cone_cutoff     (meshoptimizer.h's perspective test)
//   sphere-s8: dot(center - eye, axis) >= cutoff * length(center - eye) + radius, with axis =
//              cone_axis_s8 / 127 and cutoff = cone_cutoff_s8 / 127          (niagara, src/shaders/math.h, coneCull)
// An orthographic view (direction d) tests dot(d, axis) >= cutoff, as meshoptimizer.h gives it.
// Beyond 512 triangles (the library's limit) or coordinates beyond 1e18 (it squares them in float)
// the record never culls: cone_cutoff 1, cone_cutoff_s8 127, the rest zero.

// The library's bounds of meshlet m of `arrays`, whose vertex ids index `positions`; of every meshlet.
MeshletBounds meshoptMeshletBounds(const MeshletArrays& arrays, size_t meshlet, const std::vector<glm::vec3>& positions);
std::vector<MeshletBounds> meshoptBoundsOfMeshlets(const MeshletArrays& arrays, const std::vector<glm::vec3>& positions);
// Of a meshlet file's arrays read onto `mesh` (applyMeshlets), whose vertex ids are the file's vertices
// (Mesh::fileVertices) at the mesh's world positions: the bounds an engine computes from the file's
// own meshlets, in its triangle order (the library's cone and sphere depend on it).
std::vector<MeshletBounds> meshoptBoundsOfFileMeshlets(const MeshletArrays& arrays, const Mesh& mesh);
// The same for a cluster given as triangles (three indices each, into `positions`).
MeshletBounds meshoptEngineBounds(const std::vector<uint32_t>& indices, const std::vector<glm::vec3>& positions);

// The two tests from an eye, in float (`eye.position` rounded to float as a shader gets it), and
// sphere-s8's float original: the same test with cone_axis and cone_cutoff as floats.
bool meshoptApexCulls(const MeshletBounds& bounds, const Eye& eye);
bool meshoptSphereS8Culls(const MeshletBounds& bounds, const Eye& eye);
bool meshoptSphereF32Culls(const MeshletBounds& bounds, const Eye& eye);
// How far each passes its threshold (above 0 it culls), in units of the unit view's dot product.
double meshoptApexMargin(const MeshletBounds& bounds, const Eye& eye);
double meshoptSphereS8Margin(const MeshletBounds& bounds, const Eye& eye);
// Share of view directions (eye at infinity) each culls from: (1 - cutoff) / 2, 0 when cutoff >= 1.
double meshoptApexCullShare(const MeshletBounds& bounds);
double meshoptSphereS8CullShare(const MeshletBounds& bounds);

// --- Simplification: meshopt_simplify for cluster LOD hierarchies ----------------------------------

// Triangles simplified and the error that cost, in the positions' units.
struct SimplifiedTriangles {
    std::vector<uint32_t> indices;  // three per triangle, into the same positions
    double error = 0.0;
};
// meshopt_simplify of `indices` (three per triangle, into `positions`) toward `targetTriangles`, with
// every vertex on the triangles' open border locked (meshopt_SimplifyLockBorder), so that a group
// simplified alone still meets its neighbours. No error bound: the target decides, and the error
// reached is returned (the library's relative error times meshopt_simplifyScale).
SimplifiedTriangles simplifyWithLockedBorder(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                                             size_t targetTriangles);

}  // namespace conescope
