// Partitions written by partition -o read back as the same partition, in every format; meshlets
// made by the linked meshoptimizer itself read back with its meshlet count; a polygon meshlets
// split is cut into their triangles.
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include "IoTestSupport.h"
#include "core/BuildPartition.h"
#include "core/FileBuilder.h"
#include "core/MeshletArrays.h"
#include "io/ClusterFiles.h"
#include "io/ClusterIdFile.h"
#include "io/MeshReader.h"
#include "io/MeshletFiles.h"
#include "core/meshopt/Reproduction.h"

namespace conescope {
namespace {

using testing::datasetsDir;
using testing::ScratchDirectory;

// A partition as sets of triangles (sorted world corners), so partitions of meshes whose faces
// come in another order or as fan triangles compare equal.
using Corner = std::array<float, 3>;
using Triangle = std::array<Corner, 3>;
std::set<std::set<Triangle>> clustersAsTriangles(const Mesh& mesh, const Partition& partition) {
    std::vector<std::set<Triangle>> clusters(partition.clusterCount);
    auto corner = [&](uint32_t v) { return Corner{mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z}; };
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* face = mesh.faceBegin(f);
        for (size_t k = 1; k + 1 < mesh.faceSize(f); ++k) {
            Triangle t{corner(face[0]), corner(face[k]), corner(face[k + 1])};
            std::sort(t.begin(), t.end());
            clusters[partition.clusterOfFace[f]].insert(t);
        }
    }
    return {clusters.begin(), clusters.end()};
}

// The file builder's partition of a mesh with this cluster file ("" for the mesh's own clusters),
// as a front end reads it: ids into the settings, a meshlet file onto the mesh.
Settings fileSettings(const std::string& clusterFile) {
    Settings settings;
    settings.builder = Builder::File;
    settings.clusterFile = clusterFile;
    return withClusterIds(settings);
}

Partition filePartition(const Mesh& mesh, const std::string& clusterFile) {
    return buildPartition(mesh, computeFaceGeometry(mesh), fileSettings(clusterFile));
}

Partition readBack(const std::string& meshPath, const std::string& clusterFile) {
    MeshFile file = readMeshFile(meshPath);
    const Settings settings = fileSettings(clusterFile);
    readClusterFileOf(file.mesh, settings, file.notes);
    return buildPartition(file.mesh, computeFaceGeometry(file.mesh), settings);
}

Settings meshoptSettings() {
    Settings settings;
    settings.builder = Builder::Meshopt;
    return settings;
}

TEST(PartitionFiles, EveryFormatReadsBackTheSamePartition) {
    ScratchDirectory scratch;
    for (const char* name : {"elephant.off", "hexagonal-prism.off", "cube-quads.off", "torus.off"}) {
        const std::string meshPath = (datasetsDir() / name).string();
        const Mesh mesh = readMesh(meshPath);
        Settings settings = meshoptSettings();
        settings.limits.maxTriangles = 8;  // several clusters even on the small meshes
        const Partition partition = buildPartition(mesh, computeFaceGeometry(mesh), settings);
        const auto expected = clustersAsTriangles(mesh, partition);
        for (const char* extension : {".json", ".meshlets", ".txt", ".obj", ".gltf", ".vtp"}) {
            SCOPED_TRACE(std::string(name) + " as " + extension);
            const std::string out = scratch.file(std::string("partition") + extension);
            writePartitionFile(mesh, partition, out);
            const bool ownMesh = std::string(extension) == ".obj" || std::string(extension) == ".gltf" || std::string(extension) == ".vtp";
            const std::string readPath = ownMesh ? out : meshPath;
            const Mesh again = ownMesh ? readMesh(out) : mesh;
            const Partition back = readBack(readPath, ownMesh ? "" : out);
            EXPECT_EQ(back.clusterCount, partition.clusterCount);
            if (!ownMesh) {
                EXPECT_EQ(back.clusterOfFace, partition.clusterOfFace) << "meshlet c is cluster c";
                continue;
            }
            MeshFile file = readMeshFile(readPath);
            EXPECT_EQ(clustersAsTriangles(file.mesh, filePartition(file.mesh, "")), expected);
        }
    }
}

// What meshopt_buildMeshlets and meshopt_computeMeshletBounds give for the file's triangles, as an
// engine would export them.
MeshletArrays libraryMeshlets(const Mesh& mesh, size_t maxVertices, size_t maxTriangles) {
    const std::vector<uint32_t> indices = fanTriangles(mesh);
    const size_t bound = meshopt_buildMeshletsBound(indices.size(), maxVertices, maxTriangles);
    std::vector<meshopt_Meshlet> meshlets(bound);
    MeshletArrays arrays;
    arrays.vertices.resize(bound * maxVertices);
    arrays.triangles.resize(bound * maxTriangles * 3);
    const size_t count = meshopt_buildMeshlets(meshlets.data(), arrays.vertices.data(), arrays.triangles.data(), indices.data(), indices.size(),
                                               &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3), maxVertices, maxTriangles, 1.0f);
    for (size_t m = 0; m < count; ++m) {
        const meshopt_Meshlet& meshlet = meshlets[m];
        arrays.meshlets.push_back({meshlet.vertex_offset, meshlet.triangle_offset, meshlet.vertex_count, meshlet.triangle_count});
        const meshopt_Bounds b = meshopt_computeMeshletBounds(&arrays.vertices[meshlet.vertex_offset], &arrays.triangles[meshlet.triangle_offset],
                                                              meshlet.triangle_count, &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3));
        MeshletBounds bounds;
        std::copy(b.center, b.center + 3, bounds.center.begin());
        bounds.radius = b.radius;
        bounds.coneCutoff = b.cone_cutoff;
        bounds.coneCutoffS8 = b.cone_cutoff_s8;
        arrays.bounds.push_back(bounds);
    }
    const meshopt_Meshlet& last = meshlets[count - 1];
    arrays.vertices.resize(last.vertex_offset + last.vertex_count);
    arrays.triangles.resize(last.triangle_offset + ((last.triangle_count * 3 + 3) & ~3u));
    return arrays;
}

