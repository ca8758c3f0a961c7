// The eight-sided cone of normals: it holds every normal, it is tighter than the round cap where the
// normals spread one way, its share of view directions is the exact area of its pyramid, and its
// test culls from eyes the round apex test cannot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "TestMeshes.h"
#include "core/ClusterBounds.h"
#include "core/Culling.h"
#include "core/ExpectedCull.h"

using namespace conescope;
using testmesh::randomUnit;

namespace {

// Normals within `spreadDegrees` of an axis, squeezed `squeeze` times in one direction (1 = round).
std::vector<glm::dvec3> randomNormals(std::mt19937_64& random, size_t count, double spreadDegrees, double squeeze) {
    const glm::dvec3 axis = randomUnit(random);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, randomUnit(random))), w = glm::cross(axis, u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double reach = std::tan(glm::radians(spreadDegrees));
    std::vector<glm::dvec3> normals;
    while (normals.size() < count) {
        const double x = unit(random), y = unit(random);
        if (x * x + y * y > 1.0) continue;
        normals.push_back(glm::normalize(axis + reach * (x * u + y * w / squeeze)));
    }
    return normals;
}

// Whether n is a non-negative combination of the octagon's edges: on the inner side of the plane
// through every two neighbouring edges (a little rounding allowed).
bool holds(const OctagonCone& octagon, const glm::dvec3& n) {
    glm::dvec3 inside(0.0);
    for (const glm::dvec3& edge : octagon.edges) inside += edge;
    for (size_t k = 0; k < 8; ++k) {
        const glm::dvec3 side = glm::cross(octagon.edges[k], octagon.edges[(k + 1) % 8]);
        if (glm::length(side) < 1e-15) continue;  // a repeated edge
        const double sign = glm::dot(side, inside) > 0.0 ? 1.0 : -1.0;
        if (sign * glm::dot(side, n) < -1e-12) return false;
    }
    return true;
}

}  // namespace

TEST(OctagonCone, HoldsEveryNormal) {
    std::mt19937_64 random(41);
    size_t checked = 0;
    for (int round = 0; round < 400; ++round) {
        const size_t count = 1 + size_t(round % 40);
        const std::vector<glm::dvec3> normals = randomNormals(random, count, 2.0 + double(round % 85), 1.0 + double(round % 7));
        const ConeOfNormals cone = minimalCone(normals.data(), normals.size());
        ASSERT_TRUE(cone.cullable);
        const OctagonCone octagon = octagonCone(cone, normals.data(), normals.size());
        ASSERT_TRUE(octagon.cullable) << round;
        for (const glm::dvec3& edge : octagon.edges) EXPECT_NEAR(glm::length(edge), 1.0, 1e-12);
        for (const glm::dvec3& n : normals) {
            EXPECT_TRUE(holds(octagon, n)) << "round " << round;
            ++checked;
        }
    }
    EXPECT_GT(checked, 5000u);
    // No cone, no octagon: normals wider than a hemisphere, or none at all (zero normals only).
    const std::vector<glm::dvec3> opposite = {{0, 0, 1}, {0, 0, -1}};
    EXPECT_FALSE(octagonCone(minimalCone(opposite.data(), 2), opposite.data(), 2).cullable);
    const glm::dvec3 zero(0.0);
    EXPECT_FALSE(octagonCone(ConeOfNormals{}, &zero, 1).cullable);
}

TEST(OctagonCone, ShareIsTheExactAreaAndBeatsTheCapOnAnArc) {
    // Normals along an arc of half-width beta (a cylinder's): the octagon is a thin sliver, its
    // pyramid's cross-section a lune of (pi - 2 beta) / 2pi... of the sphere's 4 pi: 1/2 - beta/pi,
    // against (1 - sin beta) / 2 for the round cap of half-angle beta.
    for (double beta : {5.0, 20.0, 40.0, 70.0}) {
        std::vector<glm::dvec3> normals;
        for (int i = 0; i <= 20; ++i) {
            const double a = glm::radians(beta) * (2.0 * i / 20.0 - 1.0);
            normals.push_back({std::sin(a), 0.0, std::cos(a)});
        }
        const ConeOfNormals cone = minimalCone(normals.data(), normals.size());
        const OctagonCone octagon = octagonCone(cone, normals.data(), normals.size());
        const double lune = 0.5 - glm::radians(beta) / M_PI;
        EXPECT_NEAR(octagonCullShare(octagon), lune, 1e-6) << beta;
        EXPECT_GT(octagonCullShare(octagon), coneCullShare(cone.sinHalfAngle) + 0.01) << beta;
    }
    // A round spread: the octagon is a little wider than the cap, and its share a little smaller.
    std::mt19937_64 random(3);
    const std::vector<glm::dvec3> round = randomNormals(random, 400, 30.0, 1.0);
    const ConeOfNormals cone = minimalCone(round.data(), round.size());
    const double share = octagonCullShare(octagonCone(cone, round.data(), round.size()));
    EXPECT_LT(share, coneCullShare(cone.sinHalfAngle));
    EXPECT_GT(share, 0.9 * coneCullShare(cone.sinHalfAngle));
}

