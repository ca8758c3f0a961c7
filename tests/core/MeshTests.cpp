#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "TestMeshes.h"
#include "core/Mesh.h"
#include "core/Settings.h"
#include "core/Views.h"

using namespace conescope;

TEST(Mesh, NewellEqualsCrossProductForTriangles) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<float> coordinate(-10.f, 10.f);
    for (int i = 0; i < 1000; ++i) {
        glm::vec3 p[3];
        for (auto& v : p) v = {coordinate(random), coordinate(random), coordinate(random)};
        const uint32_t face[3] = {0, 1, 2};
        const glm::dvec3 cross = glm::cross(glm::dvec3(p[1]) - glm::dvec3(p[0]), glm::dvec3(p[2]) - glm::dvec3(p[0]));
        // Force the general Newell sum through a quad with a repeated last corner.
        const uint32_t quad[4] = {0, 1, 2, 2};
        const glm::dvec3 newell = newellNormal(p, quad, 4);
        EXPECT_NEAR(glm::length(newell - cross), 0.0, 1e-9 * (1.0 + glm::length(cross)));
        EXPECT_EQ(newellNormal(p, face, 3), cross);
    }
}

TEST(Mesh, NewellGivesTwiceTheProjectedAreas) {
    // Seed 003: the components are the signed areas of the projections, here a 2x3 rectangle in z = 5.
    const glm::vec3 p[4] = {{0, 0, 5}, {2, 0, 5}, {2, 3, 5}, {0, 3, 5}};
    const uint32_t face[4] = {0, 1, 2, 3};
    const glm::dvec3 n = newellNormal(p, face, 4);
    EXPECT_DOUBLE_EQ(n.x, 0.0);
    EXPECT_DOUBLE_EQ(n.y, 0.0);
    EXPECT_DOUBLE_EQ(n.z, 12.0);  // twice the area 6, counter-clockwise seen from +z
}

TEST(Mesh, FaceGeometryOfQuadCube) {
    const Mesh cube = testmesh::quadCube();
    const FaceGeometry geometry = computeFaceGeometry(cube);
    const glm::dvec3 expected[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    for (int f = 0; f < 6; ++f) {
        EXPECT_NEAR(glm::length(geometry.normals[f] - expected[f]), 0.0, 1e-12) << f;
        EXPECT_NEAR(geometry.areas[f], 4.0, 1e-12);
        // The face's plane through its centroid passes through every corner.
        for (size_t k = 0; k < 4; ++k)
            EXPECT_NEAR(glm::dot(geometry.normals[f], glm::dvec3(cube.positions[cube.faceBegin(f)[k]]) - geometry.centroids[f]), 0.0,
                        1e-12);
    }
    EXPECT_EQ(geometry.degenerateCount, 0u);
}

TEST(Mesh, DegenerateFacesAreDetected) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    mesh.addFace({0, 1, 2});  // collinear
    mesh.addFace({0, 0, 3});  // repeated vertex
    mesh.addFace({0, 1, 3});
    const FaceGeometry geometry = computeFaceGeometry(mesh);
    EXPECT_EQ(geometry.degenerateCount, 2u);
    EXPECT_TRUE(geometry.degenerate[0]);
    EXPECT_TRUE(geometry.degenerate[1]);
    EXPECT_FALSE(geometry.degenerate[2]);
    EXPECT_EQ(geometry.normals[0], glm::dvec3(0.0));
}

// Seed 003: (M^-1)^T with the sign of det M gives the normal of the transformed vertices' winding,
// for rotations, non-uniform scales and mirrors alike.
TEST(Mesh, TransformedPlanesMatchTransformedVertices) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), scale(0.2, 3.0);
    const Mesh sphere = testmesh::icosphere(1);
    for (int trial = 0; trial < 200; ++trial) {
        glm::dmat4 model = glm::translate(glm::dmat4(1.0), glm::dvec3(unit(random), unit(random), unit(random)) * 5.0);
        model = glm::rotate(model, unit(random) * M_PI, glm::normalize(glm::dvec3(unit(random), unit(random), unit(random)) + 1e-3));
        glm::dvec3 s(scale(random), scale(random), scale(random));
        if (trial % 2) s.x = -s.x;  // mirrored half of the time
        if (trial % 3 == 0) s.z = -s.z;
        model = glm::scale(model, s);
        Mesh mesh = sphere;
        mesh.model = model;
        const FaceGeometry geometry = computeFaceGeometry(mesh);
        const std::vector<glm::vec3> world = worldPositions(mesh);
        for (size_t f = 0; f < mesh.faceCount(); ++f) {
            const glm::dvec3 fromVertices = glm::normalize(newellNormal(world.data(), mesh.faceBegin(f), 3));
            EXPECT_NEAR(glm::length(geometry.normals[f] - fromVertices), 0.0, 1e-5) << "trial " << trial << " face " << f;
            EXPECT_NEAR(glm::dot(geometry.normals[f], glm::dvec3(world[mesh.faceBegin(f)[0]]) - geometry.centroids[f]), 0.0, 1e-5);
        }
        // A mirror turns the sphere's winding inside out, and the normals follow the winding.
        const glm::dvec3 center(model * glm::dvec4(0, 0, 0, 1));
        const double side = glm::determinant(model) > 0.0 ? 1.0 : -1.0;
        for (size_t f = 0; f < mesh.faceCount(); ++f)
            EXPECT_GT(side * glm::dot(geometry.normals[f], geometry.centroids[f] - center), 0.0);
    }
}

