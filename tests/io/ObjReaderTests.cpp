// The OBJ reader: the file's positions shared through the faces' indices, every corner form,
// relative and forward indices, polygons, statements that carry no geometry, lines and points
// skipped with a note, text encodings; and assimp's test models that showed the old reader wrong.
#include <array>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "core/BuildPartition.h"
#include "core/MeshChecks.h"
#include "core/Statistics.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using testing::formatSamplesDir;
using testing::expectSameMesh;
using testing::fileBytes;
using testing::ScratchDirectory;
using testing::utf16;

std::vector<uint32_t> faceVertices(const Mesh& mesh, size_t face) {
    return std::vector<uint32_t>(mesh.faceBegin(face), mesh.faceBegin(face) + mesh.faceSize(face));
}

// The sample's corners carry texture coordinates and normals, each quad its own normal: a reader
// that makes a vertex per distinct corner would give 24 vertices and 6 separate quads.
TEST(ObjFile, TexturedCubeKeepsItsEightPositionsSharedByTheSixQuads) {
    const MeshFile file = readMeshFile((formatSamplesDir() / "cube-textured.obj").string());
    const Mesh plain = readMesh((formatSamplesDir() / "cube.obj").string());
    expectSameMesh(file.mesh, plain);
    const MeshReport report = checkMesh(file.mesh, computeFaceGeometry(file.mesh));
    EXPECT_EQ(report.components, 1u);
    EXPECT_EQ(report.openEdges, 0u);
    // Groups, materials (one usemtl empty), mtllib of a missing file and smoothing groups say nothing.
    EXPECT_EQ(file.notes, (std::vector<std::string>{"skipped 1 line and 3 points: they are not faces"}));
}

TEST(ObjFile, EveryCornerFormGivesThePosition) {
    ScratchDirectory scratch;
    const std::string vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n";
    for (const char* face : {"f 1 2 3 4", "f 1/1 2/2 3/3 4/1", "f 1//1 2//1 3//1 4//1", "f 1/1/1 2/2/1 3/3/1 4/1/1",
                             "f 1/1/1 2//1 3/3 4"}) {
        SCOPED_TRACE(face);
        const Mesh mesh = readMesh(scratch.writeFile("square.obj", vertices + face + "\n"));
        EXPECT_EQ(mesh.positions.size(), 4u);
        ASSERT_EQ(mesh.faceCount(), 1u);
        EXPECT_EQ(faceVertices(mesh, 0), (std::vector<uint32_t>{0, 1, 2, 3}));
    }
}

// Printer-bed files of a slicer end corners with a slash (`104/`, `1//`): the vertex alone, as assimp
// reads them; a texture coordinate before the slash is still checked.
TEST(ObjFile, TrailingSlashesNameTheVertexAlone) {
    ScratchDirectory scratch;
    const std::string vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n";
    for (const char* face : {"f 1/ 2/ 3/ 4/", "f 1// 2// 3// 4//", "f 1/1/ 2/1/ 3/1/ 4/1/", "f 1/ 2// 3/1/ 4"}) {
        SCOPED_TRACE(face);
        const MeshFile file = readMeshFile(scratch.writeFile("slashes.obj", vertices + face + "\n"));
        ASSERT_EQ(file.mesh.faceCount(), 1u);
        EXPECT_EQ(faceVertices(file.mesh, 0), (std::vector<uint32_t>{0, 1, 2, 3}));
        EXPECT_TRUE(file.notes.empty());
    }
    EXPECT_READ_ERROR(scratch.writeFile("texture.obj", vertices + "f 1/2/ 2/ 3/ 4/\n"),
                      ":6: face corner '1/2/' uses texture coordinate 2 but the file has only 1");
}

