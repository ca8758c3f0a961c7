// The PLY reader beyond the cube samples: header lines without a PLY keyword where assimp reads
// them (Blender 2.4's "Created by ..."), byte order marks and UTF-16, and values it must not read
// as something else.
#include <filesystem>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "core/MeshChecks.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using testing::expectSameMesh;
using testing::fileBytes;
using testing::formatSamplesDir;
using testing::ScratchDirectory;

const std::string blenderLine = "Created by Blender3D 247 - www.blender.org, source file: ";

// The ASCII cube sample with `line` inserted before the first line that starts with `before`.
std::string cubeWithLineBefore(const std::string& before, const std::string& line) {
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    text.insert(text.find("\n" + before) + 1, line + "\n");
    return text;
}

Mesh cube() { return readMesh((formatSamplesDir() / "cube.ply").string()); }

// assimp 5.2.5 skips such a line after the format line, between elements and before end_header.
TEST(PlyHeader, LineWithoutKeywordAfterTheFormatLineIsAComment) {
    ScratchDirectory scratch;
    for (const char* before : {"comment", "element face", "end_header"}) {
        SCOPED_TRACE(before);
        const MeshFile file = readMeshFile(scratch.writeFile("blender.ply", cubeWithLineBefore(before, blenderLine)));
        expectSameMesh(file.mesh, cube());
        ASSERT_EQ(file.notes.size(), 1u);
        EXPECT_EQ(file.notes[0].rfind("read a header line without a PLY keyword as a comment (line ", 0), 0u) << file.notes[0];
        EXPECT_NE(file.notes[0].find("'Created by Blender3D 247"), std::string::npos) << file.notes[0];
    }
}

TEST(PlyHeader, SeveralSuchLinesAreOneNote) {
    ScratchDirectory scratch;
    std::string text = cubeWithLineBefore("comment", blenderLine);
    text.insert(text.find("\nend_header") + 1, "exported 2009\n");
    const MeshFile file = readMeshFile(scratch.writeFile("two.ply", text));
    EXPECT_EQ(file.notes, (std::vector<std::string>{"read 2 header lines without a PLY keyword as comments (line 3: "
                                                    "'Created by Blender3D 247 - www.b...' is the first)"}));
}

// assimp refuses the line before the format line, and among an element's properties it ends the
// element's property list and drops the properties after it: both stay errors.
TEST(PlyHeader, LineWithoutKeywordBeforeTheFormatOrAmongPropertiesIsAnError) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("first.ply", cubeWithLineBefore("format", blenderLine)),
                      ":2: unexpected PLY header line 'Created by Blender3D 247 - www.b...' before the format line");
    EXPECT_READ_ERROR(scratch.writeFile("among.ply", cubeWithLineBefore("property float y", "made by hand")),
                      ":6: unexpected PLY header line 'made by hand' among the properties of element 'vertex'");
    EXPECT_READ_ERROR(scratch.writeFile("list.ply", cubeWithLineBefore("property list", "made by hand")),
                      ":9: unexpected PLY header line 'made by hand' among the properties of element 'face'");
}

TEST(PlyHeader, BlendersWusonFromAssimpsModels) {
    const std::filesystem::path wuson = "/usr/share/assimp/models/PLY/Wuson.ply";
    if (!std::filesystem::exists(wuson)) GTEST_SKIP() << "install assimp-testmodels";
    const MeshFile file = readMeshFile(wuson.string());
    // Blender 2.47 wrote a vertex per face corner (with its texture coordinate): 3 x 3,732 - 12 of
    // them, at the 2,117 positions of the OBJ, STL and OFF exports. Merged, the faces are neighbours
    // again: the same 54 pieces as the others, not one per triangle.
    EXPECT_EQ(file.mesh.positions.size(), 2117u);
    EXPECT_EQ(file.mesh.faceCount(), 3732u);
    EXPECT_EQ(triangleCount(file.mesh), 3732u);
    EXPECT_EQ(checkMesh(file.mesh, computeFaceGeometry(file.mesh)).components, 54u);
    ASSERT_EQ(file.notes.size(), 2u);
    EXPECT_NE(file.notes[1].find("merged 9067 vertices"), std::string::npos) << file.notes[1];
}

