// The reproduction of meshoptimizer's builder against the library itself: the same meshlets, the
// same vertices in the same order, the same triangles in the same order, on meshes that exercise
// every branch (ties of the clamped score, triangles left alone at a vertex, the k-d tree between
// separate pieces, full meshlets, degenerate and repeated triangles, coordinates near the float
// range) and at limits and cone weights across their range. With another meshoptimizer linked
// they skip (MeshoptVersionTests.cpp fails instead).
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <cmath>
#include <random>

#include "TestMeshes.h"
#include "core/meshopt/KdTree.h"
#include "core/meshopt/Meshopt.h"
#include "core/meshopt/Reproduction.h"
#include "core/Partition.h"

namespace conescope {
namespace {

struct Case {
    std::vector<uint32_t> indices;
    std::vector<glm::vec3> positions;
};

Case fromMesh(const Mesh& mesh) {
    Case c{{}, mesh.positions};
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 1; k + 1 < mesh.faceSize(f); ++k)
            c.indices.insert(c.indices.end(), {mesh.faceBegin(f)[0], mesh.faceBegin(f)[k], mesh.faceBegin(f)[k + 1]});
    return c;
}

// Runs both and compares meshlet by meshlet: the library's vertex list and local triangles against
// those rebuilt from the reproduction's placement order.
void expectSameAsLibrary(const Case& c, size_t maxVertices, size_t maxTriangles, float coneWeight) {
    SCOPED_TRACE(testing::Message() << c.indices.size() / 3 << " triangles, limits " << maxVertices << "/" << maxTriangles
                                    << ", cone weight " << coneWeight);
    const size_t bound = meshopt_buildMeshletsBound(c.indices.size(), maxVertices, maxTriangles);
    std::vector<meshopt_Meshlet> meshlets(bound);
    std::vector<unsigned int> meshletVertices(bound * maxVertices);
    std::vector<unsigned char> meshletTriangles(bound * maxTriangles * 3);
    const size_t count = meshopt_buildMeshlets(meshlets.data(), meshletVertices.data(), meshletTriangles.data(), c.indices.data(),
                                               c.indices.size(), &c.positions[0].x, c.positions.size(), sizeof(glm::vec3),
                                               maxVertices, maxTriangles, coneWeight);
    const MeshoptMeshlets ours = reproduceMeshoptMeshlets(c.indices.data(), c.indices.size(), &c.positions[0].x, c.positions.size(),
                                                          sizeof(glm::vec3), maxVertices, maxTriangles, coneWeight);
    ASSERT_EQ(ours.count, count);
    size_t placed = 0;
    for (size_t m = 0; m < count; ++m) {
        std::vector<uint32_t> vertices;
        std::vector<uint8_t> local(c.positions.size(), 0xff);
        for (size_t t = 0; t < meshlets[m].triangle_count; ++t, ++placed) {
            const uint32_t triangle = ours.placementOrder[placed];
            ASSERT_EQ(ours.meshletOfTriangle[triangle], m) << "placement " << placed;
            for (int k = 0; k < 3; ++k) {
                const uint32_t v = c.indices[triangle * 3 + k];
                if (local[v] == 0xff) local[v] = uint8_t(vertices.size()), vertices.push_back(v);
                ASSERT_EQ(meshletTriangles[meshlets[m].triangle_offset + t * 3 + k], local[v]) << "meshlet " << m << ", triangle " << t;
            }
        }
        ASSERT_EQ(std::vector<uint32_t>(meshletVertices.begin() + meshlets[m].vertex_offset,
                                        meshletVertices.begin() + meshlets[m].vertex_offset + meshlets[m].vertex_count),
                  vertices)
            << "meshlet " << m;
    }
    // Everything placed is in a meshlet; the rest is what the library never placed either.
    EXPECT_EQ(placed, ours.placementOrder.size());
    size_t unplaced = 0;
    for (uint32_t meshlet : ours.meshletOfTriangle) unplaced += meshlet == ~0u;
    EXPECT_EQ(unplaced + placed, c.indices.size() / 3);
}

void expectSameAsLibraryAtSeveralLimits(const Case& c) {
    expectSameAsLibrary(c, 64, 124, 1.0f);
    expectSameAsLibrary(c, 64, 124, 0.25f);
    expectSameAsLibrary(c, 32, 64, 0.5f);
    expectSameAsLibrary(c, 255, 512, 0.0f);
    expectSameAsLibrary(c, 3, 4, 1.0f);
    expectSameAsLibrary(c, 128, 256, 0.9f);
}

// Many pieces far apart (each its own sphere, some tiny), so meshlets end and start through the tree.
Case scatteredPieces(std::mt19937_64& random, int pieces) { return fromMesh(testmesh::scatteredSpheres(random, pieces)); }

TEST(MeshoptMeshlets, SameAsTheLibraryOnSmoothClosedMeshes) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    expectSameAsLibraryAtSeveralLimits(fromMesh(testmesh::icosphere(4)));
    expectSameAsLibraryAtSeveralLimits(fromMesh(testmesh::torus(1.0, 0.3, 96, 48)));
}

