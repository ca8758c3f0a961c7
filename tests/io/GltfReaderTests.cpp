// glTF 2.0 and GLB files that must read: the hand-written samples of tests/data/gltf
// (make_gltf_samples.py), with counts, positions and face orientations checked by hand.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "GltfTestSupport.h"
#include "core/Culling.h"
#include "core/MeshChecks.h"
#include "core/Views.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using nlohmann::json;
using testing::changedGltf;
using testing::gltfSample;
using testing::ScratchDirectory;

MeshReport reportOf(const Mesh& mesh) { return checkMesh(mesh, computeFaceGeometry(mesh)); }

// Every face's normal points away from the centre of the unit-cube instance it belongs to, which
// `centreOf` names for a face centroid: outward under the counter-clockwise convention.
void expectOutward(const Mesh& mesh, const std::function<glm::dvec3(const glm::dvec3&)>& centreOf) {
    const FaceGeometry faces = computeFaceGeometry(mesh);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        ASSERT_FALSE(faces.degenerate[f]) << "face " << f;
        const glm::dvec3 outward = faces.centroids[f] - centreOf(faces.centroids[f]);
        EXPECT_GT(glm::dot(faces.normals[f], outward), 0.0) << "face " << f << " points inward";
    }
}

void expectOutwardFromOrigin(const Mesh& mesh) {
    expectOutward(mesh, [](const glm::dvec3&) { return glm::dvec3(0.0); });
}

// True when `points` and `expected` hold the same points, each within 1e-5, none twice.
void expectSamePoints(std::vector<glm::vec3> points, std::vector<glm::dvec3> expected) {
    ASSERT_EQ(points.size(), expected.size());
    for (const glm::dvec3& point : expected) {
        auto match = std::find_if(points.begin(), points.end(), [&](const glm::vec3& p) {
            return glm::length(glm::dvec3(p) - point) < 1e-5;
        });
        ASSERT_NE(match, points.end()) << "no vertex at " << point.x << " " << point.y << " " << point.z;
        points.erase(match);
    }
}

// The unit cube's 8 corners, each carried by `place`.
std::vector<glm::dvec3> placedCorners(const std::function<glm::dvec3(double, double, double)>& place) {
    std::vector<glm::dvec3> corners;
    for (int i = 0; i < 8; ++i) corners.push_back(place(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5));
    return corners;
}

// The file reads with `faces` faces and says exactly `note`.
void expectFacesAndNote(const std::string& path, size_t faces, const std::string& note) {
    const MeshFile file = readMeshFile(path);
    EXPECT_EQ(file.mesh.faceCount(), faces);
    EXPECT_EQ(file.notes, std::vector<std::string>{note});
}

class GltfCube : public ::testing::TestWithParam<const char*> {};

// cube.gltf (external .bin), cube-embedded.gltf (base64 data URI), cube.glb (BIN chunk), 8-, 16-
// and 32-bit indices, and no indices: 24 or 36 vertices split at the face seams, merged to the
// cube's 8 corners, 12 outward triangles, one closed component.
TEST_P(GltfCube, ReadsAsOneClosedCubeOfEightMergedVertices) {
    const MeshFile file = readMeshFile(gltfSample(GetParam()));
    const Mesh& mesh = file.mesh;
    EXPECT_TRUE(file.notes.empty());
    EXPECT_EQ(mesh.model, glm::dmat4(1.0));
    ASSERT_EQ(mesh.faceCount(), 12u);
    for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_EQ(mesh.faceSize(f), 3u);
    expectSamePoints(mesh.positions, placedCorners([](double x, double y, double z) { return glm::dvec3(x, y, z); }));
    const MeshReport report = reportOf(mesh);
    EXPECT_EQ(report.components, 1u);
    EXPECT_EQ(report.openEdges, 0u);
    EXPECT_EQ(report.inconsistentEdges, 0u);
    expectOutwardFromOrigin(mesh);
}

