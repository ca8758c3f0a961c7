#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "TestMeshes.h"
#include "core/Adjacency.h"

using namespace conescope;

namespace {

std::vector<uint32_t> row(const Rows& rows, size_t i) { return {rows.begin(i), rows.end(i)}; }

}  // namespace

TEST(Adjacency, QuadCubeFacesAroundVerticesAndAcrossEdges) {
    const Mesh cube = testmesh::quadCube();
    const Rows around = facesAroundVertices(cube);
    ASSERT_EQ(around.starts.size(), cube.positions.size() + 1);
    for (size_t v = 0; v < cube.positions.size(); ++v) {
        const std::vector<uint32_t> faces = row(around, v);
        EXPECT_EQ(faces.size(), 3u) << "vertex " << v;
        EXPECT_TRUE(std::is_sorted(faces.begin(), faces.end()));
        for (uint32_t f : faces) EXPECT_NE(std::count(cube.faceBegin(f), cube.faceBegin(f) + 4, v), 0);
    }
    const Rows across = facesAcrossEdges(cube);
    ASSERT_EQ(across.starts.size(), cube.faceCount() + 1);
    for (size_t f = 0; f < cube.faceCount(); ++f) {
        const std::vector<uint32_t> neighbours = row(across, f);
        // Every face of a cube borders the four faces that are not itself or its opposite.
        EXPECT_EQ(neighbours.size(), 4u) << "face " << f;
        EXPECT_EQ(std::set<uint32_t>(neighbours.begin(), neighbours.end()).size(), 4u);
        EXPECT_EQ(std::count(neighbours.begin(), neighbours.end(), uint32_t(f)), 0);
        for (uint32_t g : neighbours) {
            const std::vector<uint32_t> back = row(across, g);
            EXPECT_NE(std::count(back.begin(), back.end(), uint32_t(f)), 0) << "not symmetric: " << f << ", " << g;
        }
    }
}

TEST(Adjacency, FaceRepeatingAVertexIsListedOnceAndItsCollapsedSideIsNoSide) {
    // A fan of two triangles plus a quad that names vertex 0 twice (sides 0-0 and the rest).
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.addFace({0, 1, 2});
    mesh.addFace({0, 2, 3});
    mesh.addFace({0, 0, 3, 2});
    const Rows around = facesAroundVertices(mesh);
    EXPECT_EQ(row(around, 0), (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(row(around, 1), (std::vector<uint32_t>{0}));
    EXPECT_EQ(row(around, 2), (std::vector<uint32_t>{0, 1, 2}));

    std::vector<std::pair<uint32_t, uint32_t>> sides;
    forEachSide(mesh, 2, [&](uint32_t a, uint32_t b) { sides.emplace_back(a, b); });
    EXPECT_EQ(sides, (std::vector<std::pair<uint32_t, uint32_t>>{{0, 3}, {3, 2}, {2, 0}}));

    const Rows across = facesAcrossEdges(mesh);
    // In the order of the face's sides and, along a side, of the faces; each face once.
    EXPECT_EQ(row(across, 0), (std::vector<uint32_t>{1, 2}));  // side 2-0
    EXPECT_EQ(row(across, 1), (std::vector<uint32_t>{0, 2}));  // side 0-2; 2-3 and 3-0 again face 2
    EXPECT_EQ(row(across, 2), (std::vector<uint32_t>{1, 0}));  // sides 0-3 and 2-0
}

TEST(Adjacency, EdgeKeyIgnoresDirection) {
    EXPECT_EQ(edgeKey(3, 7), edgeKey(7, 3));
    EXPECT_NE(edgeKey(3, 7), edgeKey(3, 8));
    EXPECT_EQ(edgeKey(0xFFFFFFFFu, 1), (uint64_t(1) << 32) | 0xFFFFFFFFu);
}
