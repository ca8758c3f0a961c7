// Bad input of every kind must end in MeshReadError naming the file (and for OFF the line), never in
// a crash, a huge allocation, a silently empty mesh, or VTK chatter on stderr.
#include <array>
#include <fstream>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"

namespace conescope {
namespace {

using testing::formatSamplesDir;
using testing::fileBytes;
using testing::ScratchDirectory;

// Replaces the first (or last) occurrence of `from`, failing the test if there is none.
void replaceFirst(std::string& text, const std::string& from, const std::string& to) {
    size_t position = text.find(from);
    ASSERT_NE(position, std::string::npos) << from;
    text.replace(position, from.size(), to);
}

void replaceLast(std::string& text, const std::string& from, const std::string& to) {
    size_t position = text.rfind(from);
    ASSERT_NE(position, std::string::npos) << from;
    text.replace(position, from.size(), to);
}

// Reading a sample of tests/data/formats with the first `from` replaced by `to` must fail with a
// message naming the file and holding `fragment`.
void expectErrorWhenReplaced(const std::string& sample, const std::string& from, const std::string& to,
                             const std::string& fragment) {
    SCOPED_TRACE(sample + ": '" + from + "' -> '" + to + "'");
    std::string text = fileBytes(formatSamplesDir() / sample);
    replaceFirst(text, from, to);
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile(sample, text), fragment);
}

// Deterministic noise with NUL bytes and high bytes: the "binary garbage" case for every format.
std::string garbageBytes(size_t size, unsigned seed) {
    std::mt19937 generator(seed);
    std::string bytes(size, '\0');
    for (char& c : bytes) c = static_cast<char>(generator() & 0xff);
    return bytes;
}

// ---------------------------------------------------------------- OFF

struct BadOff {
    const char* name;
    std::string text;
    std::string expected;  // fragment of the message, usually ":line: what"
};

std::string caseName(const ::testing::TestParamInfo<BadOff>& info) { return info.param.name; }

// Names the case in test listings instead of dumping the whole file text.
void PrintTo(const BadOff& bad, std::ostream* out) { *out << bad.name; }

class MalformedOff : public ::testing::TestWithParam<BadOff> {};

TEST_P(MalformedOff, ThrowsWithFileLineAndReason) {
    ScratchDirectory scratch;
    std::string path = scratch.writeFile(std::string(GetParam().name) + ".off", GetParam().text);
    EXPECT_READ_ERROR(path, GetParam().expected);
}

// 27 bytes per vertex line, so the counts pass the size check and the parser meets the real problem.
const std::string v0 = "0.000000 0.000000 0.000000\n";
const std::string v1 = "1.000000 0.000000 0.000000\n";
const std::string v2 = "0.000000 1.000000 0.000000\n";
const std::string v3 = "0.000000 0.000000 1.000000\n";
const std::string fourVertices = v0 + v1 + v2 + v3;

INSTANTIATE_TEST_SUITE_P(
    Cases, MalformedOff,
    ::testing::Values(
        BadOff{"empty", "", "file is empty"},
        BadOff{"only_comments", "# nothing\n\n# here\n", ":3: no content"},
        BadOff{"wrong_keyword", "PLY\n3 1 0\n", ":1: not an OFF file: expected the keyword 'OFF', found 'PLY'"},
        BadOff{"binary_garbage", garbageBytes(4096, 7), "not an OFF file"},
        BadOff{"binary_off", "OFF BINARY\n", ":1: binary OFF is not supported"},
        BadOff{"missing_counts", "OFF\n# counts should follow\n", ":2: file ends early: expected the counts line"},
        BadOff{"missing_face_count", "OFF\n4\n" + fourVertices, ":2: missing face count"},
        BadOff{"text_count", "OFF\nfour 1 0\n" + fourVertices, ":2: expected a vertex count, found 'four'"},
        BadOff{"negative_vertex_count", "OFF\n-4 1 0\n" + fourVertices, ":2: negative vertex count -4"},
        BadOff{"negative_face_count", "OFF\n4 -1 0\n" + fourVertices, ":2: negative face count -1"},
        BadOff{"zero_faces", "OFF\n4 0 0\n" + fourVertices, ":2: header declares 0 faces (no faces)"},
        BadOff{"zero_vertices", "OFF\n0 1 0\n3 0 1 2\n", ":2: header declares 0 vertices"},
        BadOff{"vertex_count_2_pow_32_minus_1", "OFF\n4294967295 1 0\n" + fourVertices + "3 0 1 2\n",
               ":2: header declares 4294967295 vertices but only 116 bytes follow"},
        BadOff{"vertex_count_2_pow_32", "OFF\n4294967296 1 0\n" + fourVertices, ":2: vertex count 4294967296 exceeds"},
        BadOff{"face_count_2_pow_40", "OFF\n4 1099511627776 0\n" + fourVertices + "3 0 1 2\n",
               ":2: header declares 4 vertices and 1099511627776 faces but only 116 bytes follow"},
        BadOff{"count_beyond_int64", "OFF\n99999999999999999999999 1 0\n" + fourVertices,
               ":2: vertex count '99999999999999999999999' is far larger than the file"},
        BadOff{"truncated_in_vertices", "OFF\n4 1 0\n" + v0 + v1 + v2, ":5: file ends early: expected vertex 3 of 4 (truncated file?)"},
        BadOff{"vertices_on_one_line", "OFF\n3 1 0\n0 0 0 1 0 0 0 1 0\n3 0 1 2\n",
               ":4: file ends early: expected vertex 2 of 3 (line 3 holds 9 numbers: are several vertices on one line?"},
        BadOff{"truncated_in_faces", "OFF\n4 3 0\n" + fourVertices + "3 0 1 2\n3 0 2 3\n",
               ":8: file ends early: expected face 2 of 3"},
        BadOff{"truncated_mid_line", "OFF\n4 1 0\n" + fourVertices + "3 0 1", ":7: face 0 lists 2 of its 3 vertex indices"},
        BadOff{"vertex_two_coordinates", "OFF\n4 1 0\n" + v0 + "1.000000 0.000000\n" + v2 + v3 + "3 0 1 2\n",
               ":4: vertex 1 has 2 coordinates, expected 3"},
        BadOff{"vertex_text", "OFF\n4 1 0\n" + v0 + v1 + "0.000000 one 0.000000\n" + v3 + "3 0 1 2\n",
               ":5: vertex 2: expected a coordinate, found 'one'"},
        BadOff{"faces_after_declared", "OFF\n4 1 0\n" + v0 + v1 + v2 + v3 + "3 0 1 2\n3 0 2 3\n",
               ":8: a face after the 1 faces the header declares"},
        BadOff{"vertex_nan", "OFF\n4 1 0\n" + v0 + "nan 0.000000 0.000000\n" + v2 + v3 + "3 0 1 2\n",
               ":4: vertex 1 has a non-finite coordinate 'nan'"},
        BadOff{"vertex_inf", "OFF\n4 1 0\n" + v0 + v1 + v2 + "0.000000 -inf 0.000000\n" + "3 0 1 2\n",
               ":6: vertex 3 has a non-finite coordinate '-inf'"},
        BadOff{"vertex_beyond_float", "OFF\n4 1 0\n1e39 0.000000 0.000000\n" + v1 + v2 + v3 + "3 0 1 2\n",
               ":3: vertex 0 has a coordinate beyond single-precision range"},
        BadOff{"face_two_vertices", "OFF\n4 1 0\n" + fourVertices + "2 0 1\n", ":7: face 0 has 2 vertices (needs at least 3)"},
        BadOff{"face_zero_vertices", "OFF\n4 1 0\n" + fourVertices + "0\n", ":7: face 0 has 0 vertices"},
        BadOff{"face_negative_size", "OFF\n4 1 0\n" + fourVertices + "-3 0 1 2\n", ":7: face 0 has -3 vertices"},
        BadOff{"face_size_text", "OFF\n4 1 0\n" + fourVertices + "three 0 1 2\n",
               ":7: face 0: expected its vertex count, found 'three'"},
        BadOff{"face_huge_size", "OFF\n4 1 0\n" + fourVertices + "4294967295 0 1 2\n",
               ":7: face 0 lists 3 of its 4294967295 vertex indices"},
        BadOff{"negative_index", "OFF\n4 2 0\n" + fourVertices + "3 0 1 2\n3 0 -1 2\n",
               ":8: face 1 has negative vertex index -1"},
        BadOff{"index_out_of_range", "OFF\n4 1 0\n" + fourVertices + "3 0 1 4\n", ":7: face 0 uses vertex 4 but there are only 4 vertices"},
        BadOff{"index_near_2_pow_32", "OFF\n4 1 0\n" + fourVertices + "3 0 1 4294967296\n",
               ":7: face 0 uses vertex 4294967296 but there are only 4 vertices"},
        BadOff{"index_not_integer", "OFF\n4 1 0\n" + fourVertices + "3 0 1.5 2\n", ":7: face 0: expected a vertex index, found '1.5'"},
        BadOff{"noff_dimension_4", "nOFF\n4\n4 1 0\n" + fourVertices + "3 0 1 2\n", ":2: only 3-dimensional nOFF is supported"},
        BadOff{"homogeneous_w_zero", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n3 0 1 2\n", ":4: vertex 1 has homogeneous coordinate w = 0"},
        BadOff{"nul_in_number", std::string("OFF\n4 1 0\n") + v0 + std::string("1.0\0 0 0\n", 9) + v2 + v3 + "3 0 1 2\n",
               ":4: vertex 1: expected a coordinate, found '1.0\\x00'"}),
    caseName);

TEST(MalformedOffFile, KeepsTheMessageShortForHugeGarbageTokens) {
    ScratchDirectory scratch;
    std::string path = scratch.writeFile("long.off", std::string(100000, 'x'));
    std::string message = testing::readErrorMessage(path);
    EXPECT_LT(message.size(), path.size() + 200) << message;
}

// ---------------------------------------------------------------- every format: empty, garbage, truncated

class MalformedAnyFormat : public ::testing::TestWithParam<const char*> {};

std::string extensionName(const ::testing::TestParamInfo<const char*>& info) { return info.param + 1; }

TEST_P(MalformedAnyFormat, EmptyFile) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile(std::string("empty") + GetParam(), ""), "file is empty");
}

