// meshoptimizer's meshlet arrays as meshopt_buildMeshlets fills them, and the partition of a mesh's
// faces they describe. An engine ships these; ConeScope reads them back onto the mesh file they were
// made from (io's MeshletFiles.h reads and writes them as JSON and binary).
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "FileClusters.h"
#include "Mesh.h"
#include "Partition.h"

namespace conescope {

struct MeshletArrays {
    // Per meshlet: vertex_offset, triangle_offset, vertex_count, triangle_count (meshopt_Meshlet).
    std::vector<std::array<uint32_t, 4>> meshlets;
    std::vector<uint32_t> vertices;   // meshlet_vertices: indices of the mesh file's vertices
    std::vector<uint8_t> triangles;   // meshlet_triangles: three local indices a triangle
    std::vector<MeshletBounds> bounds;  // per meshlet when stored (meshopt_Bounds), else empty
};

// meshoptimizer's limits on one meshlet (meshoptimizer.h, meshopt_buildMeshlets: max_vertices <= 255,
// max_triangles <= 512; meshopt_computeMeshletBounds assumes them). Files that break them are refused.
constexpr uint32_t kMeshletMaxVertices = 255, kMeshletMaxTriangles = 512;

// Thrown for arrays that do not describe a partition of the mesh; what() names the meshlet and the
// fault (an offset or count out of range or above meshoptimizer's limits, a vertex past the mesh, a
// triangle matching no face, a face in two meshlets, faces in no meshlet).
class MeshletError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Puts the meshlets on `mesh`: each triangle is matched to the face with its three corners (file
// vertices mapped through mesh.fileVertices; among faces with the same corners, one wound the same
// way first); a polygon whose triangles lie in different meshlets is cut into those triangles, in
// its own winding, its face arrays and the other file partitions copied to each piece. Returns the
// partition with the meshlets' own numbering: cluster m is meshlet m. Every face must be in exactly
// one meshlet. The bounds are the arrays' (empty when the file stored none: io's readClusterFile
// then computes meshoptimizer's, meshoptBoundsOfFileMeshlets). Throws MeshletError.
struct AppliedMeshlets {
    FileClusters clusters;
    size_t cutPolygons = 0;   // polygons cut into their triangles
};
AppliedMeshlets applyMeshlets(Mesh& mesh, const MeshletArrays& arrays);

// The partition as meshlet arrays: cluster c is meshlet c, its vertices in order of first use, its
// faces as fan triangles; vertex ids are the mesh's (io maps them to the file's). Throws
// std::invalid_argument naming the cluster when one breaks meshoptimizer's limits (above).
MeshletArrays meshletsOfPartition(const Mesh& mesh, const Partition& partition);

}  // namespace conescope