// Negative indices count back from the elements defined so far, so each face below uses the four
// positions just before it; positive indices may refer to positions defined later in the file.
TEST(ObjFile, RelativeAndForwardIndices) {
    ScratchDirectory scratch;
    const Mesh relative = readMesh(scratch.writeFile("relative.obj",
                                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf -4//-1 -3//-1 -2//-1 -1//-1\n"
                                                     "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf -1 -2 -3 -4\n"));
    ASSERT_EQ(relative.faceCount(), 2u);
    EXPECT_EQ(faceVertices(relative, 0), (std::vector<uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(faceVertices(relative, 1), (std::vector<uint32_t>{7, 6, 5, 4}));

    const Mesh forward = readMesh(scratch.writeFile("forward.obj", "f 1/1 2/1 3/1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"));
    EXPECT_EQ(forward.positions.size(), 3u);
    EXPECT_EQ(faceVertices(forward, 0), (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_READ_ERROR(scratch.writeFile("beyond.obj", "f 1 2 4\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"),
                      ":1: face corner '4' uses vertex 4 but the file has only 3");
    EXPECT_READ_ERROR(scratch.writeFile("behind.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n"),
                      ":3: face corner '-3' refers to vertex -3 but only 2 are defined before it");
}

TEST(ObjFile, PolygonsStayPolygons) {
    ScratchDirectory scratch;
    const Mesh mesh = readMesh(scratch.writeFile(
        "polygons.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nv 1 1 1\nf 1 2 3 4 5\nf 1 2 6\n"));
    ASSERT_EQ(mesh.faceCount(), 2u);
    EXPECT_EQ(faceVertices(mesh, 0), (std::vector<uint32_t>{0, 1, 2, 3, 4}));
    EXPECT_EQ(faceVertices(mesh, 1), (std::vector<uint32_t>{0, 1, 5}));
    EXPECT_EQ(triangleCount(mesh), 4u);
}

TEST(ObjFile, CommentsAtTheEndOfALineAndCrlfLineEnds) {
    ScratchDirectory scratch;
    const Mesh mesh = readMesh(scratch.writeFile("comments.obj", "v 0 0 0 # origin\r\nv 1 0 0\r\nv 0 1 0\r\n\r\nf 1 2 3 # one\r\n"));
    EXPECT_EQ(mesh.positions[0], glm::vec3(0.0f));
    EXPECT_EQ(faceVertices(mesh, 0), (std::vector<uint32_t>{0, 1, 2}));
}

TEST(ObjFile, LinesAndPointsAreSkippedWithANote) {
    ScratchDirectory scratch;
    const MeshFile file = readMeshFile(scratch.writeFile(
        "mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nl 1 2\nl 2 3 4\np 1\np 2 3 4\nf 1 3 2\nl 1 4\n"));
    EXPECT_EQ(file.mesh.faceCount(), 1u);
    EXPECT_EQ(file.notes, (std::vector<std::string>{"skipped 3 lines and 4 points: they are not faces"}));
    // Their corners are still checked: a bad index there means a damaged file.
    EXPECT_READ_ERROR(scratch.writeFile("bad-line.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 7\nf 1 2 3\n"),
                      ":4: face corner '7' uses vertex 7 but the file has only 3");
    EXPECT_READ_ERROR(scratch.writeFile("only-points.obj", "v 0 0 0\nv 1 0 0\np 1 2\n"),
                      ": no faces (2 vertices; 2 points skipped, which are not faces)");
    EXPECT_READ_ERROR(scratch.writeFile("one-line.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"), ": no faces (2 vertices; 1 line skipped, which is not a face)");
    const MeshFile one = readMeshFile(scratch.writeFile("one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\np 2\n"));
    EXPECT_EQ(one.notes, (std::vector<std::string>{"skipped 1 point: it is not a face"}));
}

TEST(ObjFile, StatementsWithUnknownKeywordsAreNoted) {
    ScratchDirectory scratch;
    const MeshFile file = readMeshFile(scratch.writeFile(
        "surface.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ncstype bspline\ndeg 3\ncurv 0 1 1 2 3\nend\n"));
    EXPECT_EQ(file.mesh.faceCount(), 1u);
    EXPECT_EQ(file.notes, (std::vector<std::string>{
                              "ignored 4 statements with a keyword this reader does not know (line 5: 'cstype' is the first)"}));
}

// Exporters write an edge as a face of two corners among the faces (Sweet Home 3D's furniture
// has files with 0.3 to 8 % of them): skipped with a note, as lines are, never the file refused.
TEST(ObjFile, FacesOfFewerThanThreeCornersAreSkippedWithANote) {
    ScratchDirectory scratch;
    const MeshFile file = readMeshFile(
        scratch.writeFile("edges.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2\nf 1 3 2\nf 4 1\nf 2 3 4\nf 3\n"));
    ASSERT_EQ(file.mesh.faceCount(), 2u);
    EXPECT_EQ(faceVertices(file.mesh, 0), (std::vector<uint32_t>{0, 2, 1}));
    EXPECT_EQ(faceVertices(file.mesh, 1), (std::vector<uint32_t>{1, 2, 3}));
    EXPECT_EQ(file.notes, (std::vector<std::string>{"skipped 3 faces of fewer than 3 corners (the first on line 5): a face needs at least 3"}));
    const MeshFile one = readMeshFile(scratch.writeFile("edge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\nl 1 3\n"));
    EXPECT_EQ(one.notes, (std::vector<std::string>{"skipped 1 line: it is not a face",
                                                   "skipped 1 face of fewer than 3 corners (line 5): a face needs at least 3"}));
    // Their corners are still checked, and a file of nothing else has no faces.
    EXPECT_READ_ERROR(scratch.writeFile("bad-edge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 9\nf 1 2 3\n"),
                      ":4: face corner '9' uses vertex 9 but the file has only 3");
    EXPECT_READ_ERROR(scratch.writeFile("two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"),
                      ": no faces (3 vertices; 1 face of fewer than 3 corners skipped, which is not a face)");
}

TEST(ObjFile, MalformedFaces) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("none.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\n"), ":4: face has 0 corners");
    EXPECT_READ_ERROR(scratch.writeFile("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2.5 3\n"), ":4: malformed face corner '2.5'");
    EXPECT_READ_ERROR(scratch.writeFile("parts.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n"), ":4: malformed face corner '1/1/1/1'");
}

// ---------------------------------------------------------------- encodings

TEST(ObjEncoding, Utf8ByteOrderMarkIsSkipped) {
    ScratchDirectory scratch;
    const std::string text = fileBytes(formatSamplesDir() / "cube.obj");
    const MeshFile file = readMeshFile(scratch.writeFile("bom.obj", "\xef\xbb\xbf" + text));
    expectSameMesh(file.mesh, readMesh((formatSamplesDir() / "cube.obj").string()));
    EXPECT_TRUE(file.notes.empty());
}

TEST(ObjEncoding, Utf16IsConvertedWithANote) {
    ScratchDirectory scratch;
    const Mesh expected = readMesh((formatSamplesDir() / "cube-textured.obj").string());
    const std::string text = fileBytes(formatSamplesDir() / "cube-textured.obj");
    for (bool bigEndian : {false, true}) {
        const std::string encoding = bigEndian ? "UTF-16 BE" : "UTF-16 LE";
        SCOPED_TRACE(encoding);
        const MeshFile file = readMeshFile(scratch.writeFile("utf16.obj", utf16(text, bigEndian)));
        expectSameMesh(file.mesh, expected);
        ASSERT_EQ(file.notes.size(), 2u);
        EXPECT_EQ(file.notes[0], "converted from " + encoding + " to UTF-8 before reading");
        EXPECT_READ_ERROR(scratch.writeFile("odd.obj", utf16(text, bigEndian) + '\n'),
                          ": " + encoding + " text (by its byte order mark) with an odd number of bytes");
    }
}

TEST(ObjEncoding, Utf16GroupNamesOutsideAsciiConvert) {
    ScratchDirectory scratch;
    // "g ü😀\n" then a triangle: U+00FC, and U+1F600 as the surrogate pair D83D DE00.
    std::string bytes = utf16("g ", true) + std::string("\x00\xfc\xd8\x3d\xde\x00", 6) +
                        utf16("\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", true).substr(2);
    EXPECT_EQ(readMesh(scratch.writeFile("names.obj", bytes)).faceCount(), 1u);
    EXPECT_READ_ERROR(scratch.writeFile("unpaired.obj", utf16("g ", true) + std::string("\xd8\x3d", 2) + utf16("\n", true).substr(2)),
                      ": UTF-16 BE text with an unpaired surrogate at byte 6");
}

TEST(ObjEncoding, Utf32IsRefusedByName) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("utf32.obj", std::string("\xff\xfe\0\0v\0\0\0", 8)), ": UTF-32 text (by its byte order mark) is not supported");
}

