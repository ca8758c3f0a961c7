#include <gtest/gtest.h>

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
