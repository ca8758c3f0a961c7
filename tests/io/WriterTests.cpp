// Writers: what readMesh gets back is what was written (geometry exactly, per-face arrays for VTK).
#include <fstream>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"

namespace conescope {
namespace {

using testing::datasetsDir;
using testing::ScratchDirectory;

void expectSameGeometry(const Mesh& actual, const Mesh& expected) {
    EXPECT_EQ(actual.positions, expected.positions);
    EXPECT_EQ(actual.faceStarts, expected.faceStarts);
    EXPECT_EQ(actual.faceVertices, expected.faceVertices);
}

std::vector<double> clusterIdsByOctant(const Mesh& mesh) {
    std::vector<double> clusterIds;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        glm::vec3 p = mesh.positions[mesh.faceBegin(f)[0]];
        clusterIds.push_back((p.x > 0 ? 1 : 0) + (p.y > 0 ? 2 : 0) + (p.z > 0 ? 4 : 0));
    }
    return clusterIds;
}

TEST(WriteOff, RoundTripsExactly) {
    Mesh sphere = readMesh((datasetsDir() / "icosphere.off").string());
    ScratchDirectory scratch;
    writeOff(sphere, scratch.file("sphere.off"));
    expectSameGeometry(readMesh(scratch.file("sphere.off")), sphere);
}

TEST(WriteOff, KeepsPolygons) {
    Mesh prism = readMesh((datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    writeOff(prism, scratch.file("prism.off"));
    expectSameGeometry(readMesh(scratch.file("prism.off")), prism);
}

TEST(WriteOff, IsIndependentOfTheLocale) {
    Mesh sphere = readMesh((datasetsDir() / "icosphere.off").string());
    ScratchDirectory scratch;
    {
        testing::ScopedCommaDecimalLocale german;
        writeOff(sphere, scratch.file("sphere.off"));
        writePolyData(sphere, scratch.file("sphere.vtk"), {{"weight", std::vector<double>(sphere.faceCount(), 0.5)}});
    }
    expectSameGeometry(readMesh(scratch.file("sphere.off")), sphere);
    Mesh legacy = readMesh(scratch.file("sphere.vtk"));
    expectSameGeometry(legacy, sphere);
    EXPECT_EQ(legacy.faceArrays.at("weight"), std::vector<double>(sphere.faceCount(), 0.5));
}

class PolyDataRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(PolyDataRoundTrip, KeepsGeometryAndClusterIds) {
    Mesh torus = readMesh((datasetsDir() / "torus.off").string());
    std::vector<double> clusterIds = clusterIdsByOctant(torus);
    ScratchDirectory scratch;
    std::string path = scratch.file(std::string("torus") + GetParam());
    writePolyData(torus, path, {{"cluster_id", clusterIds}});
    Mesh back = readMesh(path);
    expectSameGeometry(back, torus);
    ASSERT_EQ(back.faceArrays.count("cluster_id"), 1u);
    EXPECT_EQ(back.faceArrays.at("cluster_id"), clusterIds);
}

TEST_P(PolyDataRoundTrip, KeepsPolygonsFractionalArraysAndTheModelMatrix) {
    Mesh prism = readMesh((datasetsDir() / "hexagonal-prism.off").string());
    prism.faceArrays["weight"] = {0.1, -2.5, 1e-30, 3.0, 4.75, 5.0, 1e30, -0.0};
    prism.model = glm::dmat4(0.5);
    prism.model[3] = glm::dvec4(0.1, 0.2, 0.3, 1.0);
    ScratchDirectory scratch;
    std::string path = scratch.file(std::string("prism") + GetParam());
    writePolyData(prism, path);
    Mesh back = readMesh(path);
    expectSameGeometry(back, prism);
    EXPECT_EQ(back.faceArrays, prism.faceArrays);
    EXPECT_EQ(back.model, prism.model);
}

INSTANTIATE_TEST_SUITE_P(Formats, PolyDataRoundTrip, ::testing::Values(".vtp", ".vtk", ".VTP"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             return std::string(info.param + 1) + (info.index == 2 ? "_upper" : "");
                         });

TEST(WritePolyData, PlyAndOffKeepGeometry) {
    Mesh prism = readMesh((datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    for (const char* name : {"prism.ply", "prism-too.off"}) {
        writePolyData(prism, scratch.file(name), {{"cluster_id", std::vector<double>(prism.faceCount(), 1.0)}});
        expectSameGeometry(readMesh(scratch.file(name)), prism);
    }
}

TEST(WritePolyData, ExtraArraysReplaceTheMeshsOwn) {
    Mesh cube = readMesh((datasetsDir() / "cube.off").string());
    cube.faceArrays["cluster_id"] = std::vector<double>(12, 5.0);
    std::vector<double> replacement = {0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5};
    ScratchDirectory scratch;
    writePolyData(cube, scratch.file("cube.vtp"), {{"cluster_id", replacement}});
    EXPECT_EQ(readMesh(scratch.file("cube.vtp")).faceArrays.at("cluster_id"), replacement);
}

TEST(WritePolyData, RejectsArraysOfTheWrongLength) {
    Mesh cube = readMesh((datasetsDir() / "cube.off").string());
    ScratchDirectory scratch;
    EXPECT_THROW(writePolyData(cube, scratch.file("cube.vtp"), {{"cluster_id", {1.0, 2.0}}}), MeshWriteError);
    EXPECT_THROW(writePolyData(cube, scratch.file("cube.vtp"), {{"", std::vector<double>(12, 0.0)}}), MeshWriteError);
}

TEST(WritePolyData, RejectsUnknownExtensionsAndInvalidMeshes) {
    Mesh cube = readMesh((datasetsDir() / "cube.off").string());
    ScratchDirectory scratch;
    try {
        writePolyData(cube, scratch.file("cube.stl"));
        ADD_FAILURE() << "wrote an unsupported extension";
    } catch (const MeshWriteError& error) {
        EXPECT_NE(std::string(error.what()).find("cube.stl"), std::string::npos) << error.what();
    }
    Mesh broken = cube;
    broken.faceVertices[0] = 100;
    EXPECT_THROW(writePolyData(broken, scratch.file("broken.vtp")), MeshWriteError);
    EXPECT_THROW(writeOff(broken, scratch.file("broken.off")), MeshWriteError);
    EXPECT_THROW(writeOff(Mesh{}, scratch.file("empty.off")), MeshWriteError);
}

TEST(WritePolyData, UnwritablePathThrowsQuietly) {
    Mesh cube = readMesh((datasetsDir() / "cube.off").string());
    ::testing::internal::CaptureStderr();
    for (const char* name : {"/nonexistent/dir/cube.vtp", "/nonexistent/dir/cube.vtk", "/nonexistent/dir/cube.ply",
                             "/nonexistent/dir/cube.off"}) {
        try {
            writePolyData(cube, name);
            ADD_FAILURE() << "wrote " << name;
        } catch (const MeshWriteError& error) {
            EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
        }
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(WritableExtensions, MatchWhatWritePolyDataAccepts) {
    EXPECT_EQ(writableMeshExtensions(), (std::vector<std::string>{".vtp", ".vtk", ".ply", ".off"}));
}

}  // namespace
}  // namespace conescope
