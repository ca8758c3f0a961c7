// A partition assigns every face to one cluster. Builders produce it; everything after reads it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Mesh.h"
#include "MeshoptMeshlets.h"

namespace conescope {

struct Partition {
    std::vector<uint32_t> clusterOfFace;
    uint32_t clusterCount = 0;
};

struct MeshletLimits {
    size_t maxVertices = 64;
    size_t maxTriangles = 124;
};

// Greedy growth over faces that share a vertex, under the vertex/triangle limits. Among the
// faces that fit, it prefers those that keep the normal cone narrow and add few new vertices.
// normalWeight = 0 grows by locality only.
Partition buildMeshlets(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                        double normalWeight = 1.0);

// Lloyd iterations on (position / mesh size, normal * normalWeight) to `clusterCount` clusters.
Partition buildKMeans(const Mesh& mesh, const FaceGeometry& faces, size_t clusterCount, double normalWeight = 1.0,
                      size_t iterations = 12, uint64_t seed = 1);

// The faces as fan triangles, in face order: what meshoptimizer's builder takes.
std::vector<uint32_t> fanTriangles(const Mesh& mesh);

// The partition of faces that meshlets made from fanTriangles(mesh) give: a polygon goes with the
// first meshlet holding one of its fan triangles; a face the library left unplaced (centres near
// the float range, where its k-d tree finds nothing) goes with the face before it.
Partition facesOfMeshlets(const Mesh& mesh, const MeshoptMeshlets& meshlets);

// meshoptimizer's meshopt_buildMeshlets on the fan triangulation. A polygon goes to the first
// meshlet holding one of its fan triangles. Made by reproduceMeshoptMeshlets (MeshoptMeshlets.h)
// where it reproduces the linked library, else by the library (meshoptLibraryMeshlets).
Partition buildMeshoptMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// The same from the library itself, its output triangles matched back to faces by their corners
// (of faces with the same corners, each takes the next one not yet matched).
Partition meshoptLibraryMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// How many meshlets buildMeshoptMeshlets makes, without mapping them back to faces (the default
// budget of the optimized builder). Throws std::invalid_argument as buildMeshoptMeshlets does.
size_t meshoptMeshletCount(const Mesh& mesh, const MeshletLimits& limits, float coneWeight);
// Whether meshoptimizer's builder takes these limits (3..255 vertices, at most 512 triangles, a
// multiple of 4); buildMeshoptMeshlets throws std::invalid_argument otherwise.
bool meshoptTakesLimits(const MeshletLimits& limits);

// Ids given per face (from a mesh array or a text file), renumbered densely in order of first use.
// Throws std::runtime_error if the count does not match or an id is negative / not an integer.
Partition partitionFromIds(const std::vector<double>& ids, size_t faceCount, const std::string& source);

// One id per face, whitespace separated; '#' starts a comment.
std::vector<double> readClusterIdFile(const std::string& path);

// Cluster ids renumbered densely (0..K-1) in order of first use; ids no face has are dropped.
Partition renumberClusters(std::vector<uint32_t> clusterOfFace);

// Faces of each cluster, as offsets into one array (compressed rows).
struct ClusterFaces {
    std::vector<uint32_t> starts;  // clusterCount + 1
    std::vector<uint32_t> faces;
};
ClusterFaces facesByCluster(const Partition& partition);

}  // namespace conescope
