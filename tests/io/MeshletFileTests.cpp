// meshoptimizer's meshlet arrays as files: both forms read back what was written, and every fault
// of a file or of its arrays against the mesh is refused with the meshlet and the fault named.
#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/ClusterFiles.h"
#include "io/MeshletFiles.h"

namespace conescope {
namespace {

using testing::ScratchDirectory;

// A 2 x 2 grid of squares, each two triangles: 9 vertices, 8 faces (0..7, two per square).
Mesh grid() {
    Mesh mesh;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) mesh.positions.emplace_back(float(x), float(y), 0.0f);
    for (uint32_t y = 0; y < 2; ++y)
        for (uint32_t x = 0; x < 2; ++x) {
            const uint32_t a = 3 * y + x, b = a + 1, c = a + 4, d = a + 3;
            mesh.addFace({a, b, c});
            mesh.addFace({a, c, d});
        }
    return mesh;
}

// Two meshlets: the left squares (faces 0, 1, 4, 5) and the right ones, local indices as
// meshopt_buildMeshlets writes them, triangles padded to 4 bytes.
MeshletArrays gridMeshlets() {
    MeshletArrays arrays;
    arrays.vertices = {0, 1, 4, 3, 6, 7, 1, 2, 5, 4, 7, 8};
    // Meshlet 0: faces (0,1,4) (0,4,3) (3,4,7) (3,7,6); meshlet 1: (1,2,5) (1,5,4) (4,5,8) (4,8,7).
    arrays.triangles = {0, 1, 2, 0, 2, 3, 3, 2, 5, 3, 5, 4, 0, 1, 2, 0, 2, 3, 3, 2, 5, 3, 5, 4};
    arrays.meshlets = {{0, 0, 6, 4}, {6, 12, 6, 4}};
    return arrays;
}

MeshletBounds someBounds(float seed) {
    MeshletBounds bounds;
    bounds.center = {seed, 0.5f, -0.25f};
    bounds.radius = 0.75f;
    bounds.coneApex = {0.1f, 0.2f, -3.0f};
    bounds.coneAxis = {0.0f, 0.0f, 1.0f};
    bounds.coneCutoff = 0.3f;
    bounds.coneAxisS8 = {0, -1, 127};
    bounds.coneCutoffS8 = 40;
    return bounds;
}

void expectSameArrays(const MeshletArrays& a, const MeshletArrays& b) {
    EXPECT_EQ(a.meshlets, b.meshlets);
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.triangles, b.triangles);
    ASSERT_EQ(a.bounds.size(), b.bounds.size());
    for (size_t m = 0; m < a.bounds.size(); ++m) {
        EXPECT_EQ(a.bounds[m].center, b.bounds[m].center);
        EXPECT_EQ(a.bounds[m].radius, b.bounds[m].radius);
        EXPECT_EQ(a.bounds[m].coneApex, b.bounds[m].coneApex);
        EXPECT_EQ(a.bounds[m].coneAxis, b.bounds[m].coneAxis);
        EXPECT_EQ(a.bounds[m].coneCutoff, b.bounds[m].coneCutoff);
        EXPECT_EQ(a.bounds[m].coneAxisS8, b.bounds[m].coneAxisS8);
        EXPECT_EQ(a.bounds[m].coneCutoffS8, b.bounds[m].coneCutoffS8);
    }
}

