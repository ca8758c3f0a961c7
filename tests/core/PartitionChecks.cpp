#include "PartitionChecks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/meshopt/Meshopt.h"

namespace conescope {

namespace {

// How full a partition's clusters are: how many hold more than the limits, and the most
// vertices and triangles one holds.
struct Fill {
    size_t overLimits = 0, vertices = 0, triangles = 0;
};
Fill fillOf(const Mesh& mesh, const Partition& partition, const MeshletLimits& limits) {
    const ClusterFaces rows = facesByCluster(partition);
    Fill fill;
    for (uint32_t c = 0; c < partition.clusterCount; ++c) {
        std::set<uint32_t> vertices;
        size_t triangles = 0;
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            triangles += mesh.faceSize(rows.faces[i]) - 2;
            vertices.insert(mesh.faceBegin(rows.faces[i]), mesh.faceBegin(rows.faces[i]) + mesh.faceSize(rows.faces[i]));
        }
        fill.overLimits += vertices.size() > limits.maxVertices || triangles > limits.maxTriangles;
        fill.vertices = std::max(fill.vertices, vertices.size());
        fill.triangles = std::max(fill.triangles, triangles);
    }
    return fill;
}

}  // namespace

// Every face in exactly one non-empty cluster, each cluster within both limits.
void expectValidWithinLimits(const Mesh& mesh, const Partition& partition, const MeshletLimits& limits) {
    ASSERT_EQ(partition.clusterOfFace.size(), mesh.faceCount());
    for (uint32_t id : partition.clusterOfFace) ASSERT_LT(id, partition.clusterCount);
    const ClusterFaces rows = facesByCluster(partition);
    for (uint32_t c = 0; c < partition.clusterCount; ++c) {
        ASSERT_GT(rows.starts[c + 1], rows.starts[c]) << "empty cluster " << c;
        std::set<uint32_t> vertices;
        size_t triangles = 0;
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            const uint32_t f = rows.faces[i];
            triangles += mesh.faceSize(f) - 2;
            vertices.insert(mesh.faceBegin(f), mesh.faceBegin(f) + mesh.faceSize(f));
        }
        EXPECT_LE(vertices.size(), limits.maxVertices) << "cluster " << c;
        EXPECT_LE(triangles, limits.maxTriangles) << "cluster " << c;
    }
}

// On polygon meshes meshoptimizer's meshlets split polygons, and its partition of whole faces
// holds more than the limits where they join a full meshlet: the default has its count, never
// more clusters over the limits nor a larger one (and holds the limits where meshoptimizer does).
void expectMeshoptimizersCountAndFill(const Mesh& mesh, const Partition& partition, const MeshletLimits& limits) {
    ASSERT_EQ(partition.clusterOfFace.size(), mesh.faceCount());
    const Partition meshopt = buildMeshoptMeshlets(mesh, limits, 1.0f);
    EXPECT_EQ(partition.clusterCount, meshopt.clusterCount);
    const Fill ours = fillOf(mesh, partition, limits), theirs = fillOf(mesh, meshopt, limits);
    EXPECT_LE(ours.overLimits, theirs.overLimits);
    EXPECT_LE(ours.vertices, std::max<size_t>(limits.maxVertices, theirs.vertices));
    EXPECT_LE(ours.triangles, std::max<size_t>(limits.maxTriangles, theirs.triangles));
}

// Number of clusters whose faces do not form one piece across shared edges.
size_t disconnectedClusters(const Mesh& mesh, const Partition& partition) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> facesOfEdge;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 0; k < mesh.faceSize(f); ++k) {
            const uint32_t a = mesh.faceBegin(f)[k], b = mesh.faceBegin(f)[(k + 1) % mesh.faceSize(f)];
            facesOfEdge[std::minmax(a, b)].push_back(f);
        }
    std::vector<uint32_t> parent(mesh.faceCount());
    for (uint32_t f = 0; f < parent.size(); ++f) parent[f] = f;
    auto root = [&](uint32_t f) {
        while (parent[f] != f) f = parent[f] = parent[parent[f]];
        return f;
    };
    for (const auto& [edge, faces] : facesOfEdge)
        for (size_t i = 1; i < faces.size(); ++i)
            if (partition.clusterOfFace[faces[0]] == partition.clusterOfFace[faces[i]]) parent[root(faces[0])] = root(faces[i]);
    std::vector<std::set<uint32_t>> pieces(partition.clusterCount);
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) pieces[partition.clusterOfFace[f]].insert(root(f));
    return size_t(std::count_if(pieces.begin(), pieces.end(), [](const std::set<uint32_t>& p) { return p.size() > 1; }));
}

}  // namespace conescope