TEST_P(MalformedAnyFormat, BinaryGarbage) {
    ScratchDirectory scratch;
    for (unsigned seed = 1; seed <= 5; ++seed) {
        std::string path = scratch.writeFile("garbage" + std::to_string(seed) + GetParam(), garbageBytes(300 * seed, seed));
        EXPECT_READ_ERROR(path, ": ");
    }
}

TEST_P(MalformedAnyFormat, TextGarbage) {
    ScratchDirectory scratch;
    std::string path = scratch.writeFile(std::string("text") + GetParam(), "this is not a mesh\nat all\n");
    EXPECT_READ_ERROR(path, ": ");
}

INSTANTIATE_TEST_SUITE_P(Formats, MalformedAnyFormat, ::testing::Values(".off", ".ply", ".obj", ".stl", ".vtp", ".vtk"),
                         extensionName);

// Every good sample cut short at several points: an error or (if the cut happens to leave a smaller
// valid mesh, e.g. an OBJ cut between lines) a valid mesh, but never a crash or an invalid mesh.
class TruncatedSample : public ::testing::TestWithParam<const char*> {};

std::string sampleFileName(const ::testing::TestParamInfo<const char*>& info) {
    std::string name = info.param;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

TEST_P(TruncatedSample, NeverCrashesOrReturnsAnInvalidMesh) {
    std::string bytes = fileBytes(formatSamplesDir() / GetParam());
    ASSERT_FALSE(bytes.empty());
    ScratchDirectory scratch;
    std::string extension = std::filesystem::path(GetParam()).extension().string();
    size_t errors = 0, cuts = 0;
    for (size_t length = 1; length < bytes.size(); length += std::max<size_t>(1, bytes.size() / 40), ++cuts) {
        std::string path = scratch.writeFile("cut" + std::to_string(length) + extension, bytes.substr(0, length));
        try {
            Mesh mesh = readMesh(path);
            EXPECT_NO_THROW(validateMesh(mesh));
            EXPECT_GT(mesh.faceCount(), 0u);
        } catch (const MeshReadError& error) {
            ++errors;
            EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
        }
    }
    EXPECT_GT(errors, cuts / 2) << "most cuts should be detected";
}

INSTANTIATE_TEST_SUITE_P(Formats, TruncatedSample,
                         ::testing::Values("cube.ply", "cube-binary.ply", "cube.obj", "cube-textured.obj", "cube-ascii.stl", "cube-binary.stl",
                                           "cube.vtp", "cube.vtk"),
                         sampleFileName);

TEST(TruncatedOffDataset, EveryCutIsAnError) {
    std::string bytes = fileBytes(testing::datasetsDir() / "icosphere.off");
    ScratchDirectory scratch;
    // Cuts inside the face list; the last line has no trailing content to lose, so stop before it.
    for (size_t length = 10; length + 20 < bytes.size(); length += bytes.size() / 37) {
        std::string path = scratch.writeFile("cut" + std::to_string(length) + ".off", bytes.substr(0, length));
        EXPECT_READ_ERROR(path, path + ":");
    }
}

// ---------------------------------------------------------------- PLY

TEST(MalformedPly, ForgedVertexCountIsRejectedBeforeAllocating) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    replaceFirst(text, "element vertex 8", "element vertex 4000000000");
    EXPECT_READ_ERROR(scratch.writeFile("forged.ply", text), "truncated file or wrong count");
}

