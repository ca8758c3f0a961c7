#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "TestMeshes.h"
#include "core/Culling.h"
#include "ScreenSpace.h"

using namespace conescope;

// Seed 001's worked example: V0(2,2), V1(5,3), V2(3,4) has area 2.5 (counter-clockwise), and the
// same triangle listed V0, V2, V1 has area -2.5.
TEST(ScreenSpace, SeedWorkedExample) {
    const glm::dvec2 counterClockwise[3] = {{2, 2}, {5, 3}, {3, 4}};
    const glm::dvec2 clockwise[3] = {{2, 2}, {3, 4}, {5, 3}};
    EXPECT_DOUBLE_EQ(0.5 * signedArea2D(counterClockwise, 3), 2.5);
    EXPECT_DOUBLE_EQ(0.5 * signedArea2D(clockwise, 3), -2.5);
}

// Seed 004's example: A top-left, B bottom-left, C bottom-right faces the viewer; A, C, B does not.
TEST(ScreenSpace, SeedRightHandRuleExample) {
    const glm::dvec3 a(0, 1, 0), b(0, 0, 0), c(1, 0, 0);
    const glm::dvec3 eye(0.3, 0.3, 5);
    const glm::dmat4 transform = viewProjection(eye, {0.3, 0.3, 0}, 60, 1, 0.1, 100);
    const glm::dvec3 facing[3] = {a, b, c}, away[3] = {a, c, b};
    EXPECT_EQ(classifyByScreenArea(transform, facing, 3), ScreenFacing::Front);
    EXPECT_EQ(classifyByScreenArea(transform, away, 3), ScreenFacing::Back);
    // The normal test agrees: (B-A)x(C-A) = +z, n.(e - A) > 0.
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), eye - a), 0.0);
}

// World-space normal test and clip-space signed area agree for every face in front of the eye,
// with ordinary and mirrored model matrices.
TEST(ScreenSpace, AgreesWithNormalTestIncludingMirrors) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Mesh base = testmesh::torus(1.0, 0.4, 24, 12);
    size_t compared = 0;
    for (int trial = 0; trial < 60; ++trial) {
        Mesh mesh = base;
        glm::dvec3 s(1.0 + 0.5 * unit(random), 1.0 + 0.5 * unit(random), 1.0 + 0.5 * unit(random));
        if (trial % 2) s.y = -s.y;
        mesh.model = glm::scale(glm::rotate(glm::dmat4(1.0), unit(random) * 3, glm::dvec3(0.3, 1, 0.2)), s);
        const auto world = worldPositions(mesh);
        const FaceGeometry faces = computeFaceGeometry(mesh);
        const glm::dvec3 eye = glm::normalize(glm::dvec3(unit(random), unit(random), unit(random))) * 4.0;
        const glm::dmat4 transform = viewProjection(eye, glm::dvec3(0.0), 70, 1.3, 0.05, 50);
        const Eye perspective = Eye::perspective(eye);
        for (size_t f = 0; f < mesh.faceCount(); ++f) {
            glm::dvec3 corners[3];
            for (int k = 0; k < 3; ++k) corners[k] = glm::dvec3(world[mesh.faceBegin(f)[k]]);
            const ScreenFacing screen = classifyByScreenArea(transform, corners, 3);
            if (screen == ScreenFacing::Clipped || screen == ScreenFacing::EdgeOn) continue;
            const Facing truth = classifyFace(mesh, world, faces, f, perspective);
            EXPECT_EQ(screen == ScreenFacing::Back, truth == Facing::Back) << "trial " << trial << " face " << f;
            ++compared;
        }
    }
    EXPECT_GT(compared, 30000u);
}