// The library searches its k-d tree when no triangle around the meshlet is left (the first
// triangle, pieces' ends, pockets). Scans stand in for it while they are cheap: the nearest centre,
// or among centres exactly as near the one the search meets first, found by making only the nodes
// on its way. Both ways, the same meshlets as the library's.
TEST(MeshoptMeshlets, TheTreeIsBuiltOnlyWhereScansCannotStandIn) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    const auto built = [](const Case& c) {
        expectSameAsLibrary(c, 64, 124, 1.0f);
        return reproduceMeshoptMeshlets(c.indices.data(), c.indices.size(), &c.positions[0].x, c.positions.size(), sizeof(glm::vec3), 64,
                                        124, 1.0f)
            .builtTree;
    };
    // The first search starts at the origin. Moved off it, the torus has one nearest centre there
    // and at its few dead ends.
    Case moved = fromMesh(testmesh::readBundledOff("torus.off"));
    for (glm::vec3& p : moved.positions) p += glm::vec3(3.0f, 0.4f, 0.7f);
    EXPECT_FALSE(built(moved));
    // Centred on the origin, 32 centres of its inner ring are exactly as near: the search's order
    // decides, and no tree is needed for it.
    EXPECT_FALSE(built(fromMesh(testmesh::readBundledOff("torus.off"))));
    // Forty pieces: too many searches for scans.
    std::mt19937_64 random(5);
    EXPECT_TRUE(built(scatteredPieces(random, 40)));
}

// From 2^15 triangles the tree is made at once on threads of its own, its root's two subtrees at
// the same time (kdBuildInTwo): the same nodes as made in one piece, and the library's meshlets.
TEST(MeshoptMeshlets, TheTreeMadeInTwoHalvesIsTheSameTree) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
    for (size_t count : {size_t(5), size_t(100), size_t(40000)}) {
        std::vector<glm::vec3> points(count);
        for (glm::vec3& p : points) p = glm::vec3(coordinate(random), coordinate(random), std::round(coordinate(random) * 4.0f));
        std::vector<unsigned int> wholeIndices(count), halvesIndices(count);
        for (unsigned int i = 0; i < count; ++i) wholeIndices[i] = halvesIndices[i] = i;
        std::vector<meshoptkd::KdNode> whole(2 * count), halves(2 * count);
        const size_t used = meshoptkd::kdBuild(whole.data(), &points[0].x, 3, wholeIndices.data(), count, 8);
        ASSERT_EQ(meshoptkd::kdBuildInTwo(halves.data(), &points[0].x, 3, halvesIndices.data(), count, 8, Cores{}), used);
        EXPECT_EQ(halvesIndices, wholeIndices);
        for (size_t n = 0; n < used; ++n) {
            EXPECT_EQ(halves[n].index, whole[n].index) << n;
            EXPECT_EQ(halves[n].axis, whole[n].axis) << n;
            EXPECT_EQ(halves[n].children, whole[n].children) << n;
        }
    }
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    expectSameAsLibrary(fromMesh(testmesh::icosphere(6)), 64, 124, 1.0f);
    std::mt19937_64 pieces(11);
    expectSameAsLibrary(scatteredPieces(pieces, 700), 64, 124, 1.0f);
}

