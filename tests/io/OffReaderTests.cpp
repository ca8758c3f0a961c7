// The OFF dialects found in the wild (CGAL, Geomview, hand-written) that the parser must accept.
#include <cmath>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"
#include "io/OffFormat.h"

namespace conescope {
namespace {

const char* const triangleAndQuad =
    "OFF\n"
    "5 2 0\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n"
    "3 1 4 2\n"
    "4 0 1 2 3\n";

void expectTriangleAndQuad(const Mesh& mesh) {
    ASSERT_EQ(mesh.positions.size(), 5u);
    ASSERT_EQ(mesh.faceCount(), 2u);
    EXPECT_EQ(mesh.faceSize(0), 3u);
    EXPECT_EQ(mesh.faceSize(1), 4u);
    EXPECT_EQ(mesh.faceVertices, (std::vector<uint32_t>{1, 4, 2, 0, 1, 2, 3}));
    EXPECT_EQ(mesh.positions[4], glm::vec3(2, 0, 0));
    EXPECT_NO_THROW(validateMesh(mesh));
}

TEST(OffParser, ReadsPlainOff) { expectTriangleAndQuad(parseOff(triangleAndQuad, "plain")); }

TEST(OffParser, IgnoresCommentsBlankLinesAndCarriageReturns) {
    expectTriangleAndQuad(parseOff(
        "# made by hand\r\n"
        "OFF # keyword\r\n"
        "\r\n"
        "# counts follow\r\n"
        "5 2 0\r\n"
        "0 0 0\r\n1 0 0 # trailing comment\r\n1 1 0\r\n\r\n0 1 0\r\n2 0 0\r\n"
        "3 1 4 2\r\n"
        "4 0 1 2 3",  // no newline at the very end
        "comments"));
}

TEST(OffParser, SkipsUtf8ByteOrderMark) {
    expectTriangleAndQuad(parseOff(std::string("\xEF\xBB\xBF") + triangleAndQuad, "bom"));
}

TEST(OffParser, AcceptsCountsOnTheKeywordLine) {
    expectTriangleAndQuad(parseOff("OFF 5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n3 1 4 2\n4 0 1 2 3\n", "one-line"));
}

TEST(OffParser, AcceptsMissingEdgeCount) {
    expectTriangleAndQuad(parseOff("OFF\n5 2\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n3 1 4 2\n4 0 1 2 3\n", "no-edges"));
}

TEST(OffParser, AcceptsMissingKeyword) {
    expectTriangleAndQuad(parseOff("5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n3 1 4 2\n4 0 1 2 3\n", "headerless"));
}

TEST(OffParser, IgnoresPerFaceColours) {
    // CGAL and Geomview append an RGB(A) colour, integer or float, after the indices.
    expectTriangleAndQuad(parseOff(
        "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n3 1 4 2 255 0 0\n4 0 1 2 3 0.1 0.2 0.3 1.0\n", "colours"));
}

TEST(OffParser, IgnoresPerVertexExtrasOfCnoffAndStoff) {
    expectTriangleAndQuad(parseOff(
        "CNOFF\n5 2 0\n"
        "0 0 0  0 0 1  1 0 0 1\n1 0 0  0 0 1  0 1 0 1\n1 1 0  0 0 1  0 0 1 1\n0 1 0  0 0 1  1 1 1 1\n"
        "2 0 0  0 0 1  0.5 0.5 0.5 1\n"
        "3 1 4 2\n4 0 1 2 3\n",
        "cnoff"));
    expectTriangleAndQuad(parseOff(
        "STOFF\n5 2 0\n0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n2 0 0 2 0\n3 1 4 2\n4 0 1 2 3\n", "stoff"));
}

TEST(OffParser, DividesHomogeneousCoordinatesOf4Off) {
    Mesh mesh = parseOff("4OFF\n3 1 0\n0 0 0 1\n2 0 0 2\n0 4 0 4\n3 0 1 2\n", "4off");
    EXPECT_EQ(mesh.positions[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.positions[2], glm::vec3(0, 1, 0));
}

TEST(OffParser, AcceptsNoffOfDimensionThree) {
    Mesh mesh = parseOff("nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "noff");
    EXPECT_EQ(mesh.faceCount(), 1u);
    mesh = parseOff("nOFF 3 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "noff-one-line");
    EXPECT_EQ(mesh.faceCount(), 1u);
}

TEST(OffParser, ReadsNumberSyntaxVariants) {
    Mesh mesh = parseOff("OFF\n3 1 0\n+1.5 -2e-3 1E2\n.5 -0 1.\n-1.55991e-008 0 0\n3 0 1 2\n", "numbers");
    EXPECT_EQ(mesh.positions[0], glm::vec3(1.5f, -2e-3f, 100.0f));
    EXPECT_EQ(mesh.positions[1], glm::vec3(0.5f, 0.0f, 1.0f));
    EXPECT_FLOAT_EQ(mesh.positions[2].x, -1.55991e-8f);
}

TEST(OffParser, ReadsLargePolygons) {
    std::string text = "OFF\n8 1 0\n";
    for (int k = 0; k < 8; ++k) text += std::to_string(std::cos(k * 0.785398)) + " " + std::to_string(std::sin(k * 0.785398)) + " 0\n";
    text += "8 0 1 2 3 4 5 6 7\n";
    Mesh mesh = parseOff(text, "octagon");
    ASSERT_EQ(mesh.faceCount(), 1u);
    EXPECT_EQ(mesh.faceSize(0), 8u);
}

TEST(OffParser, IgnoresAnythingAfterTheLastFace) {
    expectTriangleAndQuad(parseOff(std::string(triangleAndQuad) + "2 0 1\n# edges, unused\n", "trailing"));
}

TEST(OffParser, IsIndependentOfTheLocale) {
    Mesh mesh;
    {
        testing::ScopedCommaDecimalLocale german;
        mesh = parseOff("OFF\n3 1 0\n0.5 0 0\n1 0.25 0\n0 1 1e-3\n3 0 1 2\n", "locale");
    }
    EXPECT_EQ(mesh.positions[0].x, 0.5f);
    EXPECT_EQ(mesh.positions[1].y, 0.25f);
    EXPECT_EQ(mesh.positions[2].z, 1e-3f);
}

TEST(OffParser, ReadOffReadsAFile) {
    Mesh mesh = readOff((testing::datasetsDir() / "cube-quads.off").string());
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.faceCount(), 6u);
}

}  // namespace
}  // namespace conescope