INSTANTIATE_TEST_SUITE_P(Containers, GltfCube,
                         ::testing::Values("cube.gltf", "cube-embedded.gltf", "cube.glb", "cube-u8.gltf",
                                           "cube-u32.gltf", "cube-unindexed.gltf"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             std::string name = info.param;
                             std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                             return name;
                         });

// Walls as two strips (indexed and not), caps as two fans (indexed and not): the glTF triangle order
// of strips and fans keeps every triangle outward.
TEST(GltfReader, StripsAndFansKeepTheirWinding) {
    const Mesh mesh = readMesh(gltfSample("strips-fans.gltf"));
    ASSERT_EQ(mesh.faceCount(), 12u);
    EXPECT_EQ(mesh.positions.size(), 8u);
    const MeshReport report = reportOf(mesh);
    EXPECT_EQ(report.components, 1u);
    EXPECT_EQ(report.openEdges, 0u);
    EXPECT_EQ(report.inconsistentEdges, 0u);
    EXPECT_EQ(report.duplicateFaces, 0u);
    expectOutwardFromOrigin(mesh);
}

// A sparse accessor replaces the 12 top corners of the split cube: a box from z = -0.5 to 1.5.
TEST(GltfReader, SparseAccessorsReplaceTheirElements) {
    const Mesh mesh = readMesh(gltfSample("sparse.gltf"));
    ASSERT_EQ(mesh.faceCount(), 12u);
    expectSamePoints(mesh.positions, placedCorners([](double x, double y, double z) {
                         return glm::dvec3(x, y, z > 0 ? 1.5 : z);
                     }));
    EXPECT_EQ(reportOf(mesh).components, 1u);
    expectOutward(mesh, [](const glm::dvec3&) { return glm::dvec3(0, 0, 0.5); });
}

// One mesh, two nodes: twice the triangles, each copy at its node's translation.
TEST(GltfReader, AMeshUsedByTwoNodesCountsTwice) {
    const Mesh mesh = readMesh(gltfSample("instanced.gltf"));
    EXPECT_EQ(mesh.faceCount(), 24u);
    EXPECT_EQ(reportOf(mesh).components, 2u);
    std::vector<glm::dvec3> expected = placedCorners([](double x, double y, double z) { return glm::dvec3(x + 2, y, z); });
    for (const glm::dvec3& p : placedCorners([](double x, double y, double z) { return glm::dvec3(x - 2, y, z); }))
        expected.push_back(p);
    expectSamePoints(mesh.positions, expected);
    expectOutward(mesh, [](const glm::dvec3& c) { return glm::dvec3(c.x > 0 ? 2.0 : -2.0, 0.0, 0.0); });
}

// Node 0: scale (2, 1, 1), then 90 degrees about z, then +5 in z; its child: +2 in x in node 0's
// frame; node 1: the column-major matrix of scale 3 then +10 in x. Worked out by hand.
TEST(GltfReader, TrsMatrixAndChildTransformsAreComposed) {
    const Mesh mesh = readMesh(gltfSample("transforms.gltf"));
    EXPECT_EQ(mesh.faceCount(), 36u);
    EXPECT_EQ(reportOf(mesh).components, 3u);
    std::vector<glm::dvec3> expected;
    for (auto place : std::vector<std::function<glm::dvec3(double, double, double)>>{
             [](double x, double y, double z) { return glm::dvec3(-y, 2 * x, z + 5); },
             [](double x, double y, double z) { return glm::dvec3(-y, 2 * (x + 2), z + 5); },
             [](double x, double y, double z) { return glm::dvec3(3 * x + 10, 3 * y, 3 * z); }})
        for (const glm::dvec3& p : placedCorners(place)) expected.push_back(p);
    expectSamePoints(mesh.positions, expected);
    expectOutward(mesh, [](const glm::dvec3& c) {
        return c.x > 5 ? glm::dvec3(10, 0, 0) : c.y > 2 ? glm::dvec3(0, 4, 5) : glm::dvec3(0, 0, 5);
    });
}