TEST(OctagonCone, NormalsShareIsTheSameAboutAnyConeThatHoldsThem) {
    // The hull of the normals on the sphere does not depend on the axis they are projected about:
    // the minimal cone's, the average cone's, or none given. Many normals (most inside the hull,
    // which the hull leaves out before sorting) and few; round and squeezed spreads.
    std::mt19937_64 random(17);
    for (int round = 0; round < 300; ++round) {
        const size_t count = 3 + size_t(round % 150);
        const std::vector<glm::dvec3> normals = randomNormals(random, count, 3.0 + double(round % 80), 1.0 + double(round % 9));
        const double alone = normalsCullShare(normals.data(), normals.size());
        const ConeOfNormals minimal = minimalCone(normals.data(), normals.size()), average = averageCone(normals.data(), normals.size());
        EXPECT_NEAR(normalsCullShare(normals.data(), normals.size(), &minimal), alone, 1e-12) << round;
        if (average.cullable && average.cosHalfAngle > 0.0) EXPECT_NEAR(normalsCullShare(normals.data(), normals.size(), &average), alone, 1e-12) << round;
        // Against the hull found the slow way: an edge from n_i to n_j is on it when every other normal
        // lies on one side of the plane through both (random normals: none on that plane).
        if (count <= 60) {
            double perimeter = 0.0;
            for (size_t i = 0; i < count; ++i)
                for (size_t j = 0; j < count; ++j) {
                    if (i == j) continue;
                    const glm::dvec3 side = glm::cross(normals[i], normals[j]);
                    bool allLeft = true;
                    for (size_t k = 0; k < count && allLeft; ++k) allLeft = k == i || k == j || glm::dot(side, normals[k]) > 0.0;
                    if (allLeft) perimeter += std::acos(std::clamp(glm::dot(normals[i], normals[j]), -1.0, 1.0));
                }
            EXPECT_NEAR(alone, (2.0 * M_PI - perimeter) / (4.0 * M_PI), 1e-9) << round;
        }
        // The polygon of the hull: never below what the octagon and the cap around the same normals give.
        EXPECT_GE(alone + 1e-12, octagonCullShare(octagonCone(minimal, normals.data(), normals.size()))) << round;
        EXPECT_GE(alone + 1e-12, coneCullShare(minimal.sinHalfAngle)) << round;
    }
    // A cone that does not hold them in front of its axis is not used: the minimal cone decides.
    const std::vector<glm::dvec3> opposite = {{0, 0, 1}, {0, 0, -1}};
    const ConeOfNormals notCullable{};
    EXPECT_EQ(normalsCullShare(opposite.data(), 2, &notCullable), 0.0);
}

TEST(OctagonCone, OctagonAndNormalsShareAtOnceAreEachAlone) {
    // One hull for both gives exactly what each finds alone: about the minimal cone, the average
    // cone, with zero normals (degenerate faces) among them, and for a cone that cannot be
    // projected about (the share then comes from the minimal cone of the nonzero normals).
    std::mt19937_64 random(29);
    for (int round = 0; round < 200; ++round) {
        std::vector<glm::dvec3> normals = randomNormals(random, 2 + size_t(round % 90), 2.0 + double(round % 100), 1.0 + double(round % 7));
        if (round % 3 == 0) normals.insert(normals.begin() + long(normals.size() / 2), glm::dvec3(0.0));
        std::vector<glm::dvec3> nonzero;
        for (const glm::dvec3& n : normals)
            if (n != glm::dvec3(0.0)) nonzero.push_back(n);
        const ConeOfNormals cones[3] = {minimalCone(nonzero.data(), nonzero.size()), averageCone(nonzero.data(), nonzero.size()),
                                        ConeOfNormals{}};
        for (const ConeOfNormals& cone : cones) {
            const OctagonAndShare both = octagonAndNormalsShare(cone, normals.data(), normals.size());
            const OctagonCone alone = octagonCone(cone, normals.data(), normals.size());
            EXPECT_EQ(both.octagon.cullable, alone.cullable) << round;
            EXPECT_EQ(both.octagon.edges, alone.edges) << round;
            EXPECT_EQ(both.normalsShare, normalsCullShare(nonzero.data(), nonzero.size(), &cone)) << round;
        }
    }
}

