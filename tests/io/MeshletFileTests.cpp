// meshoptimizer's meshlet arrays as files: both forms read back what was written, and every fault
// of a file or of its arrays against the mesh is refused with the meshlet and the fault named.
#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "core/BuildPartition.h"
#include "core/meshopt/Meshopt.h"
#include "io/ClusterFiles.h"
#include "io/MeshReader.h"
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

// meshopt_buildMeshlets allows at most 255 vertices and 512 triangles a meshlet, and
// meshopt_computeMeshletBounds assumes so: a file beyond them is not an engine's meshlet file.
TEST(MeshletFiles, RefusesAMeshletBeyondMeshoptimizersLimits) {
    MeshletArrays arrays = gridMeshlets();
    arrays.meshlets[1][2] = 300;
    EXPECT_HAS(applyError(arrays), "meshlet 1: vertex_count 300 is above 255 (meshoptimizer's meshlets hold at most 255 vertices and 512 triangles)");
    arrays = gridMeshlets();
    arrays.meshlets[0][3] = 513;
    EXPECT_HAS(applyError(arrays), "meshlet 0: triangle_count 513 is above 512");
    // The writer refuses what the reader would: a cluster of 256 vertices (a 16 x 15 grid of squares).
    Mesh big;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) big.positions.emplace_back(float(x), float(y), 0.0f);
    for (uint32_t y = 0; y < 15; ++y)
        for (uint32_t x = 0; x < 15; ++x) big.addFace({16 * y + x, 16 * y + x + 1, 16 * y + x + 17, 16 * y + x + 16});
    Partition whole;
    whole.clusterOfFace.assign(big.faceCount(), 0);
    whole.clusterCount = 1;
    EXPECT_HAS(errorOf<std::invalid_argument>([&] { meshletsOfPartition(big, whole); }), "cluster 0: vertex_count 256 is above 255");
}

// Without stored bounds, a file is scored with meshopt_computeMeshletBounds of its own meshlets, in
// its own triangle order (the library's cone and sphere depend on it), not of the mesh's faces:
// elephant's partition with each meshlet's triangles reversed changes the bounds of some meshlets.
TEST(MeshletFiles, BoundsOfAFileWithoutThemComeFromItsOwnMeshlets) {
    const std::string path = (testing::datasetsDir() / "elephant.off").string();
    Mesh mesh = readMesh(path);
    Settings settings;
    settings.builder = Builder::Meshopt;
    const Partition partition = buildPartition(mesh, computeFaceGeometry(mesh), settings);
    MeshletArrays faceOrder = meshletsOfPartition(mesh, partition), reversed = faceOrder;
    for (const auto& [vertexOffset, triangleOffset, vertexCount, triangleCount] : reversed.meshlets)
        for (uint32_t t = 0; t < triangleCount; ++t)
            for (int k = 0; k < 3; ++k)
                reversed.triangles[triangleOffset + 3 * t + k] = faceOrder.triangles[triangleOffset + 3 * (triangleCount - 1 - t) + k];
    const std::vector<glm::vec3> positions = mesh.positions;  // the file's vertices: elephant.off repeats none
    ASSERT_TRUE(mesh.fileVertices.empty());
    const std::vector<MeshletBounds> ownOrder = meshoptBoundsOfMeshlets(reversed, positions);
    const std::vector<MeshletBounds> meshOrder = meshoptBoundsOfMeshlets(faceOrder, positions);
    ScratchDirectory scratch;
    const std::string file = scratch.writeFile("reversed.json", meshletJson(reversed));
    std::vector<std::string> notes;
    readClusterFile(mesh, file, notes);
    const std::vector<MeshletBounds>& read = mesh.fileClusters.at(file).bounds;
    ASSERT_EQ(read.size(), reversed.meshlets.size());
    size_t differ = 0;
    for (size_t m = 0; m < ownOrder.size(); ++m) {
        EXPECT_EQ(read[m].coneAxis, ownOrder[m].coneAxis) << m;
        EXPECT_EQ(read[m].coneApex, ownOrder[m].coneApex) << m;
        EXPECT_EQ(read[m].center, ownOrder[m].center) << m;
        EXPECT_EQ(read[m].radius, ownOrder[m].radius) << m;
        EXPECT_EQ(read[m].coneCutoffS8, ownOrder[m].coneCutoffS8) << m;
        differ += ownOrder[m].coneApex != meshOrder[m].coneApex || ownOrder[m].center != meshOrder[m].center ||
                  ownOrder[m].coneAxis != meshOrder[m].coneAxis;
    }
    EXPECT_GT(differ, 0u) << "the order makes no difference here: the test shows nothing";
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
    EXPECT_HAS(binaryError("MESHLETX" + bytes.substr(8)),
               "m.meshlets: not a meshlet file: a binary one starts with the 8 bytes 'MESHLETS', this one with 'MESHLETX'");
    EXPECT_HAS(binaryError(bytes.substr(0, 20)), "m.meshlets: truncated: the file ends at byte 20, inside the 32-byte header");
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

// A binary file whose magic is wrong is a meshlet file that says what it should start with, not a
// text of cluster ids refused with a message cut at its first NUL byte; whatever its name.
TEST(MeshletFiles, AWrongMagicNamesTheRightOne) {
    ScratchDirectory scratch;
    std::string bytes = meshletBinary(gridMeshlets());
    bytes[7] = 'X';
    for (const char* name : {"grid.meshlets", "grid.bin", "grid.txt"}) {
        const std::string path = scratch.writeFile(name, bytes);
        EXPECT_TRUE(isMeshletFile(path)) << name;
        Mesh mesh = grid();
        std::vector<std::string> notes;
        Settings settings;
        settings.builder = Builder::File;
        settings.clusterFile = path;
        EXPECT_EQ(errorOf<ClusterFileError>([&] { readClusterFileOf(mesh, settings, notes); }),
                  path + ": not a meshlet file: a binary one starts with the 8 bytes 'MESHLETS', this one with 'MESHLETX' (and a JSON one with '{')");
    }
    // A text of ids stays one.
    EXPECT_FALSE(isMeshletFile(scratch.writeFile("ids.txt", "0\n1\n0\n")));
}

}  // namespace
}  // namespace conescope