TEST(MalformedPly, ForgedCountInBinaryFile) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.ply");
    replaceFirst(bytes, "element face 12", "element face 2147483647");
    EXPECT_READ_ERROR(scratch.writeFile("forged.ply", bytes), "truncated file or wrong count");
}

TEST(MalformedPly, HeaderWithoutEnd) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("open.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"),
                      "no end_header");
}

TEST(MalformedPly, UnknownPropertyType) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n1\n"),
                      ":4: unknown PLY property type 'float128'");
}

TEST(MalformedPly, NoFaceElement) {
    ScratchDirectory scratch;
    std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                       "end_header\n0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_READ_ERROR(scratch.writeFile("points.ply", text), "no faces");
}

TEST(MalformedPly, IndexOutOfRange) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    replaceLast(text, "4 1 3 7 5", "4 1 3 7 9");
    EXPECT_READ_ERROR(scratch.writeFile("index.ply", text), "vertex");
}

// Each of these crashed VTK 9.1's PLY reader before PLY files were checked (they are read by hand now).
TEST(MalformedPly, LastLineWithoutNewline) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    text.pop_back();
    EXPECT_READ_ERROR(scratch.writeFile("last.ply", text), ":24: PLY face 5 is not ended by a newline");
}

TEST(MalformedPly, EndHeaderWithoutNewline) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.ply");
    bytes.resize(bytes.find("end_header") + 10);
    EXPECT_READ_ERROR(scratch.writeFile("header.ply", bytes), "file ends right after end_header");
}

