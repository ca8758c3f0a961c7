#include "ExpectedCull.h"

#include <vector>

namespace conescope {

double expectedCullRate(const ConeOfNormals* cones, const uint32_t* triangles, size_t clusterCount) {
    double culled = 0.0, total = 0.0;
    for (size_t c = 0; c < clusterCount; ++c) {
        if (cones[c].cullable) culled += expectedCulledTriangles(double(triangles[c]), cones[c].sinHalfAngle);
        total += double(triangles[c]);
    }
    return total > 0.0 ? culled / total : 0.0;
}

double expectedCullRate(const Mesh& mesh, const FaceGeometry& faces, const Partition& partition) {
    const ClusterFaces rows = facesByCluster(partition);
    std::vector<ConeOfNormals> cones(partition.clusterCount);
    std::vector<uint32_t> triangles(partition.clusterCount, 0);
    std::vector<glm::dvec3> normals;
    for (uint32_t c = 0; c < partition.clusterCount; ++c) {
        normals.clear();
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            normals.push_back(faces.normals[rows.faces[i]]);
            triangles[c] += uint32_t(mesh.faceSize(rows.faces[i]) - 2);
        }
        cones[c] = minimalCone(normals.data(), normals.size());
    }
    return expectedCullRate(cones.data(), triangles.data(), partition.clusterCount);
}

}  // namespace conescope