// Regular grids, flat, bowl-shaped or bumpy, centred on the origin or copied side by side, their
// triangles shuffled or not: many centres exactly as near as the nearest at the first search and
// at pieces' ends, where the tree's order of search picks one.
TEST(MeshoptMeshlets, SameAsTheLibraryWhereCentresAreExactlyAsNear) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    std::mt19937_64 random(42);
    for (int trial = 0; trial < 40; ++trial) {
        SCOPED_TRACE(testing::Message() << "trial " << trial);
        Case c;
        const int kind = trial % 4, columns = 3 + int(random() % 24), rows = 3 + int(random() % 24);
        const float step = random() % 2 ? 1.0f : 0.1f;
        const int copies = kind == 2 ? 2 + int(random() % 12) : 1;
        for (int copy = 0; copy < copies; ++copy) {
            const uint32_t first = uint32_t(c.positions.size());
            const glm::vec3 offset = kind == 2 ? glm::vec3(float(int(random() % 11) - 5) * 5.0f, float(int(random() % 11) - 5) * 5.0f,
                                                           float(random() % 3))
                                               : glm::vec3(0.0f);
            for (int y = 0; y <= rows; ++y)
                for (int x = 0; x <= columns; ++x) {
                    glm::vec3 p(step * (float(x) - float(columns) / 2.0f), step * (float(y) - float(rows) / 2.0f), 0.0f);
                    if (kind == 1) p.z = 0.3f * step * (p.x * p.x + p.y * p.y);
                    if (kind == 3) p.z = 0.1f * float(random() % 3);
                    c.positions.push_back(p + offset);
                }
            for (int y = 0; y < rows; ++y)
                for (int x = 0; x < columns; ++x) {
                    const uint32_t a = first + uint32_t(y * (columns + 1) + x), b = a + 1, d = a + uint32_t(columns) + 1, e = d + 1;
                    if ((x + y + copy) % 2) c.indices.insert(c.indices.end(), {a, b, e, a, e, d});
                    else c.indices.insert(c.indices.end(), {a, b, d, b, e, d});
                }
        }
        if (random() % 2) {
            for (size_t i = c.indices.size() / 3 - 1; i > 0; --i) {
                const size_t j = random() % (i + 1);
                for (int k = 0; k < 3; ++k) std::swap(c.indices[i * 3 + k], c.indices[j * 3 + k]);
            }
        }
        expectSameAsLibrary(c, 64, 124, 1.0f);
        expectSameAsLibrary(c, 32, 64, 0.5f);
        expectSameAsLibrary(c, 3, 4, 1.0f);
    }
}

TEST(MeshoptMeshlets, SameAsTheLibraryOnBumpyPatchesAndPolygons) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    std::mt19937_64 random(11);
    for (int i = 0; i < 4; ++i) expectSameAsLibraryAtSeveralLimits(fromMesh(testmesh::randomPatch(random, 20 + 7 * i, 10.0 + 25.0 * i)));
    expectSameAsLibraryAtSeveralLimits(fromMesh(testmesh::quadCube()));
}

TEST(MeshoptMeshlets, SameAsTheLibraryOnSeparatePieces) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    std::mt19937_64 random(5);
    expectSameAsLibraryAtSeveralLimits(scatteredPieces(random, 40));
}