TEST(MalformedPly, MissingCoordinateProperty) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    replaceFirst(text, "property float y", "property float w");
    EXPECT_READ_ERROR(scratch.writeFile("noy.ply", text), "PLY vertex element lacks property 'y'");
}

TEST(MalformedPly, ControlCharacterInHeader) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    text.insert(text.find("property float y") + 16, "\f");
    EXPECT_READ_ERROR(scratch.writeFile("formfeed.ply", text), ":6: unexpected control character '\\x0c'");
}

TEST(MalformedPly, ListLongerThanItsLine) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply");
    replaceFirst(text, "4 0 2 3 1", "9 0 2 3 1");
    EXPECT_READ_ERROR(scratch.writeFile("list.ply", text), ":19: PLY face 0 lists 4 of its 9 values");
}

TEST(MalformedPly, NegativeListLengthInBinary) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.ply");
    std::string header = bytes.substr(0, bytes.find("end_header\n") + 11);
    std::string body = bytes.substr(header.size());
    replaceFirst(header, "list uchar int", "list int int");
    // Re-encode the first face with an int count of -1.
    std::string face = std::string("\xff\xff\xff\xff", 4) + body.substr(8 * 12 + 1, 12);
    std::string bodyWithIntCounts = body.substr(0, 8 * 12) + face;
    EXPECT_READ_ERROR(scratch.writeFile("negative.ply", header + bodyWithIntCounts), "has negative list length -1");
}

// vtkPLY reads only the elements the header declares: a count too small dropped the rest.
TEST(MalformedPly, FaceCountSmallerThanTheFaces) {
    expectErrorWhenReplaced("cube.ply", "element face 6", "element face 5",
                            ":24: data after the last element the header declares (8 vertex, 5 face): is a count in the header too small?");
}

TEST(MalformedPly, VertexCountSmallerThanTheVertices) {
    // With integer coordinates the last vertex line reads as a face without indices, and the faces
    // shift by one line: only the line left over at the end shows the count is wrong.
    ScratchDirectory scratch;
    std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty int y\nproperty int z\n"
                       "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                       "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n";
    EXPECT_READ_ERROR(scratch.writeFile("vertices.ply", text), ":14: data after the last element the header declares (3 vertex, 1 face)");
    replaceFirst(text, "element vertex 3", "element vertex 4");
    EXPECT_EQ(readMesh(scratch.writeFile("right.ply", text)).faceCount(), 1u);
}

// A binary PLY square: 4 vertices and 2 triangles in the body, whatever the header declares.
std::string binarySquarePly(bool bigEndian, int declaredFaces) {
    const std::string format = bigEndian ? "binary_big_endian" : "binary_little_endian";
    std::string bytes = "ply\nformat " + format + " 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                        "property float z\nelement face " + std::to_string(declaredFaces) +
                        "\nproperty list uchar int vertex_indices\nend_header\n";
    for (float coordinate : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f})
        testing::appendBinaryFloat(bytes, coordinate, bigEndian);
    for (const std::array<uint32_t, 3>& face : {std::array<uint32_t, 3>{0, 1, 2}, std::array<uint32_t, 3>{0, 2, 3}}) {
        bytes.push_back(char(3));
        for (uint32_t index : face) testing::appendBinaryInteger(bytes, index, 4, bigEndian);
    }
    return bytes;
}

// vtkPLY reads only the elements the header declares in binary too: the face it was not told of
// (13 bytes: a count byte and three ints) was dropped.
TEST(MalformedPly, BinaryFaceCountSmallerThanTheFaces) {
    ScratchDirectory scratch;
    for (bool bigEndian : {false, true}) {
        SCOPED_TRACE(bigEndian ? "big endian" : "little endian");
        const std::string bytes = binarySquarePly(bigEndian, 1);
        const size_t declaredEnd = bytes.size() - 13;
        EXPECT_READ_ERROR(scratch.writeFile("faces.ply", bytes),
                          ": data after the last element the header declares (4 vertex, 1 face): 13 bytes from offset " +
                              std::to_string(declaredEnd) + " to the end of the " + std::to_string(bytes.size()) +
                              "-byte file; is a count in the header too small?");
        EXPECT_EQ(readMesh(scratch.writeFile("right.ply", binarySquarePly(bigEndian, 2))).faceCount(), 2u);
    }
}

// One stray byte is too short for a triangle, but could be a face with an empty list: rejected.
TEST(MalformedPly, BinaryStrayByteAfterTheDataIsAnError) {
    ScratchDirectory scratch;
    for (bool bigEndian : {false, true}) {
        const std::string bytes = binarySquarePly(bigEndian, 2);
        EXPECT_READ_ERROR(scratch.writeFile("stray.ply", bytes + '\0'),
                          "(4 vertex, 2 face): 1 byte from offset " + std::to_string(bytes.size()));
        EXPECT_READ_ERROR(scratch.writeFile("late.ply", bytes + "\n\n\x01"), "3 bytes from offset");
    }
}