TEST(OctagonCone, CullsACylinderStripWhereTheRoundConeCannot) {
    // A strip of a cylinder around the y axis, normals within 40 degrees of +z in the xz plane. An
    // eye far off along -z and tilted 60 degrees towards y sees every face from behind (n.y = 0),
    // but 60 degrees is beyond the round cone's 90 - 40 = 50.
    Mesh mesh;
    const int columns = 8;
    for (int i = 0; i <= columns; ++i) {
        const double a = glm::radians(40.0) * (2.0 * i / columns - 1.0);
        for (double y : {0.0, 1.0}) mesh.positions.emplace_back(float(std::sin(a)), float(y), float(std::cos(a)));
    }
    for (uint32_t i = 0; i < uint32_t(columns); ++i) {
        const uint32_t a = 2 * i, b = 2 * i + 2;
        mesh.addFace({a, b, b + 1});
        mesh.addFace({a, b + 1, a + 1});
    }
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    ASSERT_GT(faces.normals[0].z, 0.5);  // outward: towards +z
    const Partition one{std::vector<uint32_t>(mesh.faceCount(), 0), 1};
    const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, one, ConeMethod::Minimal);
    const CullingInput input{mesh, world, faces, bounds};
    const glm::dvec3 tilted = 100.0 * glm::dvec3(0.0, std::sin(glm::radians(60.0)), -std::cos(glm::radians(60.0)));
    const Eye eye = Eye::perspective(glm::dvec3(0.0, 0.5, 0.0) + tilted);
    for (Facing facing : classifyFaces(mesh, world, faces, eye)) ASSERT_EQ(facing, Facing::Back);
    EXPECT_FALSE(cullCluster(input, 0, eye, CullTest::Apex));
    EXPECT_TRUE(cullCluster(input, 0, eye, CullTest::Octagon));
    EXPECT_EQ(cullClusters(input, eye, CullTest::Octagon)[0], 1);  // and so does the batched kernel
    // Straight behind both cull; in front neither does.
    const Eye behind = Eye::perspective({0.0, 0.5, -100.0}), before = Eye::perspective({0.0, 0.5, 100.0});
    EXPECT_TRUE(cullCluster(input, 0, behind, CullTest::Octagon));
    EXPECT_FALSE(cullCluster(input, 0, before, CullTest::Octagon));
    EXPECT_TRUE(cullCluster(input, 0, Eye::orthographicAlong(-tilted), CullTest::Octagon));
    EXPECT_FALSE(cullCluster(input, 0, Eye::orthographicAlong(-tilted), CullTest::Apex));
    // The explanation reads the same numbers: every edge passes, by the margin of the tightest.
    const CullExplanation why = explainCull(input, 0, eye, CullTest::Octagon);
    EXPECT_TRUE(why.exactCulled);
    EXPECT_EQ(why.edgesBack, 8u);
    EXPECT_GT(why.margin, 0.0);
    EXPECT_LT(explainCull(input, 0, before, CullTest::Octagon).margin, 0.0);
}

TEST(OctagonCone, PyramidEdgesBoundTheEyesItCullsFrom) {
    std::mt19937_64 random(17);
    for (int round = 0; round < 50; ++round) {
        const std::vector<glm::dvec3> normals = randomNormals(random, 30, 10.0 + round, 1.0 + round % 4);
        const OctagonCone octagon = octagonCone(minimalCone(normals.data(), normals.size()), normals.data(), normals.size());
        const std::array<glm::dvec3, 8> pyramid = octagonPyramidEdges(octagon);
        for (const glm::dvec3& edge : pyramid) {
            EXPECT_NEAR(glm::length(edge), 1.0, 1e-9);
            // On the pyramid's surface: no octagon edge sees it from the front, at least one is edge-on
            // (up to the 1e-7 within which neighbouring edges count once).
            double least = 1.0;
            for (const glm::dvec3& g : octagon.edges) {
                EXPECT_LT(glm::dot(g, edge), 1e-6);
                least = std::min(least, std::abs(glm::dot(g, edge)));
            }
            EXPECT_LT(least, 1e-9);
        }
        // Eyes inside the pyramid (positive mixes of its edges, behind the apex) are culled; an eye
        // along the cone's axis, in front, is not.
        glm::dvec3 inside(0.0);
        for (const glm::dvec3& edge : pyramid) inside += edge;
        EXPECT_TRUE(octagonSeesBack(octagon, -inside)) << round;  // the view vector runs from the eye to the apex
        EXPECT_FALSE(octagonSeesBack(octagon, inside)) << round;
    }
}