TEST(PlyEncoding, ByteOrderMarkAndUtf16) {
    ScratchDirectory scratch;
    const std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    const MeshFile bom = readMeshFile(scratch.writeFile("bom.ply", "\xef\xbb\xbf" + text));
    expectSameMesh(bom.mesh, cube());
    EXPECT_TRUE(bom.notes.empty());
    for (bool bigEndian : {false, true}) {
        const std::string encoding = bigEndian ? "UTF-16 BE" : "UTF-16 LE";
        const MeshFile file = readMeshFile(scratch.writeFile("utf16.ply", testing::utf16(text, bigEndian)));
        expectSameMesh(file.mesh, cube());
        EXPECT_EQ(file.notes, (std::vector<std::string>{"converted from " + encoding + " to UTF-8 before reading"}));
        // Binary data does not survive being saved as UTF-16 text.
        std::string binary = testing::utf16(fileBytes(formatSamplesDir() / "cube-binary.ply").substr(0, 240), bigEndian);
        EXPECT_READ_ERROR(scratch.writeFile("binary16.ply", binary), ": binary PLY in a " + encoding + " text file");
    }
}

TEST(PlyValues, CoordinatesAreFiniteFloatsAndIntegersAreIntegers) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    std::string bad = text;
    bad.replace(bad.find("\n0.5 0.5 0.5") + 1, 11, "0.5 nan 0.5");
    EXPECT_READ_ERROR(scratch.writeFile("nan.ply", bad), ":18: PLY vertex 7 has a coordinate that is not a finite float: 'nan'");
    bad = text;
    bad.replace(bad.find("\n0.5 0.5 0.5") + 1, 11, "0.5 1e39 0.5");
    EXPECT_READ_ERROR(scratch.writeFile("huge.ply", bad), ":18: PLY vertex 7 has a coordinate that is not a finite float: '1e39'");
    // vtkPLY read "0.5" for an int with atoi, as 0.
    bad = text;
    bad.replace(bad.find("property float x"), 16, "property int x");
    EXPECT_READ_ERROR(scratch.writeFile("int.ply", bad), ":11: PLY vertex 0: expected an integer, found '-0.5'");
    bad = text;
    bad.replace(bad.find("4 0 2 3 1"), 9, "2 0 2");
    EXPECT_READ_ERROR(scratch.writeFile("short.ply", bad), ":19: PLY face 0 has 2 vertices (needs at least 3)");
    bad = text;
    bad.replace(bad.find("end_header"), 10, "element vertex 1\nproperty float x\nend_header");
    EXPECT_READ_ERROR(scratch.writeFile("twice.ply", bad), ": PLY header declares element 'vertex' twice");
}

TEST(PlyValues, BinaryCoordinateThatIsNotFinite) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.ply");
    const size_t body = bytes.find("end_header\n") + 11;
    bytes.replace(body + 4, 4, std::string("\x00\x00\x80\x7f", 4));  // vertex 0's y: +inf
    EXPECT_READ_ERROR(scratch.writeFile("inf.ply", bytes), ": PLY vertex 0 has a coordinate that is not a finite float: inf");
}

TEST(PlyFile, ReportsProgressAndCanBeCancelled) {
    ScratchDirectory scratch;
    const int vertices = 150000;
    std::string text = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
                       "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                       "property list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < vertices; ++i) text += "0.125 0.25 0.5\n";
    const std::string path = scratch.writeFile("long.ply", text + "3 0 1 2\n");
    testing::expectProgressAndCancellation(path);
}

}  // namespace
}  // namespace conescope