TEST(MeshoptMeshlets, SameAsTheLibraryWithShuffledTrianglesAndVertices) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    // Triangles and vertices in random order: the visiting order, and so every tie, changes.
    std::mt19937_64 random(7);
    Case c = fromMesh(testmesh::torus(1.0, 0.4, 60, 30));
    std::vector<uint32_t> order(c.indices.size() / 3), relabel(c.positions.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    for (uint32_t i = 0; i < relabel.size(); ++i) relabel[i] = i;
    std::shuffle(order.begin(), order.end(), random);
    std::shuffle(relabel.begin(), relabel.end(), random);
    Case shuffled;
    shuffled.positions.resize(c.positions.size());
    for (uint32_t v = 0; v < c.positions.size(); ++v) shuffled.positions[relabel[v]] = c.positions[v];
    for (uint32_t t : order)
        for (int k = 0; k < 3; ++k) shuffled.indices.push_back(relabel[c.indices[t * 3 + k]]);
    expectSameAsLibraryAtSeveralLimits(shuffled);
}

TEST(MeshoptMeshlets, SameAsTheLibraryOnDegenerateAndRepeatedTriangles) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    Case c = fromMesh(testmesh::icosphere(3));
    const size_t triangles = c.indices.size() / 3;
    for (size_t t = 0; t < triangles; t += 7) {  // the same triangle again, and with a corner repeated
        const uint32_t a = c.indices[t * 3], b = c.indices[t * 3 + 1], d = c.indices[t * 3 + 2];
        c.indices.insert(c.indices.end(), {a, b, d, a, a, b, d, d, d});
    }
    const uint32_t far = uint32_t(c.positions.size());
    c.positions.insert(c.positions.end(), {{5, 5, 5}, {5, 5, 5}, {5, 5, 5}});  // zero-area triangles of their own
    c.indices.insert(c.indices.end(), {far, far + 1, far + 2, far + 2, far + 1, far});
    expectSameAsLibraryAtSeveralLimits(c);
}

TEST(MeshoptMeshlets, SameAsTheLibraryWhereScoresAreNotNumbers) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    // Centres near the float range overflow to infinity; the scores become NaN and the library's
    // order of comparison decides (at 3e38 even its k-d tree finds nothing and it places no
    // triangle at all). And a mesh of zero area: the expected radius is 0.
    for (float scale : {1e19f, 1e20f, 1e22f, 1e38f, 3e38f}) {
        // Coarse and fine: neighbouring centres of the coarse one are 1e19 and more apart.
        Case coarse = fromMesh(testmesh::icosphere(0));
        for (glm::vec3& p : coarse.positions) p *= scale;
        expectSameAsLibrary(coarse, 64, 124, 1.0f);
        Case huge = fromMesh(testmesh::icosphere(2));
        for (glm::vec3& p : huge.positions) p *= scale;
        expectSameAsLibrary(huge, 64, 124, 1.0f);
        expectSameAsLibrary(huge, 64, 124, 0.5f);
    }
    Case flat = fromMesh(testmesh::icosphere(2));
    for (glm::vec3& p : flat.positions) p = glm::vec3(1.f, 2.f, 3.f);
    expectSameAsLibrary(flat, 64, 124, 1.0f);
    expectSameAsLibrary(flat, 64, 124, 0.5f);
    // Tiny meshes, placed off the origin: at cone weight 1 the distance's term is multiplied by 0,
    // which the reproduction skips only while the term stays finite; with an expected radius near
    // or below 1e-19 a distance over it can overflow, and the product is NaN.
    for (float scale : {1e-17f, 1e-19f, 1e-20f, 1e-22f}) {
        Case tiny = fromMesh(testmesh::icosphere(2));
        for (glm::vec3& p : tiny.positions) p = p * scale + glm::vec3(0.5f, 0.0f, 0.0f);
        expectSameAsLibrary(tiny, 64, 124, 1.0f);
    }
    // A strip of slivers 1e19 long and 1 wide, bent: normals and areas stay finite, while squared
    // distances between neighbouring centres overflow (the score is then NaN; a reproduction that
    // dropped the distance there would pick by the cone alone).
    std::mt19937_64 random(3);
    std::uniform_real_distribution<float> bend(-1.0f, 1.0f);
    for (float spacing : {1e19f, 1e20f}) {
        Case strip;
        for (int i = 0; i <= 60; ++i) {
            strip.positions.push_back(glm::vec3(float(i) * spacing, 0.0f, bend(random)));
            strip.positions.push_back(glm::vec3(float(i) * spacing, 1.0f, bend(random)));
        }
        for (uint32_t a = 0; a < 120; a += 2) strip.indices.insert(strip.indices.end(), {a, a + 2, a + 1, a + 1, a + 2, a + 3});
        expectSameAsLibrary(strip, 64, 124, 1.0f);
    }
    // Zero area but not one point (every triangle on a line): distance / 0 is infinite.
    Case line = fromMesh(testmesh::icosphere(2));
    for (glm::vec3& p : line.positions) p = glm::vec3(p.x, 0.0f, 0.0f);
    expectSameAsLibrary(line, 64, 124, 1.0f);
}