// ---------------------------------------------------------------- assimp's test models

const std::filesystem::path assimpModels = "/usr/share/assimp/models";


// WusonOBJ.obj has 2,117 v lines and 3,732 triangles (counted with grep). The STL of the same model
// stores a corner per triangle, the OFF duplicates its seams (3,205 vertices at 2,117 positions) and
// the PLY a vertex per corner (11,184): read, all four are the same surface, with the same pieces
// and (from the same builder) the same clusters.
TEST(ObjAssimpModels, WusonIsTheSameSurfaceInEveryFormat) {
    if (!std::filesystem::exists(assimpModels / "OBJ/WusonOBJ.obj")) GTEST_SKIP() << "install assimp-testmodels";
    const Mesh obj = readMesh((assimpModels / "OBJ/WusonOBJ.obj").string());
    EXPECT_EQ(obj.positions.size(), 2117u);
    EXPECT_EQ(obj.faceCount(), 3732u);
    EXPECT_EQ(triangleCount(obj), 3732u);
    const MeshReport objReport = checkMesh(obj, computeFaceGeometry(obj));
    EXPECT_EQ(objReport.components, 54u);
    const Partition objClusters = buildPartition(obj, computeFaceGeometry(obj), Settings{});
    for (const char* other : {"STL/Wuson.stl", "OFF/Wuson.off", "PLY/Wuson.ply"}) {
        const Mesh mesh = readMesh((assimpModels / other).string());
        EXPECT_EQ(mesh.positions.size(), obj.positions.size()) << other;
        EXPECT_EQ(triangleCount(mesh), triangleCount(obj)) << other;
        EXPECT_EQ(checkMesh(mesh, computeFaceGeometry(mesh)).components, objReport.components) << other;
        const Partition clusters = buildPartition(mesh, computeFaceGeometry(mesh), Settings{});
        EXPECT_NEAR(double(clusters.clusterCount), double(objClusters.clusterCount), 0.05 * objClusters.clusterCount) << other;
    }
}