// Some exporters end a binary file with a newline; whitespace bytes after the data are padding.
TEST(MalformedPly, BinaryTrailingNewlineIsFine) {
    ScratchDirectory scratch;
    for (bool bigEndian : {false, true}) {
        const std::string bytes = binarySquarePly(bigEndian, 2);
        EXPECT_EQ(readMesh(scratch.writeFile("newline.ply", bytes + "\n")).faceCount(), 2u);
        EXPECT_EQ(readMesh(scratch.writeFile("crlf.ply", bytes + "\r\n \t")).faceCount(), 2u);
    }
}

TEST(MalformedPly, BlankLinesAfterTheDataAreFine) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply") + "\n  \r\n\n";
    EXPECT_EQ(readMesh(scratch.writeFile("blank.ply", text)).faceCount(), 6u);
}

TEST(MalformedPly, CrlfLineEndsAreFine) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.ply"), crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    EXPECT_EQ(readMesh(scratch.writeFile("crlf.ply", crlf)).faceCount(), 6u);
}

// ---------------------------------------------------------------- STL

TEST(MalformedStl, ForgedTriangleCount) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.stl");
    bytes.replace(80, 4, std::string("\xff\xff\xff\x7f", 4));
    EXPECT_READ_ERROR(scratch.writeFile("forged.stl", bytes), "declares 2147483647 triangles but the file holds only 12");
}

// A short binary file with a text comment sniffs as text, and VTK then reported "Expecting 'solid'".
TEST(MalformedStl, HeaderOnly) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.stl").substr(0, 84);
    bytes.replace(80, 4, std::string(4, '\0'));
    EXPECT_READ_ERROR(scratch.writeFile("header.stl", bytes),
                      ": neither ASCII STL (it does not start with 'solid') nor binary STL: header declares 0 triangles "
                      "(no faces; the file is 84 bytes)");
}

TEST(MalformedStl, ShorterThanTheHeader) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.stl");
    EXPECT_READ_ERROR(scratch.writeFile("text40.stl", bytes.substr(0, 40)),
                      ": neither ASCII STL (it does not start with 'solid') nor binary STL: the file is 40 bytes, "
                      "shorter than the 84-byte header");
    EXPECT_READ_ERROR(scratch.writeFile("zero40.stl", std::string(40, '\0')),
                      ": binary STL: the file is 40 bytes, shorter than the 84-byte header");
    EXPECT_READ_ERROR(scratch.writeFile("cut84.stl", bytes.substr(0, 84)),
                      "nor binary STL: header declares 12 triangles but the file holds only 0");
}

// vtkSTLReader reads only the triangles the header declares: a count too small dropped the rest.
TEST(MalformedStl, TriangleCountSmallerThanTheTriangles) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.stl");
    bytes.replace(80, 4, std::string("\x0b\0\0\0", 4));
    EXPECT_READ_ERROR(scratch.writeFile("count.stl", bytes),
                      ": binary STL: header declares 11 triangles but the file's 684 bytes hold 12 (84 + 50 per triangle");
}

TEST(MalformedStl, PaddingShorterThanATriangleIsFine) {
    ScratchDirectory scratch;
    std::string bytes = fileBytes(formatSamplesDir() / "cube-binary.stl") + std::string(49, '\0');
    EXPECT_EQ(readMesh(scratch.writeFile("padded.stl", bytes)).faceCount(), 12u);
    EXPECT_READ_ERROR(scratch.writeFile("triangle.stl", bytes + '\0'), "declares 12 triangles but the file's 734 bytes hold 13");
}

TEST(MalformedStl, AsciiWithBrokenFacet) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube-ascii.stl");
    replaceFirst(text, "vertex", "vortex");
    EXPECT_READ_ERROR(scratch.writeFile("broken.stl", text), ": ");
}

TEST(MalformedStl, AsciiSolidWithoutFacets) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("hollow.stl", "solid nothing\nendsolid nothing\n"), ": ");
}

// ---------------------------------------------------------------- OBJ

TEST(MalformedObj, IndexOutOfRange) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), ": ");
}

// VTK's OBJ reader reads these as 0 (or FLT_MAX) without a word; each would move a vertex.
TEST(MalformedObj, CoordinatesThatAreNotFiniteNumbers) {
    ScratchDirectory scratch;
    const std::string faces = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
    EXPECT_READ_ERROR(scratch.writeFile("nan.obj", "v nan 0 0\n" + faces), ":1: vertex 1 has a coordinate that is not a finite number: 'nan'");
    EXPECT_READ_ERROR(scratch.writeFile("inf.obj", "v 0 -inf 0\n" + faces), ":1: vertex 1 has a coordinate that is not a finite number: '-inf'");
    EXPECT_READ_ERROR(scratch.writeFile("huge.obj", "v 0 0 1e39\n" + faces), ":1: vertex 1 has a coordinate that is not a finite number: '1e39'");
    EXPECT_READ_ERROR(scratch.writeFile("text.obj", "v 0.5 x 0.5\n" + faces), ":1: vertex 1 has a coordinate that is not a finite number: 'x'");
    EXPECT_READ_ERROR(scratch.writeFile("two.obj", "v 0 0 0\nv 1 2\nv 0 1 0\nf 1 2 3\n"), ":2: vertex 2 has fewer than 3 coordinates");
    // A w or an RGB colour after the coordinates is allowed.
    ScratchDirectory good;
    EXPECT_EQ(readMesh(good.writeFile("colour.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n")).faceCount(), 1u);
}