// The message of the Error that `run` throws ("" when it throws none).
template <typename Error, typename Run>
std::string errorOf(Run run) {
    try {
        run();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

// The MeshletError applyMeshlets throws for these arrays on the grid ("" when it throws none).
std::string applyError(MeshletArrays arrays, Mesh mesh = grid()) {
    return errorOf<MeshletError>([&] { applyMeshlets(mesh, arrays); });
}

#define EXPECT_HAS(text, fragment) EXPECT_NE(std::string(text).find(fragment), std::string::npos) << (text)

TEST(MeshletFiles, JsonAndBinaryReadBackWhatWasWritten) {
    MeshletArrays arrays = gridMeshlets();
    for (bool withBounds : {false, true}) {
        arrays.bounds.clear();
        if (withBounds) arrays.bounds = {someBounds(1.0f / 3.0f), someBounds(-7.25e-12f)};
        expectSameArrays(parseMeshletJson(meshletJson(arrays), "a.json"), arrays);
        expectSameArrays(parseMeshletBinary(meshletBinary(arrays), "a.meshlets"), arrays);
    }
    // The four signed bytes after the floats are bytes, not a float: these form a NaN's bits (as
    // meshoptimizer's wide cones with a negative z do; found on assimp's Wuson model).
    arrays.bounds[1].coneAxisS8 = {-108, -64, -17};
    arrays.bounds[1].coneCutoffS8 = 127;
    expectSameArrays(parseMeshletBinary(meshletBinary(arrays), "a.meshlets"), arrays);
    // The binary layout is the documented one: 32-byte header, 16 per meshlet, 4 per vertex, padded triangles, 48 per bounds.
    EXPECT_EQ(meshletBinary(arrays).size(), 32u + 2 * 16 + 12 * 4 + 24 + 2 * 48);
}

TEST(MeshletFiles, TheFuzzersSeedsHoldTheGridsMeshlets) {
    const std::string folder = std::string(CONESCOPE_TESTDATA_DIR) + "/meshlets/";
    for (const char* name : {"grid.json", "grid.meshlets"}) expectSameArrays(readMeshletFile(folder + name), gridMeshlets());
}

TEST(MeshletFiles, ApplyGivesEachFaceItsMeshlet) {
    Mesh mesh = grid();
    const AppliedMeshlets applied = applyMeshlets(mesh, gridMeshlets());
    EXPECT_EQ(applied.clusters.clusterCount, 2u);
    EXPECT_EQ(applied.clusters.clusterOfFace, (std::vector<uint32_t>{0, 0, 1, 1, 0, 0, 1, 1}));
    EXPECT_EQ(applied.cutPolygons, 0u);
    EXPECT_EQ(mesh.faceCount(), 8u);
}

TEST(MeshletFiles, DuplicateFacesAndPolygonsThatRepeatAVertexMatch) {
    // Faces 0 and 8 have the same corners (an STL's collapsed triangles come like that): each
    // meshlet's copy takes one of them, whichever meshlet comes first.
    Mesh mesh = grid();
    mesh.addFace({0, 1, 4});
    MeshletArrays arrays = gridMeshlets();
    arrays.vertices.insert(arrays.vertices.end(), {0, 1, 4});
    arrays.triangles.insert(arrays.triangles.end(), {0, 1, 2, 0});
    arrays.meshlets.push_back({12, 24, 3, 1});
    AppliedMeshlets applied = applyMeshlets(mesh, arrays);
    EXPECT_EQ(applied.clusters.clusterOfFace[0], 0u);
    EXPECT_EQ(applied.clusters.clusterOfFace[8], 2u);
    // A pentagon that visits vertex 4 twice: its fan holds the triangle (0, 4, 4)... twice over two
    // corners; its fan triangles in two meshlets cut it, in its own winding.
    Mesh polygon;
    polygon.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    polygon.addFace({0, 1, 2, 0, 3});  // fan: (0,1,2) (0,2,0) (0,0,3)
    MeshletArrays fans;
    fans.vertices = {0, 1, 2, 0, 3};
    fans.triangles = {0, 1, 2, 0, 0, 2, 0, 0, 3, 0, 0, 0};  // meshlet 0: (0,1,2) (0,2,0); meshlet 1: (0,0,3)
    fans.meshlets = {{0, 0, 3, 2}, {3, 8, 2, 1}};
    fans.triangles[8] = 0, fans.triangles[9] = 0, fans.triangles[10] = 1;
    const AppliedMeshlets cut = applyMeshlets(polygon, fans);
    EXPECT_EQ(cut.cutPolygons, 1u);
    EXPECT_EQ(polygon.faceCount(), 3u);
    EXPECT_EQ(cut.clusters.clusterOfFace, (std::vector<uint32_t>{0, 0, 1}));
}

TEST(MeshletFiles, BackToBackTwinsTakeTheMeshletWoundTheirWay) {
    // A quad and its reversed twin (a double-sided wall, as furniture models have): the meshlet
    // holding the twin's fan comes first; each face takes the meshlet wound as it is, whole.
    Mesh quads;
    quads.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quads.addFace({0, 1, 2, 3});
    quads.addFace({0, 3, 2, 1});
    MeshletArrays arrays;
    arrays.vertices = {0, 3, 2, 1, 0, 1, 2, 3};
    arrays.triangles = {0, 1, 2, 0, 2, 3, 0, 0, 0, 1, 2, 0, 2, 3, 0, 0};
    arrays.meshlets = {{0, 0, 4, 2}, {4, 8, 4, 2}};
    AppliedMeshlets applied = applyMeshlets(quads, arrays);
    EXPECT_EQ(applied.clusters.clusterOfFace, (std::vector<uint32_t>{1, 0}));
    EXPECT_EQ(applied.cutPolygons, 0u);
    // Two triangles back to back, likewise.
    Mesh triangles;
    triangles.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    triangles.addFace({0, 1, 2});
    triangles.addFace({0, 2, 1});
    arrays.vertices = {0, 2, 1, 0, 1, 2};
    arrays.triangles = {0, 1, 2, 0, 0, 1, 2, 0};
    arrays.meshlets = {{0, 0, 3, 1}, {3, 4, 3, 1}};
    applied = applyMeshlets(triangles, arrays);
    EXPECT_EQ(applied.clusters.clusterOfFace, (std::vector<uint32_t>{1, 0}));
}

TEST(MeshletFiles, RefusesOffsetsAndCountsOutOfRange) {
    MeshletArrays arrays = gridMeshlets();
    arrays.meshlets[1][0] = 7;  // vertex_offset 7 + 6 runs past the 12 entries
    EXPECT_HAS(applyError(arrays), "meshlet 1: vertex_offset 7 + vertex_count 6 runs past meshlet_vertices (12 entries)");
    arrays = gridMeshlets();
    arrays.meshlets[1][3] = 5;  // 12 + 15 bytes > 24
    EXPECT_HAS(applyError(arrays), "meshlet 1: triangle_offset 12 + 3 x triangle_count 5 runs past meshlet_triangles (24 bytes)");
    arrays = gridMeshlets();
    arrays.triangles[14] = 6;  // meshlet 1, triangle 0, corner 2: only 6 vertices
    EXPECT_HAS(applyError(arrays), "meshlet 1, triangle 0: local vertex 6 is past the meshlet's 6 vertices");
    arrays = gridMeshlets();
    arrays.meshlets[0][3] = 0;
    EXPECT_HAS(applyError(arrays), "meshlet 0 has no triangles");
    arrays = gridMeshlets();
    arrays.bounds = {someBounds(0.0f)};
    EXPECT_HAS(applyError(arrays), "bounds has 1 entries for 2 meshlets");
}

TEST(MeshletFiles, RefusesAVertexPastTheMesh) {
    MeshletArrays arrays = gridMeshlets();
    arrays.vertices[8] = 9;  // the grid has vertices 0..8
    EXPECT_HAS(applyError(arrays), "meshlet 1: meshlet_vertices[8] = 9 is past the mesh file's 9 vertices");
}

TEST(MeshletFiles, RefusesATriangleThatMatchesNoFace) {
    MeshletArrays arrays = gridMeshlets();
    arrays.triangles[2] = 4;  // (0, 1, 6): the corners of no face
    EXPECT_HAS(applyError(arrays), "meshlet 0, triangle 0 (vertices 0, 1, 6 of the mesh): no face of the mesh has these three corners");
}

TEST(MeshletFiles, RefusesAFaceInTwoMeshlets) {
    MeshletArrays arrays = gridMeshlets();
    // Meshlet 1's first triangle becomes face 0 (vertices 0, 1, 4), which meshlet 0 holds.
    arrays.vertices[6] = 0, arrays.vertices[7] = 1, arrays.vertices[8] = 4;
    EXPECT_HAS(applyError(arrays), "meshlet 1, triangle 0 (vertices 0, 1, 4 of the mesh): its face 0 is already in meshlet 0");
}

TEST(MeshletFiles, RefusesAPolygonsTriangleInTwoMeshlets) {
    Mesh square;
    square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.addFace({0, 1, 2, 3});
    MeshletArrays arrays;
    arrays.vertices = {0, 1, 2, 3, 0, 1, 2};
    arrays.triangles = {0, 1, 2, 0, 2, 3, 0, 0, 0, 1, 2, 0};
    arrays.meshlets = {{0, 0, 4, 2}, {4, 8, 3, 1}};
    EXPECT_HAS(applyError(arrays, square), "meshlet 1: its triangle (vertices 0, 1, 2 of the mesh) of face 0 is already in meshlet 0");
    arrays.meshlets = {{0, 0, 4, 1}};  // half the square
    arrays.triangles.resize(4);
    EXPECT_HAS(applyError(arrays, square), "face 0 (a polygon of 4 corners): the 1 triangles of meshlets 0 do not cut it into triangles");
}

TEST(MeshletFiles, ReportsFacesInNoMeshlet) {
    MeshletArrays arrays = gridMeshlets();
    arrays.meshlets[1][3] = 2;  // meshlet 1 loses faces 6 and 7
    EXPECT_HAS(applyError(arrays), "2 faces are in no meshlet: faces 6, 7");
}

TEST(MeshletFiles, ReadErrorsNameThePlace) {
    auto jsonError = [](const std::string& text) { return errorOf<MeshletFileError>([&] { parseMeshletJson(text, "m.json"); }); };
    const std::string good = meshletJson(gridMeshlets());
    EXPECT_HAS(jsonError("{\"meshlets\": []}"), "m.json: the document: has no \"format\"");
    EXPECT_HAS(jsonError("[1, 2]"), "is not a JSON object");
    EXPECT_HAS(jsonError("{\"format\": \"meshoptimizer-meshlets\", \"meshlets\""), "m.json: not valid JSON");
    std::string text = good;
    testing::replaceFirst(text, "[0,0,6,4]", "[0,0,6]");
    EXPECT_HAS(jsonError(text), "meshlets[0]: is not [vertex_offset, triangle_offset, vertex_count, triangle_count]");
    text = good;
    testing::replaceFirst(text, "[0,1,4,3", "[0,1.5,4,3");
    EXPECT_HAS(jsonError(text), "meshlet_vertices[1]: is number, not a whole number");
    text = good;
    testing::replaceFirst(text, "\"meshlet_triangles\":[0", "\"meshlet_triangles\":[256");
    EXPECT_HAS(jsonError(text), "meshlet_triangles[0]: 256 is outside [0, 255]");
    text = good;
    testing::replaceFirst(text, "[0,0,6,4]", "[-1,0,6,4]");
    EXPECT_HAS(jsonError(text), "meshlets[0][0]: -1 is outside");

    auto binaryError = [](const std::string& bytes) { return errorOf<MeshletFileError>([&] { parseMeshletBinary(bytes, "m.meshlets"); }); };
    const std::string bytes = meshletBinary(gridMeshlets());
    EXPECT_HAS(binaryError(bytes.substr(0, bytes.size() - 4)), "but the file has 132");
    EXPECT_HAS(binaryError("MESHLETX" + bytes.substr(8)), "not a binary meshlet file");
    std::string version = bytes;
    version[8] = 2;
    EXPECT_HAS(binaryError(version), "byte 8: version 2");
}

TEST(MeshletFiles, ClusterFileErrorsNameTheFile) {
    ScratchDirectory scratch;
    MeshletArrays arrays = gridMeshlets();
    arrays.triangles[2] = 4;
    const std::string path = scratch.writeFile("bad.meshlets", meshletBinary(arrays));
    Mesh mesh = grid();
    std::vector<std::string> notes;
    try {
        readClusterFile(mesh, path, notes);
        FAIL() << "a triangle matching no face was accepted";
    } catch (const ClusterFileError& error) {
        EXPECT_HAS(error.what(), path + ": meshlet 0, triangle 0");
    }
    EXPECT_TRUE(mesh.fileClusters.empty()) << "nothing is kept of a file that did not load";
}

}  // namespace
}  // namespace conescope