// Meshlet files index the file's vertices as read (Mesh::fileVertices): for glTF, each placed
// primitive's POSITION vertices one after another, nodes in a depth-first walk of the scene (a
// node, then its children), not in the order of the nodes array. transforms.gltf lists the child
// first; the walk places the TRS node (centre (0, 0, 5)), its child ((0, 4, 5)), then the matrix node.
TEST(GltfReader, FileVerticesFollowTheDepthFirstWalkOfTheScene) {
    const Mesh mesh = readMesh(gltfSample("transforms.gltf"));
    ASSERT_EQ(mesh.fileVertices.size(), 72u);
    const glm::dvec3 centres[] = {{0, 0, 5}, {0, 4, 5}, {10, 0, 0}};
    for (size_t instance = 0; instance < 3; ++instance) {
        glm::dvec3 sum(0.0);
        for (size_t v = 24 * instance; v < 24 * (instance + 1); ++v) sum += glm::dvec3(mesh.positions[mesh.fileVertices[v]]);
        const glm::dvec3 centre = sum / 24.0;
        EXPECT_LT(glm::length(centre - centres[instance]), 1e-5) << "instance " << instance;
    }
}

// The cube at x = 3 under a mirror scale (-1, 1, 1): it lands at x = -3 and, its triangles turned,
// every face still points out. From an eye in front of its +z face, exactly that face's two
// triangles face the eye (by the core's per-face oracle); the other ten face away.
TEST(GltfReader, AMirroredNodeKeepsOutwardFaces) {
    const Mesh mesh = readMesh(gltfSample("mirrored.gltf"));
    ASSERT_EQ(mesh.faceCount(), 12u);
    expectSamePoints(mesh.positions, placedCorners([](double x, double y, double z) { return glm::dvec3(x - 3, y, z); }));
    expectOutward(mesh, [](const glm::dvec3&) { return glm::dvec3(-3, 0, 0); });
    EXPECT_EQ(reportOf(mesh).inconsistentEdges, 0u);

    const FaceGeometry faces = computeFaceGeometry(mesh);
    const std::vector<Facing> facing = classifyFaces(mesh, worldPositions(mesh), faces, Eye::perspective({-3, 0, 3}));
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const bool onFrontFace = faces.centroids[f].z > 0.49;
        EXPECT_EQ(facing[f], onFrontFace ? Facing::Front : Facing::Back) << "face " << f;
    }
}

// A matrix that swaps x and y (determinant -1) mirrors too.
TEST(GltfReader, AMirroringMatrixKeepsOutwardFaces) {
    ScratchDirectory scratch;
    const std::string path = changedGltf(scratch, "cube.gltf", "swap.gltf", [](json& d) {
        d["nodes"][0]["matrix"] = {0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 4, 1};
    });
    const Mesh mesh = readMesh(path);
    ASSERT_EQ(mesh.faceCount(), 12u);
    expectOutward(mesh, [](const glm::dvec3&) { return glm::dvec3(0, 0, 4); });
}

TEST(GltfReader, PointsAndLinesAreSkippedWithANote) {
    expectFacesAndNote(gltfSample("lines-points.gltf"), 12, "Skipped 3 primitives of points or lines: they have no faces.");
}