TEST(MalformedObj, VerticesOnly) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no faces");
}

TEST(MalformedObj, LinesOnly) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n"), "no faces");
}

TEST(MalformedObj, TwoVertexFace) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("short.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"), ": ");
}

TEST(MalformedObj, CornerWithEmptyTextureIndex) {
    // "1/" crashed VTK 9.1's OBJ reader.
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("slash.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2 3\n"), ":4: malformed face corner '1/'");
}

TEST(MalformedObj, TextureAndNormalIndicesMustExist) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("vt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/5\n"),
                      ":5: face corner '3/5' uses texture coordinate 5 but the file has only 1");
    EXPECT_READ_ERROR(scratch.writeFile("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//-2\n"),
                      "refers to normal -2 but only 1 are defined before it");
}

TEST(ObjFile, RelativeIndicesAndFullCornersAreFine) {
    ScratchDirectory scratch;
    Mesh mesh = readMesh(scratch.writeFile("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf -3/1/1 -2/1/1 -1/1/1\n"));
    EXPECT_EQ(mesh.faceCount(), 1u);
}

// ---------------------------------------------------------------- VTP

TEST(MalformedVtp, OtherXml) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("other.vtp", "<?xml version=\"1.0\"?>\n<html><body/></html>\n"),
                      "not a VTK XML PolyData");
}

TEST(MalformedVtp, ImageDataInsteadOfPolyData) {
    ScratchDirectory scratch;
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\">\n"
                       "<ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n"
                       "<Piece Extent=\"0 1 0 1 0 1\"></Piece></ImageData></VTKFile>\n";
    EXPECT_READ_ERROR(scratch.writeFile("image.vtp", text), "not a VTK XML PolyData");
}

TEST(MalformedVtp, DataShorterThanDeclared) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, "NumberOfPoints=\"8\"", "NumberOfPoints=\"80\"");
    EXPECT_READ_ERROR(scratch.writeFile("short.vtp", text), ": ");
}

TEST(MalformedVtp, ConnectivityOutOfRange) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, "0 2 3 1", "0 2 3 99");
    EXPECT_READ_ERROR(scratch.writeFile("index.vtp", text), "uses vertex 99");
}

// VTK sizes the connectivity by the last offset before reading it: a forged offset was a 32 GB
// allocation (found by fuzz_mesh_readers).
TEST(MalformedVtp, ForgedOffsetIsRejectedBeforeVtkAllocates) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    ASSERT_NE(text.find(">4 8 12 16 20 24<"), std::string::npos);
    replaceFirst(text, ">4 8 12 16 20 24<", ">4 8 12 16 20\n4294967295<");
    EXPECT_READ_ERROR(scratch.writeFile("offset.vtp", text), "the last offset is 4294967295 but the connectivity array holds 24 values");
}

// VTK reads as many values as the piece counts give and ignores the rest: each of these read as a
// smaller or wrong mesh without a word. tests/io/VtpEncodingTests.cpp has the binary encodings.
TEST(MalformedVtp, MoreAsciiValuesThanTheCountsGive) {
    expectErrorWhenReplaced("cube.vtp", "NumberOfPolys=\"6\"", "NumberOfPolys=\"5\"",
                            ": DataArray 'cluster_id' in CellData of piece 0 holds 6 values but the piece's 5 cells gives 5 "
                            "(is a count or NumberOfComponents too small?)");
    expectErrorWhenReplaced("cube.vtp", "NumberOfPoints=\"8\"", "NumberOfPoints=\"7\"",
                            ": DataArray in Points of piece 0 holds 24 values but NumberOfPoints=7 times 3 components gives 21");
    expectErrorWhenReplaced("cube.vtp", ">4 8 12 16 20 24<", ">0 4 8 12 16 20 24<",
                            ": DataArray 'offsets' in Polys of piece 0 holds 7 values but NumberOfPolys=6 gives 6");
    expectErrorWhenReplaced("cube.vtp", "1 3 7 5<", "1 3 7 5 0 1 2 3<",
                            ": Polys of piece 0: the last offset is 24 but the connectivity array holds 28 values");
}

TEST(MalformedVtp, NoPolygons) {
    ScratchDirectory scratch;
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\">\n<PolyData>\n"
                       "<Piece NumberOfPoints=\"1\" NumberOfPolys=\"0\"><Points>"
                       "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray>"
                       "</Points></Piece></PolyData></VTKFile>\n";
    EXPECT_READ_ERROR(scratch.writeFile("points.vtp", text), "no faces");
}

// A bad cell-data array in a piece without <PointData> crashed VTK 9.1 (its error message
// dereferences the missing element); prepareVtpForVtk adds an empty one.
TEST(MalformedVtp, BadCellDataValueWithoutPointData) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    ASSERT_EQ(text.find("<PointData"), std::string::npos);
    replaceFirst(text, ">0 0 1 1 2 2<", ">0 0 x 1 2 2<");
    EXPECT_READ_ERROR(scratch.writeFile("value.vtp", text), "Cannot read cell data array \"cluster_id\"");
    text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, ">0 0 1 1 2 2<", ">0 0 1 1 2<");
    EXPECT_READ_ERROR(scratch.writeFile("short.vtp", text), "Cannot read cell data array \"cluster_id\"");
}

