#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "TestMeshes.h"
#include "core/BuildPartition.h"
#include "core/ClusterBounds.h"
#include "core/meshopt/Meshopt.h"

using namespace conescope;

namespace {
void expectWithinLimits(const Mesh& mesh, const Partition& partition, const MeshletLimits& limits) {
    ASSERT_EQ(partition.clusterOfFace.size(), mesh.faceCount());
    const ClusterFaces rows = facesByCluster(partition);
    for (uint32_t c = 0; c < partition.clusterCount; ++c) {
        std::set<uint32_t> vertices;
        size_t triangles = 0;
        ASSERT_GT(rows.starts[c + 1], rows.starts[c]) << "empty cluster " << c;
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            const uint32_t f = rows.faces[i];
            triangles += mesh.faceSize(f) - 2;
            vertices.insert(mesh.faceBegin(f), mesh.faceBegin(f) + mesh.faceSize(f));
        }
        EXPECT_LE(vertices.size(), limits.maxVertices);
        EXPECT_LE(triangles, limits.maxTriangles);
    }
}
}  // namespace

TEST(Partition, MeshletsRespectLimits) {
    const Mesh mesh = testmesh::torus(1.0, 0.3, 64, 32);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    for (MeshletLimits limits : {MeshletLimits{64, 124}, MeshletLimits{32, 64}, MeshletLimits{128, 256}, MeshletLimits{3, 1}}) {
        const Partition partition = buildMeshlets(mesh, faces, limits);
        expectWithinLimits(mesh, partition, limits);
        EXPECT_LE(partition.clusterCount, mesh.faceCount());
        // Not absurdly many clusters: at least half full on average.
        EXPECT_LE(partition.clusterCount, 2 * (mesh.faceCount() + limits.maxTriangles - 1) / limits.maxTriangles + 2);
    }
}

TEST(Partition, MeshletsPreferNarrowCones) {
    const Mesh mesh = testmesh::icosphere(4);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const auto world = worldPositions(mesh);
    auto meanAngle = [&](const Partition& partition) {
        const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
        double sum = 0;
        for (const auto& cone : bounds.cones) sum += cone.halfAngle();
        return sum / double(bounds.count());
    };
    const Partition shaped = buildMeshlets(mesh, faces, {}, 1.0);
    const Partition local = buildMeshlets(mesh, faces, {}, 0.0);
    EXPECT_LE(meanAngle(shaped), meanAngle(local) * 1.05);
}

TEST(Partition, KMeansReachesTheTarget) {
    const Mesh mesh = testmesh::icosphere(3);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition partition = buildKMeans(mesh, faces, 40);
    EXPECT_GE(partition.clusterCount, 30u);
    EXPECT_LE(partition.clusterCount, 40u);
    for (uint32_t id : partition.clusterOfFace) EXPECT_LT(id, partition.clusterCount);
}

TEST(Partition, MeshoptMeshletsCoverEveryFaceWithinLimits) {
    const Mesh mesh = testmesh::torus(1.0, 0.3, 64, 32);
    const MeshletLimits limits{64, 124};
    const Partition partition = buildMeshoptMeshlets(mesh, limits, 0.5f);
    expectWithinLimits(mesh, partition, limits);
    EXPECT_THROW(buildMeshoptMeshlets(mesh, {300, 124}, 0.5f), std::invalid_argument);
}

TEST(Partition, IdsGivenPerFace) {
    const Partition partition = partitionFromIds({7, 7, 3, 9, 3}, 5, "test");
    EXPECT_EQ(partition.clusterCount, 3u);
    EXPECT_EQ(partition.clusterOfFace, (std::vector<uint32_t>{0, 0, 1, 2, 1}));
    EXPECT_THROW(partitionFromIds({1, 2}, 3, "test"), std::runtime_error);
    EXPECT_THROW(partitionFromIds({1, -2, 3}, 3, "test"), std::runtime_error);
    EXPECT_THROW(partitionFromIds({1, 2.5, 3}, 3, "test"), std::runtime_error);
}

// The file builder takes a cluster file's ids as io read them (tests/io/ClusterIdFileTests.cpp):
// core reads no file, and says so when nobody read it.
TEST(Partition, TheFileBuilderTakesTheIdsIoRead) {
    const Mesh mesh = testmesh::icosphere(0);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    Settings settings;
    settings.builder = Builder::File;
    settings.clusterFile = "ids.txt";
    EXPECT_THROW(buildPartition(mesh, faces, settings), std::logic_error);
    auto file = std::make_shared<ClusterIdFile>();
    file->path = "ids.txt";
    for (size_t f = 0; f < mesh.faceCount(); ++f) file->ids.push_back(double(f % 3));
    settings.clusterIds = file;
    EXPECT_EQ(buildPartition(mesh, faces, settings).clusterCount, 3u);
    file->error = "ids.txt: cannot open cluster id file";
    try {
        buildPartition(mesh, faces, settings);
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "ids.txt: cannot open cluster id file");
    }
    settings.clusterFile = "other.txt";  // ids read for another file are not this one's
    EXPECT_THROW(buildPartition(mesh, faces, settings), std::logic_error);
}