TEST(Mesh, FaceGeometryOfLargeMeshesIsComputedOnAllCoresTheSameAsFaceByFace) {
    // 163,840 triangles: enough for the arrays to be sized and filled on several threads (and
    // for huge-page hints). Every face must come out as it does in a mesh of its own, computed
    // in one piece, including under a mirroring, scaling transform and for degenerate faces.
    Mesh mesh = testmesh::torus(1.0, 0.3, 512, 160);
    for (uint32_t f = 0; f < mesh.faceCount(); f += 997) mesh.faceVertices[mesh.faceStarts[f] + 1] = mesh.faceBegin(f)[0];
    mesh.model = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, -2.0, 1.0)), glm::dvec3(-2.0, 1.0, 3.0));
    const FaceGeometry geometry = computeFaceGeometry(mesh);
    ASSERT_EQ(geometry.normals.size(), mesh.faceCount());
    size_t degenerate = 0;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
        degenerate += geometry.degenerate[f];
        if (f % 61 != 0 && f % 997 != 0) continue;
        Mesh single;
        single.positions = mesh.positions;
        single.model = mesh.model;
        single.addFace(mesh.faceBegin(f), mesh.faceSize(f));
        const FaceGeometry alone = computeFaceGeometry(single);
        ASSERT_EQ(geometry.degenerate[f], alone.degenerate[0]) << "face " << f;
        EXPECT_EQ(geometry.normals[f], alone.normals[0]) << "face " << f;
        EXPECT_EQ(geometry.centroids[f], alone.centroids[0]) << "face " << f;
        EXPECT_EQ(geometry.areas[f], alone.areas[0]) << "face " << f;
    }
    EXPECT_EQ(degenerate, (mesh.faceCount() + 996) / 997);
    EXPECT_EQ(geometry.degenerateCount, degenerate);
}

TEST(Mesh, ValidateRejectsBrokenMeshes) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.addFace({0, 1, 2});
    EXPECT_NO_THROW(validateMesh(mesh));
    Mesh outOfRange = mesh;
    outOfRange.addFace({0, 1, 7});
    EXPECT_THROW(validateMesh(outOfRange), std::runtime_error);
    Mesh tooSmall = mesh;
    tooSmall.addFace({0, 1});
    EXPECT_THROW(validateMesh(tooSmall), std::runtime_error);
    Mesh notFinite = mesh;
    notFinite.positions[1].x = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(validateMesh(notFinite), std::runtime_error);
    Mesh badArray = mesh;
    badArray.faceArrays["cluster_id"] = {1, 2};
    EXPECT_THROW(validateMesh(badArray), std::runtime_error);
    Mesh singular = mesh;
    singular.model = glm::dmat4(0.0);
    EXPECT_THROW(validateMesh(singular), std::runtime_error);
}

TEST(Views, OrbitFollowsTheDocumentedFormula) {
    Aabb box{{-1, -2, -3}, {3, 2, 1}};
    const auto views = orbitViews(box, 5, 3.0);
    ASSERT_EQ(views.size(), 5u);
    const double radius = 0.5 * glm::length(glm::dvec3(4, 4, 4));
    for (size_t i = 0; i < 5; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / 5.0, r = std::sqrt(1 - y * y), phi = i * M_PI * (3 - std::sqrt(5.0));
        const glm::dvec3 expected = glm::dvec3(1, 0, -1) + 3.0 * radius * glm::dvec3(std::cos(phi) * r, y, std::sin(phi) * r);
        EXPECT_NEAR(glm::length(views[i].position - expected), 0.0, 1e-6);  // R is a float half-diagonal
        EXPECT_FALSE(views[i].orthographic);
    }
    const auto ortho = orbitViews(box, 3, 2.0, true);
    for (const Eye& eye : ortho) {
        EXPECT_TRUE(eye.orthographic);
        EXPECT_NEAR(glm::length(eye.direction), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(eye.direction, glm::normalize(glm::dvec3(1, 0, -1) - eye.position)), 1.0, 1e-9);
    }
}

TEST(Views, OrthographicViewsReportThePointTheirDirectionCameFrom) {
    const Aabb box{glm::vec3(-1.0f), glm::vec3(1.0f)};
    Settings settings;
    settings.orthographic = true;
    settings.eye = glm::dvec3(0.0, 0.0, 4.0);
    const std::vector<Eye> single = viewsFor(settings, box);
    ASSERT_EQ(single.size(), 1u);
    EXPECT_TRUE(single[0].orthographic);
    EXPECT_EQ(single[0].position, glm::dvec3(0.0, 0.0, 4.0));
    EXPECT_EQ(single[0].direction, glm::dvec3(0.0, 0.0, -1.0));
    // Orbit views: the same points as the perspective orbit, looking at the centre.
    settings.eye.reset();
    settings.views = 8;
    const std::vector<Eye> orbit = viewsFor(settings, box);
    const std::vector<Eye> perspective = orbitViews(box, 8, settings.distance);
    ASSERT_EQ(orbit.size(), 8u);
    for (size_t i = 0; i < orbit.size(); ++i) {
        EXPECT_TRUE(orbit[i].orthographic);
        EXPECT_EQ(orbit[i].position, perspective[i].position);
        EXPECT_NEAR(glm::dot(orbit[i].direction, glm::normalize(-perspective[i].position)), 1.0, 1e-12);
    }
}

TEST(Mesh, SortedCornersAreTheSameForEveryOrderOfATriangle) {
    const std::array<uint32_t, 3> expected{2, 5, 9};
    std::array<uint32_t, 3> corners{9, 2, 5};
    std::sort(corners.begin(), corners.end());
    do {
        EXPECT_EQ(sortedCorners(corners[0], corners[1], corners[2]), expected);
    } while (std::next_permutation(corners.begin(), corners.end()));
    EXPECT_EQ(sortedCorners(4, 4, 1), (std::array<uint32_t, 3>{1, 4, 4}));
}