TEST(MalformedVtp, UnknownArrayType) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, "type=\"Int32\"", "type=\"Int99\"");
    EXPECT_READ_ERROR(scratch.writeFile("type.vtp", text), "DataArray has unknown type 'Int99'");
}

TEST(MalformedVtp, ForgedPieceCounts) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, "NumberOfPolys=\"6\"", "NumberOfPolys=\"2000000000\"");
    EXPECT_READ_ERROR(scratch.writeFile("polys.vtp", text), "NumberOfPolys=2000000000, more than the file can hold");
    text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, "NumberOfPoints=\"8\"", "NumberOfPoints=\"4000000000\"");
    EXPECT_READ_ERROR(scratch.writeFile("points.vtp", text), "NumberOfPoints=4000000000, more than the file can hold");
}

TEST(MalformedVtp, BadComponentCounts) {
    ScratchDirectory scratch;
    for (const char* components : {"0", "-3", "2000000000"}) {
        std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
        replaceFirst(text, "Name=\"face_normal\" NumberOfComponents=\"3\"", std::string("Name=\"face_normal\" NumberOfComponents=\"") + components + "\"");
        EXPECT_READ_ERROR(scratch.writeFile(std::string("components") + components + ".vtp", text), "NumberOfComponents");
    }
}

TEST(MalformedVtp, CorruptAppendedBlockTable) {
    // Deleting one byte inside the appended data shifts every later block table.
    Mesh prism = readMesh((testing::datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    std::string path = scratch.file("prism.vtp");
    writePolyData(prism, path, {{"cluster_id", std::vector<double>(prism.faceCount(), 1.0)}});
    std::string bytes = fileBytes(path);
    size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1;
    size_t end = bytes.rfind("</AppendedData>");
    size_t detected = 0, cuts = 0;
    for (size_t remove = data + 1; remove < end; remove += 7, ++cuts) {
        std::string damaged = bytes;
        damaged.erase(remove, 1);
        std::string damagedPath = scratch.writeFile("damaged" + std::to_string(remove) + ".vtp", damaged);
        try {
            readMesh(damagedPath);
        } catch (const MeshReadError&) {
            ++detected;
        }
    }
    EXPECT_GT(detected, cuts / 2);
}

// ---------------------------------------------------------------- legacy VTK

TEST(MalformedLegacyVtk, UnstructuredGridIsNotPolyData) {
    EXPECT_READ_ERROR((formatSamplesDir() / "tetrahedron-grid.vtk").string(), "not a legacy VTK file with POLYDATA");
}

TEST(MalformedLegacyVtk, ForgedPointCount) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    replaceFirst(text, "POINTS 8", "POINTS 900000000");
    EXPECT_READ_ERROR(scratch.writeFile("forged.vtk", text), ": ");
}

TEST(MalformedLegacyVtk, PolygonIndexOutOfRange) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    replaceFirst(text, "4 0 2 3 1", "4 0 2 3 77");
    EXPECT_READ_ERROR(scratch.writeFile("index.vtk", text), "uses vertex 77");
}

// Each of these crashed VTK 9.1's legacy reader, or (truncated attribute data) read as zeros.
TEST(MalformedLegacyVtk, CutInsideThePolygons) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    text.resize(text.find("4 2 6 7 3"));
    EXPECT_READ_ERROR(scratch.writeFile("cut.vtk", text), "POLYGONS: file ends after 15 of 30 values");
}

TEST(MalformedLegacyVtk, TruncatedCellDataIsAnErrorNotZeros) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    text.resize(text.size() - 4);  // drops the last two cluster ids
    EXPECT_READ_ERROR(scratch.writeFile("cut.vtk", text), "SCALARS: file ends after 4 of 6 values");
}

// VTK 4.x builds the polygons from the size alone; a count that disagrees is an inconsistent header.
TEST(MalformedLegacyVtk, PolygonCountDisagreesWithTheCells) {
    expectErrorWhenReplaced("cube.vtk", "POLYGONS 6 30", "POLYGONS 5 30", "POLYGONS: header declares 5 cells but its 30 values hold 6");
    expectErrorWhenReplaced("cube.vtk", "POLYGONS 6 30", "POLYGONS 7 30", "POLYGONS: header declares 7 cells but its 30 values hold 6");
}

// VTK reads the values a header declares and takes the next word as a keyword: it stopped at the
// sixth polygon's "4", and a too-small POINTS or CELL_DATA count is the same case.
TEST(MalformedLegacyVtk, CountSmallerThanTheValues) {
    expectErrorWhenReplaced("cube.vtk", "POLYGONS 6 30", "POLYGONS 5 25",
                            ":20: POLYGONS: value '4' after the 25 values its header declares (is a count in the header too small?)");
    expectErrorWhenReplaced("cube.vtk", "POINTS 8", "POINTS 7", ":13: POINTS: value '0.5' after the 21 values its header declares");
    expectErrorWhenReplaced("cube.vtk", "CELL_DATA 6", "CELL_DATA 5", ":29: SCALARS: value '2' after the 5 values its header declares");
}

