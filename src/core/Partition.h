// A partition assigns every face to one cluster. Builders produce it; everything after reads it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Mesh.h"

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

// Ids given per face (from a mesh array or a text file), renumbered densely in order of first use.
// Throws std::runtime_error if the count does not match or an id is negative / not an integer.
Partition partitionFromIds(const std::vector<double>& ids, size_t faceCount, const std::string& source);

// A cluster id file as io read it (io/ClusterIdFile.h): its ids, or why there are none.
struct ClusterIdFile {
    std::string path;
    std::vector<double> ids;
    std::string error;  // the reader's message when it could not be read
};

// Cluster ids renumbered densely (0..K-1) in order of first use; ids no face has are dropped.
Partition renumberClusters(std::vector<uint32_t> clusterOfFace);

// Faces of each cluster, as offsets into one array (compressed rows).
struct ClusterFaces {
    std::vector<uint32_t> starts;  // clusterCount + 1
    std::vector<uint32_t> faces;
};
ClusterFaces facesByCluster(const Partition& partition);

}  // namespace conescope
