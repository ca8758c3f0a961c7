#include <gtest/gtest.h>

#include <random>

#include "core/Spheres.h"

using namespace conescope;

TEST(Spheres, BothHoldEveryPointAndMinimalIsNoLarger) {
    std::mt19937_64 random(9);
    std::normal_distribution<double> gauss;
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<glm::dvec3> points(1 + trial % 80);
        const glm::dvec3 stretch(1.0 + trial % 3, 1.0, 0.01 + trial % 5);
        for (auto& p : points) p = glm::dvec3(gauss(random), gauss(random), gauss(random)) * stretch + 100.0;
        const Sphere ritter = ritterSphere(points.data(), points.size());
        const Sphere minimal = minimalSphere(points.data(), points.size());
        for (const auto& p : points) {
            EXPECT_LE(glm::length(p - ritter.center), ritter.radius);
            EXPECT_LE(glm::length(p - minimal.center), minimal.radius);
        }
        EXPECT_LE(minimal.radius, ritter.radius * (1 + 1e-9));
        // No pair of points is farther apart than the minimal diameter, and the minimal radius is at
        // least half the largest pairwise distance (a lower bound for any enclosing sphere).
        double widest = 0.0;
        for (const auto& a : points)
            for (const auto& b : points) widest = std::max(widest, glm::length(a - b));
        EXPECT_GE(minimal.radius * 2 * (1 + 1e-9), widest);
        EXPECT_LE(minimal.radius, widest * std::sqrt(3.0 / 8.0) * (1 + 1e-9) + 1e-9);  // Jung: r <= d sqrt(3/8)
    }
}

TEST(Spheres, KnownCases) {
    const glm::dvec3 tetrahedron[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    const Sphere s = minimalSphere(tetrahedron, 4);
    EXPECT_NEAR(glm::length(s.center), 0.0, 1e-12);
    EXPECT_NEAR(s.radius, std::sqrt(3.0), 1e-9);
    const glm::dvec3 segment[3] = {{0, 0, 0}, {2, 0, 0}, {1, 0.1, 0}};
    EXPECT_NEAR(minimalSphere(segment, 3).radius, 1.0, 1e-9);
    const glm::dvec3 single(5, 5, 5);
    EXPECT_NEAR(minimalSphere(&single, 1).radius, 0.0, 1e-9);
}