TEST(ObjAssimpModels, CubeWithMaterialsEmptyMaterialAndUtf16) {
    if (!std::filesystem::exists(assimpModels / "OBJ/box.obj")) GTEST_SKIP() << "install assimp-testmodels";
    const Mesh cube = readMesh((assimpModels / "OBJ/cube_usemtl.obj").string());
    EXPECT_EQ(cube.positions.size(), 8u);
    EXPECT_EQ(cube.faceCount(), 12u);
    EXPECT_EQ(checkMesh(cube, computeFaceGeometry(cube)).components, 1u);
    EXPECT_EQ(readMesh((assimpModels / "OBJ/empty_mat.obj").string()).faceCount(), 256u);
    const MeshFile utf16 = readMeshFile((assimpModels / "OBJ/box_UTF16BE.obj").string());
    expectSameMesh(utf16.mesh, readMesh((assimpModels / "OBJ/box.obj").string()));
    EXPECT_EQ(utf16.notes, (std::vector<std::string>{"converted from UTF-16 BE to UTF-8 before reading"}));
}

// ---------------------------------------------------------------- progress

TEST(ObjFile, ReportsProgressAndCanBeCancelled) {
    ScratchDirectory scratch;
    std::string text;
    for (int i = 0; i < 200000; ++i) text += "v " + std::to_string(i) + " 0.25 0.5\n";
    const std::string path = scratch.writeFile("long.obj", text + "f 1 2 3\n");
    testing::expectProgressAndCancellation(path);
    EXPECT_EQ(readMesh(path).positions.size(), 200000u);
}

}  // namespace
}  // namespace conescope
