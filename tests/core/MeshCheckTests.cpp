#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "TestMeshes.h"
#include "core/MeshChecks.h"

using namespace conescope;

TEST(MeshChecks, ClosedSphereIsClean) {
    const Mesh mesh = testmesh::icosphere(2);
    const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(report.openEdges, 0u);
    EXPECT_EQ(report.nonManifoldEdges, 0u);
    EXPECT_EQ(report.inconsistentEdges, 0u);
    EXPECT_EQ(report.duplicateFaces, 0u);
    EXPECT_EQ(report.components, 1u);
    EXPECT_TRUE(report.orientable);
}

TEST(MeshChecks, FlippedFacesAreFoundAndFixed) {
    Mesh mesh = testmesh::icosphere(2);
    const Mesh original = mesh;
    for (size_t f : {3u, 17u, 100u}) std::reverse(mesh.faceVertices.begin() + mesh.faceStarts[f], mesh.faceVertices.begin() + mesh.faceStarts[f + 1]);
    const MeshReport broken = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(broken.inconsistentEdges, 9u);
    EXPECT_EQ(fixWinding(mesh), 3u);
    EXPECT_EQ(checkMesh(mesh, computeFaceGeometry(mesh)).inconsistentEdges, 0u);
    const FaceGeometry fixed = computeFaceGeometry(mesh), expected = computeFaceGeometry(original);
    for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_NEAR(glm::dot(fixed.normals[f], expected.normals[f]), 1.0, 1e-9);
}

TEST(MeshChecks, OpenNonManifoldAndDuplicateFaces) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    mesh.addFace({0, 1, 2});
    mesh.addFace({1, 0, 3});
    mesh.addFace({0, 1, 4});  // third face on edge 0-1
    mesh.addFace({2, 1, 0});  // duplicate of the first, reversed
    const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(report.nonManifoldEdges, 1u);
    EXPECT_GT(report.openEdges, 0u);
    EXPECT_EQ(report.duplicateFaces, 1u);
}

TEST(MeshChecks, DuplicateFacesCountedAsABruteForceSetWould) {
    // Thousands of faces of 3-5 vertices over few vertices, many repeating an earlier face's
    // vertex set in another rotation or winding: the count is faces minus distinct vertex sets.
    std::mt19937_64 random(7);
    for (int round = 0; round < 5; ++round) {
        Mesh mesh;
        for (int v = 0; v < 40; ++v) mesh.positions.emplace_back(float(v), float(v * v % 7), float(v % 5));
        std::vector<std::vector<uint32_t>> faces;
        for (int f = 0; f < 6000; ++f) {
            std::vector<uint32_t> face;
            if (!faces.empty() && random() % 3 == 0) {
                face = faces[random() % faces.size()];
                std::rotate(face.begin(), face.begin() + long(random() % face.size()), face.end());
                if (random() % 2) std::reverse(face.begin(), face.end());
            } else {
                const size_t size = 3 + random() % 3;
                while (face.size() < size) {
                    const uint32_t v = uint32_t(random() % 40);
                    if (std::find(face.begin(), face.end(), v) == face.end()) face.push_back(v);
                }
            }
            faces.push_back(face);
            mesh.addFace(face.data(), face.size());
        }
        std::set<std::vector<uint32_t>> distinct;
        for (std::vector<uint32_t> face : faces) {
            std::sort(face.begin(), face.end());
            distinct.insert(face);
        }
        const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
        EXPECT_EQ(report.duplicateFaces, faces.size() - distinct.size());
        EXPECT_GT(report.duplicateFaces, 1000u);
    }
}