TEST(MeshoptMeshlets, PartitionOfFacesIsTheLibrarysOnMeshesWithoutDuplicateFaces) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    // The library's output, matched back to faces by corners, gives the same partition.
    std::mt19937_64 random(3);
    for (const Mesh& mesh : {testmesh::icosphere(4), testmesh::torus(1.0, 0.3, 80, 40), testmesh::quadCube(), testmesh::randomPatch(random, 40, 30.0)}) {
        const MeshletLimits limits{64, 124};
        const Partition ours = meshoptReproducedMeshlets(mesh, limits, 1.0f), library = meshoptLibraryMeshlets(mesh, limits, 1.0f);
        EXPECT_EQ(ours.clusterCount, library.clusterCount);
        EXPECT_EQ(ours.clusterOfFace, library.clusterOfFace);
        EXPECT_EQ(meshoptMeshletCount(mesh, limits, 1.0f), library.clusterCount);
    }
}

TEST(MeshoptMeshlets, FacesTheLibraryLeavesUnplacedStillGetACluster) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    Mesh mesh = testmesh::icosphere(2);
    for (glm::vec3& p : mesh.positions) p *= 3e38f;
    const Partition partition = meshoptReproducedMeshlets(mesh, {64, 124}, 1.0f);
    ASSERT_EQ(partition.clusterOfFace.size(), mesh.faceCount());
    EXPECT_EQ(partition.clusterCount, 1u);
    EXPECT_EQ(meshoptLibraryMeshlets(mesh, {64, 124}, 1.0f).clusterOfFace, partition.clusterOfFace);
}

// What a MeshletStream dropped while it builds relies on: told to stop when a meshlet closes, the
// builder returns with the meshlets closed so far.
TEST(MeshoptMeshlets, StopsWhenAListenerSaysSo) {
    const Case c = fromMesh(testmesh::torus(1.0, 0.3, 96, 48));
    MeshoptMeshlets stopped;
    size_t heard = 0;
    reproduceMeshoptMeshlets(stopped, c.indices.data(), c.indices.size(), &c.positions[0].x, c.positions.size(), sizeof(glm::vec3), 64,
                             124, 1.0f, [&](size_t closedMeshlets, size_t) {
                                 ++heard;
                                 return closedMeshlets < 3;
                             });
    EXPECT_EQ(heard, 3u);
    EXPECT_EQ(stopped.count, 3u);
    EXPECT_GT(stopped.placementOrder.size(), 0u);
    EXPECT_LT(stopped.placementOrder.size(), c.indices.size() / 3);
    for (uint32_t triangle : stopped.placementOrder) EXPECT_LT(stopped.meshletOfTriangle[triangle], 3u);
}

TEST(MeshoptMeshlets, NoTrianglesNoMeshlets) {
    const MeshoptMeshlets none = reproduceMeshoptMeshlets(nullptr, 0, nullptr, 0, sizeof(glm::vec3), 64, 124, 1.0f);
    EXPECT_EQ(none.count, 0u);
    EXPECT_TRUE(none.placementOrder.empty());
}

}  // namespace
}  // namespace conescope