// The default scene: "scene" when given, else scene 0, else every root node.
TEST(GltfReader, ReadsTheDefaultScene) {
    ScratchDirectory scratch;
    auto twoScenes = [](json& d) { d["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1}}}}); };
    const Mesh chosen = readMesh(changedGltf(scratch, "instanced.gltf", "chosen.gltf", [&](json& d) {
        twoScenes(d);
        d["scene"] = 1;
    }));
    const Mesh first = readMesh(changedGltf(scratch, "instanced.gltf", "first.gltf", [&](json& d) {
        twoScenes(d);
        d.erase("scene");
    }));
    const Mesh roots = readMesh(changedGltf(scratch, "instanced.gltf", "roots.gltf", [](json& d) {
        d.erase("scene");
        d.erase("scenes");
    }));
    EXPECT_EQ(chosen.faceCount(), 12u);
    EXPECT_LT(computeAabb(chosen.positions).max.x, 0.0f);
    EXPECT_EQ(first.faceCount(), 12u);
    EXPECT_GT(computeAabb(first.positions).min.x, 0.0f);
    EXPECT_EQ(roots.faceCount(), 24u);
}

TEST(GltfReader, ATriangleListWithVerticesLeftOverKeepsItsWholeTrianglesWithANote) {
    ScratchDirectory scratch;
    const std::string path = changedGltf(scratch, "cube-unindexed.gltf", "leftover.gltf", [](json& d) {
        for (json& accessor : d["accessors"]) accessor["count"] = 35;
    });
    expectFacesAndNote(path, 11, "1 triangle list ends with 1 or 2 vertices that make no whole triangle; they were ignored.");
}

TEST(GltfReader, AStripTooShortForATriangleIsSkippedWithANote) {
    ScratchDirectory scratch;
    const std::string path = changedGltf(scratch, "cube.gltf", "short.gltf", [](json& d) {
        d["accessors"].push_back({{"bufferView", 2}, {"componentType", 5123}, {"count", 2}, {"type", "SCALAR"}});
        d["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"indices", 3}, {"mode", 5}});
    });
    expectFacesAndNote(path, 12, "Skipped 1 triangle primitive with fewer than 3 vertices.");
}

// Buffer URIs are URI references: "%20" is a space in the file name.
TEST(GltfReader, BufferUrisArePercentDecoded) {
    ScratchDirectory scratch;
    const std::string path = changedGltf(scratch, "cube.gltf", "spaced.gltf", [](json& d) {
        d["buffers"][0]["uri"] = "cube%20data.bin";
    });
    std::filesystem::rename(scratch.path() / "cube.bin", scratch.path() / "cube data.bin");
    EXPECT_EQ(readMesh(path).faceCount(), 12u);
}

TEST(GltfReader, ExtensionsAreCaseInsensitive) {
    ScratchDirectory scratch;
    std::filesystem::copy_file(testing::gltfSamplesDir() / "cube.glb", scratch.path() / "CUBE.GLB");
    EXPECT_EQ(readMesh(scratch.file("CUBE.GLB")).faceCount(), 12u);
}

// A required extension that only changes materials does not stop the geometry from being read.
TEST(GltfReader, RequiredMaterialExtensionsDoNotMatter) {
    ScratchDirectory scratch;
    const std::string path = changedGltf(scratch, "cube.gltf", "material.gltf", [](json& d) {
        d["extensionsUsed"] = d["extensionsRequired"] = {"KHR_materials_unlit", "KHR_texture_transform"};
    });
    EXPECT_EQ(readMesh(path).faceCount(), 12u);
}

TEST(GltfReader, ReportsProgressAndCanBeCancelledInEachStage) {
    std::vector<std::pair<double, std::string>> reports;
    const MeshFile file = readMeshFile(gltfSample("cube.glb"), [&](double fraction, const std::string& stage) {
        reports.emplace_back(fraction, stage);
        return true;
    });
    EXPECT_EQ(file.mesh.faceCount(), 12u);
    ASSERT_GE(reports.size(), 4u);
    for (size_t i = 1; i < reports.size(); ++i) EXPECT_GE(reports[i].first, reports[i - 1].first);
    std::vector<std::string> stages;
    for (const auto& report : reports)
        if (stages.empty() || stages.back() != report.second) stages.push_back(report.second);
    EXPECT_EQ(stages, (std::vector<std::string>{"reading glTF", "decoding glTF buffers", "placing glTF instances"}));
    for (const std::string& stage : stages) {
        EXPECT_THROW(readMeshFile(gltfSample("cube.glb"), [&](double, const std::string& current) { return current != stage; }),
                     OperationCancelled)
            << stage;
    }
}

}  // namespace
}  // namespace conescope
