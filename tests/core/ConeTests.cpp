#include <gtest/gtest.h>

#include <random>

#include "TestMeshes.h"
#include "core/Cones.h"

using namespace conescope;
using testmesh::randomUnit;

namespace {

// Normals within `spread` radians of a random axis, some of them exactly on the rim.
std::vector<glm::dvec3> randomNormals(std::mt19937_64& random, size_t count, double spread) {
    const glm::dvec3 axis = randomUnit(random);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::dvec3> normals;
    for (size_t i = 0; i < count; ++i) {
        glm::dvec3 side = glm::normalize(glm::cross(axis, randomUnit(random)));
        const double angle = (i % 4 == 0 ? 1.0 : unit(random)) * spread;
        normals.push_back(glm::normalize(std::cos(angle) * axis + std::sin(angle) * side));
    }
    return normals;
}

// Brute force: the best cos(alpha) over many axes (random, then refined around the best).
double bruteForceBestCos(std::mt19937_64& random, const std::vector<glm::dvec3>& normals) {
    auto coverage = [&](const glm::dvec3& axis) {
        double m = 2.0;
        for (const auto& n : normals) m = std::min(m, glm::dot(n, axis));
        return m;
    };
    glm::dvec3 best = normals[0];
    double bestValue = coverage(best);
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 axis = randomUnit(random);
        const double value = coverage(axis);
        if (value > bestValue) bestValue = value, best = axis;
    }
    for (double step = 0.1; step > 1e-7; step *= 0.7)
        for (int i = 0; i < 40; ++i) {
            const glm::dvec3 axis = glm::normalize(best + step * randomUnit(random));
            const double value = coverage(axis);
            if (value > bestValue) bestValue = value, best = axis;
        }
    return bestValue;
}

void expectHoldsAll(const ConeOfNormals& cone, const std::vector<glm::dvec3>& normals) {
    ASSERT_TRUE(cone.cullable);
    for (const auto& n : normals) EXPECT_GE(glm::dot(n, cone.axis), cone.cosHalfAngle);
    EXPECT_NEAR(glm::length(cone.axis), 1.0, 1e-12);
    EXPECT_GE(cone.sinHalfAngle, std::sqrt(1 - cone.cosHalfAngle * cone.cosHalfAngle));
}

}  // namespace

// Seed 000: V1 is the normalised average and B = asin(min n.V1), i.e. sin(alpha) = cos(B).
TEST(Cones, AverageConeFollowsTheSeed) {
    const std::vector<glm::dvec3> normals = {glm::normalize(glm::dvec3(1, 0, 1)), glm::normalize(glm::dvec3(-1, 0, 1)),
                                             {0, 0, 1}};
    const ConeOfNormals cone = averageCone(normals.data(), normals.size());
    EXPECT_NEAR(glm::length(cone.axis - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
    const double angleB = std::asin(std::sqrt(0.5));
    EXPECT_NEAR(cone.cosHalfAngle, std::sin(angleB), 1e-9);
    EXPECT_NEAR(cone.sinHalfAngle, std::cos(angleB), 1e-9);
    EXPECT_NEAR(glm::degrees(cone.halfAngle()), 45.0, 1e-6);
}

TEST(Cones, EveryMethodHoldsEveryNormalAndMinimalIsNeverWider) {
    std::mt19937_64 random(42);
    for (int trial = 0; trial < 2000; ++trial) {
        const double spread = glm::radians(1.0 + 88.0 * (trial % 50) / 50.0);
        const auto normals = randomNormals(random, 3 + trial % 60, spread);
        const ConeOfNormals average = averageCone(normals.data(), normals.size());
        const ConeOfNormals seed = seedSphereCone(normals.data(), normals.size());
        const ConeOfNormals minimal = minimalCone(normals.data(), normals.size());
        expectHoldsAll(minimal, normals);
        if (average.cullable) expectHoldsAll(average, normals);
        if (seed.cullable) expectHoldsAll(seed, normals);
        EXPECT_GE(minimal.cosHalfAngle, average.cosHalfAngle - 1e-12);
        EXPECT_GE(minimal.cosHalfAngle, seed.cosHalfAngle - 1e-12);
        // The true optimum lies within the generator's spread.
        EXPECT_GE(minimal.cosHalfAngle, std::cos(spread) - 1e-9);
    }
}

TEST(Cones, MinimalMatchesBruteForce) {
    std::mt19937_64 random(3);
    for (int trial = 0; trial < 200; ++trial) {
        const auto normals = randomNormals(random, 3 + trial % 30, glm::radians(5.0 + 80.0 * (trial % 17) / 17.0));
        const ConeOfNormals minimal = minimalCone(normals.data(), normals.size());
        const double brute = bruteForceBestCos(random, normals);
        EXPECT_GE(minimal.cosHalfAngle, brute - 1e-9) << "trial " << trial;
    }
}

TEST(Cones, WiderThanAHemisphereIsNeverCullable) {
    const std::vector<glm::dvec3> opposite = {{1, 0, 0}, {-1, 0, 0}};
    EXPECT_FALSE(averageCone(opposite.data(), 2).cullable);
    EXPECT_FALSE(seedSphereCone(opposite.data(), 2).cullable);
    EXPECT_FALSE(minimalCone(opposite.data(), 2).cullable);
    // Four normals spanning a tetrahedron: the origin is inside their hull.
    const std::vector<glm::dvec3> spread = {glm::normalize(glm::dvec3(1, 1, 1)), glm::normalize(glm::dvec3(1, -1, -1)),
                                            glm::normalize(glm::dvec3(-1, 1, -1)), glm::normalize(glm::dvec3(-1, -1, 1))};
    EXPECT_FALSE(minimalCone(spread.data(), 4).cullable);
    // Exactly a hemisphere (normals on a great circle) is not narrower than one either.
    const std::vector<glm::dvec3> rim = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    EXPECT_FALSE(minimalCone(rim.data(), 4).cullable);
}

TEST(Cones, DegenerateNormalsAreIgnoredAndAllDegenerateIsNotCullable) {
    const std::vector<glm::dvec3> normals = {{0, 0, 1}, {0, 0, 0}, glm::normalize(glm::dvec3(0.1, 0, 1))};
    const ConeOfNormals cone = minimalCone(normals.data(), normals.size());
    EXPECT_TRUE(cone.cullable);
    EXPECT_LT(glm::degrees(cone.halfAngle()), 3.0);
    const std::vector<glm::dvec3> none = {{0, 0, 0}, {0, 0, 0}};
    EXPECT_FALSE(minimalCone(none.data(), 2).cullable);
    EXPECT_FALSE(averageCone(none.data(), 2).cullable);
}

TEST(Cones, SingleNormalGivesAZeroAngleCone) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 2, 3));
    const ConeOfNormals cone = minimalCone(&n, 1);
    EXPECT_TRUE(cone.cullable);
    EXPECT_LT(cone.halfAngle(), 1e-5);
}
