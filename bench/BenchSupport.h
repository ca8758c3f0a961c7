// What the benchmark programs share: finding meshes, subdividing one to a million triangles, and
// meshoptimizer's own cluster pipeline (build, bounds, tests) run as its documentation shows it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <meshoptimizer.h>

#include <glm/glm.hpp>

#include "core/Mesh.h"
#include "core/Partition.h"
#include "core/meshopt/Meshopt.h"

namespace conescope::bench {

// The source tree (for default paths such as datasets/cgal and bench/results).
std::string sourceDirectory();

// Every .off file in a directory, sorted by name; a file path is returned as it is.
std::vector<std::string> meshFiles(const std::string& directoryOrFile);

// File name without directory and extension.
std::string meshName(const std::string& path);

// Splits every triangle into four at its edge midpoints (polygons are fan-triangulated first),
// repeatedly, until the mesh has at least minTriangles triangles. Shared edges share their midpoint,
// so the result stays watertight where the input was.
Mesh subdivideToAtLeast(const Mesh& mesh, size_t minTriangles);

// meshoptimizer's clusters of a mesh: meshopt_buildMeshlets on the fan triangulation of the world
// positions, then meshopt_computeMeshletBounds for each meshlet.
struct MeshoptClusters {
    std::vector<meshopt_Meshlet> meshlets;
    std::vector<unsigned int> vertices;
    std::vector<unsigned char> triangles;
    std::vector<meshopt_Bounds> bounds;

    size_t count() const { return meshlets.size(); }
};

MeshoptClusters buildMeshoptClusters(const std::vector<unsigned int>& indices, const std::vector<glm::vec3>& world,
                                     const MeshletLimits& limits, float coneWeight);

// meshoptimizer's documented per-cluster tests, in float as a renderer runs them.
// Apex: dot(normalize(apex - eye), axis) >= cutoff.
inline bool meshoptApexCulls(const meshopt_Bounds& b, const glm::vec3& eye) {
    const glm::vec3 view = glm::vec3(b.cone_apex[0], b.cone_apex[1], b.cone_apex[2]) - eye;
    const float length = glm::length(view);
    if (!(length > 0.0f)) return false;  // the eye at the apex: no direction to test
    return glm::dot(view / length, glm::vec3(b.cone_axis[0], b.cone_axis[1], b.cone_axis[2])) >= b.cone_cutoff;
}
// Sphere: dot(center - eye, axis) >= cutoff * |center - eye| + radius.
inline bool meshoptSphereCulls(const meshopt_Bounds& b, const glm::vec3& eye) {
    const glm::vec3 view = glm::vec3(b.center[0], b.center[1], b.center[2]) - eye;
    return glm::dot(view, glm::vec3(b.cone_axis[0], b.cone_axis[1], b.cone_axis[2])) >=
           b.cone_cutoff * glm::length(view) + b.radius;
}

// meshoptimizer's triangles in meshlet order as a triangle mesh, so the core's per-face oracle can
// judge them; meshlet m holds faces [faceStarts[m], faceStarts[m + 1]).
struct MeshletTriangles {
    Mesh mesh;
    std::vector<uint32_t> faceStarts;
};
MeshletTriangles meshletTriangleMesh(const MeshoptClusters& clusters, const std::vector<glm::vec3>& world);

// Peak resident set size of this process (VmHWM), in MiB: since the process started or since the
// last resetPeakResident, which brings it down to the current size (Linux's clear_refs), so that
// what came before (a child reading its input) does not hide what is measured. peakResidentMiB
// throws std::runtime_error where /proc does not give it; resetPeakResident says whether it could.
double peakResidentMiB();
bool resetPeakResident();

}  // namespace conescope::bench