TEST(MalformedLegacyVtk, KeywordWithTrailingGarbage) {
    // VTK matches "POLYGONSx" as POLYGONS by prefix and then crashed on what followed.
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    replaceFirst(text, "POLYGONS", "POLYGONS\x82");
    EXPECT_READ_ERROR(scratch.writeFile("keyword.vtk", text), "unexpected keyword");
}

TEST(MalformedLegacyVtk, IdBeyondInt) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    replaceFirst(text, "4 1 3 7 5", "4 1 3 711382209708227 5");
    EXPECT_READ_ERROR(scratch.writeFile("id.vtk", text), "expected an integer of type int, found '711382209708227'");
}

TEST(MalformedLegacyVtk, CoordinateBeyondFloat) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    replaceFirst(text, "0.5 0.5 0.5", "0.5 1e999 0.5");
    EXPECT_READ_ERROR(scratch.writeFile("float.vtk", text), "expected a finite float, found '1e999'");
}

TEST(MalformedLegacyVtk, DamagedVersionSwitchesCellLayout) {
    // "5.\xc8" reads as version 0.0 in VTK, so the 5.1 OFFSETS layout must not be assumed.
    Mesh prism = readMesh((testing::datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    std::string path = scratch.file("prism.vtk");
    writePolyData(prism, path);
    std::string bytes = fileBytes(path);
    ASSERT_EQ(bytes.rfind("# vtk DataFile Version 5.1", 0), 0u);
    bytes[25] = '\xc8';
    EXPECT_READ_ERROR(scratch.writeFile("version.vtk", bytes), ": ");
}

TEST(MalformedLegacyVtk, TruncatedBinaryFile) {
    Mesh prism = readMesh((testing::datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    std::string path = scratch.file("prism.vtk");
    writePolyData(prism, path, {{"cluster_id", std::vector<double>(prism.faceCount(), 2.0)}});
    std::string bytes = fileBytes(path);
    for (size_t length = 1; length + 1 < bytes.size(); length += 13) {
        std::string cutPath = scratch.writeFile("cut" + std::to_string(length) + ".vtk", bytes.substr(0, length));
        try {
            Mesh mesh = readMesh(cutPath);
            // Only a cut after the polygons and before the cell data can leave a valid file.
            EXPECT_EQ(mesh.faceArrays.count("cluster_id"), 0u) << length;
        } catch (const MeshReadError& error) {
            EXPECT_NE(std::string(error.what()).find(cutPath), std::string::npos);
        }
    }
}

// ---------------------------------------------------------------- paths

TEST(BadPath, NonexistentFile) {
    EXPECT_READ_ERROR("/nonexistent/dir/mesh.off", "file does not exist");
    EXPECT_READ_ERROR("/nonexistent/dir/mesh.vtp", "file does not exist");
}

TEST(BadPath, Directory) {
    ScratchDirectory scratch;
    std::filesystem::create_directory(scratch.path() / "folder.ply");
    EXPECT_READ_ERROR(scratch.file("folder.ply"), "is a directory");
}

TEST(BadPath, UnknownExtension) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("mesh.xyz", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                      "unsupported file extension '.xyz'; supported: .off .ply .obj .stl .vtp .vtk");
    EXPECT_READ_ERROR(scratch.writeFile("mesh", "OFF\n"), "unsupported file extension (none)");
}

// ---------------------------------------------------------------- quiet

TEST(VtkMessages, NothingIsPrintedToStderr) {
    ScratchDirectory scratch;
    std::vector<std::string> paths;
    for (const char* extension : {".ply", ".obj", ".stl", ".vtp", ".vtk", ".gltf", ".glb"}) {
        paths.push_back(scratch.writeFile(std::string("garbage") + extension, garbageBytes(2000, 3)));
        paths.push_back(scratch.writeFile(std::string("text") + extension, "solid\n<VTKFile>\nply\nformat ascii\n"));
    }
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    paths.push_back(scratch.writeFile("short.vtp", text.substr(0, text.size() / 2)));
    ::testing::internal::CaptureStderr();
    for (const std::string& path : paths) EXPECT_THROW(readMesh(path), MeshReadError) << path;
    std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(printed, "");
}

// A cell value VTK cannot parse passes the checks before VTK (a cut-off file no longer does: its
// XML is refused first, tests/io/VtpXmlTests.cpp), so the reason comes from vtkXMLPolyDataReader.
TEST(VtkMessages, VtkReasonIsInTheException) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, ">0 0 1 1 2 2<", ">0 0 x 1 2 2<");
    std::string path = scratch.writeFile("value.vtp", text);
    std::string message = testing::readErrorMessage(path);
    EXPECT_NE(message.find("vtkXML"), std::string::npos) << message;
    EXPECT_EQ(message.find("0x"), std::string::npos) << "object pointers should be stripped: " << message;
    EXPECT_EQ(message.find(".cxx, line"), std::string::npos) << "source locations should be stripped: " << message;
}

}  // namespace
}  // namespace conescope