TEST(PartitionFiles, MeshoptimizersOwnMeshletsLoadWithItsCount) {
    ScratchDirectory scratch;
    const std::string meshPath = (datasetsDir() / "elephant.off").string();
    const Mesh mesh = readMesh(meshPath);
    const MeshletArrays arrays = libraryMeshlets(mesh, 64, 124);
    const std::string json = scratch.writeFile("elephant.json", meshletJson(arrays));
    const std::string binary = scratch.writeFile("elephant.meshlets", meshletBinary(arrays));
    const Partition library = meshoptLibraryMeshlets(mesh, {64, 124}, 1.0f);
    for (const std::string& path : {json, binary}) {
        MeshFile file = readMeshFile(meshPath);
        readClusterFile(file.mesh, path, file.notes);
        EXPECT_EQ(file.mesh.fileClusters.at(path).clusterCount, arrays.meshlets.size());
        EXPECT_EQ(file.mesh.fileClusters.at(path).bounds.size(), arrays.meshlets.size()) << "the stored bounds come along";
        EXPECT_EQ(clustersAsTriangles(mesh, filePartition(file.mesh, path)), clustersAsTriangles(mesh, library));
    }
}

TEST(PartitionFiles, MeshletsThatSplitAPolygonCutIt) {
    // The quad cube's faces as fan triangles in meshlets of at most 4 triangles: meshoptimizer
    // splits some squares between meshlets.
    const std::string meshPath = (datasetsDir() / "cube-quads.off").string();
    const Mesh mesh = readMesh(meshPath);
    const MeshletArrays arrays = libraryMeshlets(mesh, 6, 4);
    Mesh applied = mesh;
    const AppliedMeshlets meshlets = applyMeshlets(applied, arrays);
    ASSERT_GT(meshlets.cutPolygons, 0u) << "this case needs a split square";
    EXPECT_EQ(applied.faceCount(), mesh.faceCount() + meshlets.cutPolygons);
    EXPECT_EQ(triangleCount(applied), triangleCount(mesh));
    EXPECT_EQ(meshlets.clusters.clusterCount, arrays.meshlets.size());
    // Each piece keeps its square's outward normal.
    const FaceGeometry before = computeFaceGeometry(mesh), after = computeFaceGeometry(applied);
    for (size_t f = 0; f < applied.faceCount(); ++f) {
        const glm::dvec3 centroid = after.centroids[f];
        size_t nearest = 0;
        for (size_t g = 0; g < mesh.faceCount(); ++g)
            if (glm::length(before.centroids[g] - centroid) < glm::length(before.centroids[nearest] - centroid)) nearest = g;
        EXPECT_GT(glm::dot(after.normals[f], before.normals[nearest]), 0.99) << "piece " << f;
    }
    // Read as a cluster file it says so, and the partition is exactly the meshlets'.
    ScratchDirectory scratch;
    const std::string path = scratch.writeFile("cube.json", meshletJson(arrays));
    MeshFile file = readMeshFile(meshPath);
    readClusterFile(file.mesh, path, file.notes);
    ASSERT_FALSE(file.notes.empty());
    EXPECT_NE(file.notes.back().find("cut into the triangles"), std::string::npos) << file.notes.back();
    EXPECT_EQ(filePartition(file.mesh, path).clusterCount, arrays.meshlets.size());
}

TEST(PartitionFiles, ObjGroupsAndGltfPrimitivesAreClusters) {
    ScratchDirectory scratch;
    const std::string obj = scratch.writeFile("groups.obj",
                                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                                              "f 1 2 3\no a\nf 1 3 4\ng x\nf 2 5 6\no b\nf 2 6 3\no a\ng x\nf 3 6 4\n");
    const Mesh mesh = readMesh(obj);
    // Before any group, (a), (a, x), (b, x), (a, x) again.
    EXPECT_EQ(mesh.faceArrays.at("group_id"), (std::vector<double>{0, 1, 2, 3, 2}));
    EXPECT_EQ(filePartition(mesh, "").clusterOfFace, (std::vector<uint32_t>{0, 1, 2, 3, 2}));
    const Mesh plain = readMesh((datasetsDir() / "elephant.off").string());
    EXPECT_FALSE(meshHasOwnClusters(plain));
    EXPECT_THROW(filePartition(plain, ""), std::runtime_error);
    EXPECT_THROW(filePartition(plain, "never-read.json"), std::exception);
}

TEST(PartitionFiles, WritingRefusesClustersMeshletsCannotHold) {
    const Mesh mesh = readMesh((datasetsDir() / "elephant.off").string());
    const Partition one{std::vector<uint32_t>(mesh.faceCount(), 0), 1};  // every vertex in one cluster
    ScratchDirectory scratch;
    try {
        writePartitionFile(mesh, one, scratch.file("one.json"));
        FAIL() << "a cluster of 2775 vertices was written as a meshlet";
    } catch (const std::exception& error) {
        EXPECT_NE(std::string(error.what()).find("one.json: cluster 0: vertex_count 2775 is above 255"), std::string::npos) << error.what();
    }
    writePartitionFile(mesh, one, scratch.file("one.obj"));  // any cluster fits an OBJ group
}

}  // namespace
}  // namespace conescope
