// The batched float tests: every SIMD level agrees with the scalar reference bit for bit, no batched
// test ever culls a cluster holding a front-facing face (the per-face oracle decides), and the
// rounding slack costs almost nothing: on real meshes the batch culls at least 98% of what the
// double-precision test culls.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "TestMeshes.h"
#include "core/BatchCulling.h"
#include "core/Culling.h"
#include "core/Settings.h"

using namespace conescope;
using testmesh::randomModel;
using testmesh::randomSoup;
using testmesh::randomUnit;

namespace {

const std::vector<CullTest> kBatchedTests = {CullTest::Sphere, CullTest::Apex, CullTest::MeshoptSphere, CullTest::Octagon};
const std::vector<SimdLevel> kLevels = {SimdLevel::Scalar, SimdLevel::Sse2, SimdLevel::Avx2};

// Perspective eyes of the awkward kinds: anywhere near or far, on a face plane or a hair off it, at a vertex.
std::vector<Eye> awkwardEyes(std::mt19937_64& random, const Mesh& mesh, const std::vector<glm::vec3>& world,
                             const FaceGeometry& faces, size_t count) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Aabb box = computeAabb(world);
    const glm::dvec3 center(box.center());
    const double radius = std::max(double(box.halfDiagonal()), 1e-30);
    std::vector<Eye> eyes;
    while (eyes.size() < count) {
        const size_t kind = eyes.size() % 4;
        if (kind == 0 || kind == 3) {
            eyes.push_back(Eye::perspective(center + randomUnit(random) * radius * std::pow(10.0, 3.0 * unit(random) - 1.5)));
        } else if (kind == 1) {
            const size_t f = size_t(unit(random) * double(mesh.faceCount())) % mesh.faceCount();
            if (faces.degenerate[f]) continue;
            const glm::dvec3 q(world[mesh.faceBegin(f)[0]]);
            const glm::dvec3 along = glm::normalize(glm::cross(faces.normals[f], randomUnit(random)));
            const double offset = unit(random) < 0.5 ? 0.0 : (unit(random) - 0.5) * 1e-7 * radius;
            eyes.push_back(Eye::perspective(q + along * radius * 3.0 * unit(random) + faces.normals[f] * offset));
        } else {
            const size_t v = size_t(unit(random) * double(world.size())) % world.size();
            eyes.push_back(Eye::perspective(glm::dvec3(world[v])));
        }
    }
    return eyes;
}

// Clusters with at least one front-facing face from this eye.
std::vector<uint8_t> clustersWithFrontFaces(const CullingInput& input, const Eye& eye) {
    const std::vector<Facing> facing = classifyFaces(input.mesh, input.world, input.faces, eye);
    const ClusterFaces& rows = input.bounds.faces;
    std::vector<uint8_t> front(input.bounds.count(), 0);
    for (uint32_t c = 0; c < front.size(); ++c)
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) front[c] |= facing[rows.faces[i]] == Facing::Front;
    return front;
}

struct Counts {
    size_t decisions = 0;
    size_t batchCulls = 0;
    size_t doubleCulls = 0;
    size_t bothCull = 0;       // culled by the batch and by the double test
    size_t falseCulls = 0;     // batch culled a cluster holding a front-facing face
    size_t levelMismatches = 0;
};

// Every batched test at every level against the double test and the oracle, for these eyes.
void compare(const Mesh& mesh, const Partition& partition, const std::vector<Eye>& eyes, Counts& counts) {
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    for (ConeMethod cone : allConeMethods()) {
        const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, cone);
        const CullingInput input{mesh, world, faces, bounds};
        const ClusterBatch batch = makeClusterBatch(bounds);
        for (const Eye& eye : eyes) {
            const std::vector<uint8_t> front = clustersWithFrontFaces(input, eye);
            for (CullTest test : kBatchedTests) {
                const std::vector<uint8_t> reference = cullBatch(batch, eye.position, test, SimdLevel::Scalar);
                for (SimdLevel level : kLevels)
                    counts.levelMismatches += cullBatch(batch, eye.position, test, level) != reference;
                const std::vector<uint8_t> exact = cullClustersExact(input, eye, test);
                for (size_t c = 0; c < bounds.count(); ++c) {
                    ++counts.decisions;
                    counts.batchCulls += reference[c];
                    counts.doubleCulls += exact[c];
                    counts.bothCull += reference[c] && exact[c];
                    if (reference[c] && front[c]) {
                        ++counts.falseCulls;
                        ADD_FAILURE() << "false cull: cone " << toString(cone) << " test " << toString(test) << " cluster "
                                      << c << " eye (" << eye.position.x << ", " << eye.position.y << ", "
                                      << eye.position.z << ")";
                    }
                }
            }
        }
    }
}


}  // namespace

TEST(BatchCulling, LayoutIsPaddedAndUncullableClustersNeverPass) {
    Mesh mesh = testmesh::icosphere(2);  // 320 faces
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    // 13 clusters: 12 of single faces and one holding all the rest (wider than a hemisphere).
    Partition partition;
    partition.clusterOfFace.assign(mesh.faceCount(), 12);
    for (uint32_t f = 0; f < 12; ++f) partition.clusterOfFace[f * 20] = f;
    partition.clusterCount = 13;
    const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
    ASSERT_FALSE(bounds.cones[12].cullable);
    const ClusterBatch batch = makeClusterBatch(bounds);
    EXPECT_EQ(batch.count, 13u);
    EXPECT_EQ(batch.paddedCount(), 16u);
    for (const std::vector<float>* column : {&batch.axisX, &batch.sinHalfAngle, &batch.cosHalfAngleUp, &batch.radius, &batch.apexZ})
        EXPECT_EQ(column->size(), 16u);
    EXPECT_EQ(batch.octagonBlocks.size(), 16u * ClusterBatch::kOctagonFields);
    EXPECT_GT(batch.sinHalfAngle[12], 1.0f);
    EXPECT_EQ(batch.axisX[12], 0.0f);
    for (size_t field = 3; field < ClusterBatch::kOctagonFields; ++field)  // the uncullable cluster's edges are zero
        EXPECT_EQ(batch.octagonBlocks[8 * ClusterBatch::kOctagonFields + 8 * field + 4], 0.0f);
    // Rounding goes the safe way: thresholds and radii never smaller than the double values.
    for (size_t c = 0; c < 12; ++c) {
        EXPECT_GE(double(batch.sinHalfAngle[c]), bounds.cones[c].sinHalfAngle + kBatchSinMargin);
        EXPECT_GE(double(batch.cosHalfAngleUp[c]), bounds.cones[c].cosHalfAngle);
        EXPECT_LE(double(batch.cosHalfAngleDown[c]), bounds.cones[c].cosHalfAngle);
        EXPECT_GE(double(batch.radius[c]), bounds.spheres[c].radius);
    }
    // Writes exactly `count` bytes, whatever the level's width.
    for (CullTest test : kBatchedTests)
        for (SimdLevel level : kLevels) {
            std::vector<uint8_t> culled(20, 0xAB);
            cullBatch(batch, glm::dvec3(0.0), test, culled.data(), level);
            for (size_t i = 13; i < culled.size(); ++i) EXPECT_EQ(culled[i], 0xAB) << toString(test) << " " << toString(level);
            for (size_t i = 0; i < 13; ++i) EXPECT_LE(culled[i], 1) << toString(test);
        }
    // The centre of the sphere sees the back of every face: the single-face clusters are culled by the
    // apex and octagon tests; the big cluster never is.
    for (CullTest test : {CullTest::Apex, CullTest::Octagon})
        for (SimdLevel level : kLevels) {
            const std::vector<uint8_t> culled = cullBatch(batch, glm::dvec3(0.0), test, level);
            for (size_t c = 0; c < 12; ++c) EXPECT_EQ(culled[c], 1) << c << " " << toString(test) << " " << toString(level);
            EXPECT_EQ(culled[12], 0);
        }
}

TEST(BatchCulling, FlatClusterEdgeOnIsNeverCulledAndJustBehindIs) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.addFace({0, 1, 2});
    mesh.addFace({0, 2, 3});
    // Far from the origin, where float spacing is coarse compared with the square.
    mesh.model = glm::translate(glm::dmat4(1.0), glm::dvec3(1000.0, -2000.0, 500.0));
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    Partition partition{{0, 0}, 1};
    for (ConeMethod cone : allConeMethods()) {
        const ClusterBatch batch = makeClusterBatch(computeClusterBounds(mesh, world, faces, partition, cone));
        const glm::dvec3 corner(1000.0, -2000.0, 500.0);
        for (CullTest test : kBatchedTests)
            for (SimdLevel level : kLevels) {
                const std::string name = toString(cone) + "/" + toString(test) + "/" + toString(level);
                EXPECT_EQ(cullBatch(batch, corner + glm::dvec3(0.5, 0.5, -10.0), test, level)[0], 1) << name;
                EXPECT_EQ(cullBatch(batch, corner + glm::dvec3(0.5, 0.5, 10.0), test, level)[0], 0) << name;
                EXPECT_EQ(cullBatch(batch, corner + glm::dvec3(30.0, 0.5, 0.0), test, level)[0], 0) << name;   // edge-on
                EXPECT_EQ(cullBatch(batch, corner + glm::dvec3(30.0, 0.5, 1e-6), test, level)[0], 0) << name;  // a hair in front
                EXPECT_EQ(cullBatch(batch, corner, test, level)[0], 0) << name;                                // at a vertex
                const double nan = std::numeric_limits<double>::quiet_NaN();
                EXPECT_EQ(cullBatch(batch, glm::dvec3(nan, 0.0, 0.0), test, level)[0], 0) << name;
            }
    }
}

// One cluster whose apex lies very far (a face nearly edge-on to its cone's axis pushes it back)
// loosens its own test only: the rounding slack is each cluster's, so the others still cull. (With
// one slack for the whole batch a single such cluster in assimp's 2CylinderEngine made
// every batched test cull nothing on the whole mesh.)
TEST(BatchCulling, AFarApexLoosensOnlyItsOwnCluster) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {3, 0, 0}, {4, 0, 0}, {4, 1, 0}, {3, 1, 0}};
    mesh.addFace({0, 1, 2});
    mesh.addFace({0, 2, 3});
    mesh.addFace({4, 5, 6});
    mesh.addFace({4, 6, 7});
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    ClusterBounds bounds = computeClusterBounds(mesh, world, faces, Partition{{0, 0, 1, 1}, 2}, ConeMethod::Minimal);
    const glm::dvec3 eye(0.5, 0.5, -10.0);
    for (CullTest test : kBatchedTests)
        for (SimdLevel level : kLevels) EXPECT_EQ(cullBatch(makeClusterBatch(bounds), eye, test, level)[0], 1) << toString(test);
    bounds.apexes[1] = glm::dvec3(3.5, 0.5, -1e12);  // still behind its faces: a valid, if useless, apex
    bounds.spheres[1].center.x = 1e11;               // and a centre far away
    const ClusterBatch batch = makeClusterBatch(bounds);
    for (CullTest test : kBatchedTests)
        for (SimdLevel level : kLevels) EXPECT_EQ(cullBatch(batch, eye, test, level)[0], 1) << toString(test) << " " << toString(level);
}

TEST(BatchCulling, SphereTestNeverCullsWithTheEyeInsideTheSphere) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.addFace({0, 1, 2});
    mesh.addFace({0, 2, 3});
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const ClusterBatch batch = makeClusterBatch(computeClusterBounds(mesh, world, faces, Partition{{0, 0}, 1}, ConeMethod::Minimal));
    for (SimdLevel level : kLevels) {
        EXPECT_EQ(cullBatch(batch, {0.5, 0.5, -0.1}, CullTest::Sphere, level)[0], 0);
        EXPECT_EQ(cullBatch(batch, {0.5, 0.5, -10.0}, CullTest::Sphere, level)[0], 1);
    }
}

TEST(BatchCulling, OnlySphereApexOctagonAndMeshoptSphereHaveABatchedForm) {
    for (CullTest test : allCullTests()) {
        const bool batched = std::find(kBatchedTests.begin(), kBatchedTests.end(), test) != kBatchedTests.end();
        EXPECT_EQ(batchSupports(test), batched) << toString(test);
        if (!batched) EXPECT_THROW(cullBatch(ClusterBatch{}, glm::dvec3(0.0), test), std::invalid_argument);
    }
    EXPECT_TRUE(cullBatch(ClusterBatch{}, glm::dvec3(0.0), CullTest::Apex).empty());
    std::cout << "[ batch    ] best SIMD level on this CPU: " << toString(bestSimdLevel()) << "\n";
}

// Property: random clusters (patches, soups, single faces, meshlets of a sphere) at coordinates from
// 1e-6 to 1e6, mirrored or not, up to 1e5 times their size away from the origin, seen from awkward eyes.
TEST(BatchCulling, RandomClustersNeverCullAFrontFacingFace) {
    std::mt19937_64 random(20261123);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Counts counts;
    for (size_t m = 0; m < 600; ++m) {
        Mesh mesh;
        const size_t kind = m % 4;
        if (kind == 0) mesh = testmesh::randomPatch(random, 2 + int(m % 5), 80.0 * unit(random));
        else if (kind == 1) mesh = randomSoup(random, 1 + m % 12, 120.0 * unit(random));
        else if (kind == 2) mesh = randomSoup(random, 1, 0.0);
        else mesh = testmesh::icosphere(1);
        const double scale = std::pow(10.0, 12.0 * unit(random) - 6.0);
        mesh.model = randomModel(random, scale);
        // A third of the clusters sit far from the origin compared with their size, where float
        // spacing is coarse next to the eye distances: the absolute slack is what keeps these safe.
        if (m % 3 == 0)
            mesh.model = glm::translate(glm::dmat4(1.0), randomUnit(random) * scale * std::pow(10.0, 1.0 + 4.0 * unit(random))) *
                         mesh.model;
        Partition partition;
        if (kind == 3 || (kind == 0 && m % 2)) {
            partition = buildMeshlets(mesh, computeFaceGeometry(mesh), MeshletLimits{12, 8});
        } else {
            partition.clusterOfFace.assign(mesh.faceCount(), 0);
            partition.clusterCount = 1;
        }
        const std::vector<glm::vec3> world = worldPositions(mesh);
        compare(mesh, partition, awkwardEyes(random, mesh, world, computeFaceGeometry(mesh), 60), counts);
    }
    std::cout << "[ batch    ] " << counts.decisions << " decisions, " << counts.batchCulls << " batch culls, "
              << counts.doubleCulls << " double culls, " << counts.falseCulls << " false culls\n";
    EXPECT_GE(counts.decisions, 200000u);
    EXPECT_EQ(counts.levelMismatches, 0u);
    EXPECT_EQ(counts.falseCulls, 0u);
    EXPECT_GT(counts.batchCulls, counts.decisions / 20);  // not vacuous
}

// The bundled meshes seen from the standard orbits: zero false culls, and the float slack loses at
// most 2% of the double test's culls.
TEST(BatchCulling, BundledMeshesFromOrbitsLoseAtMostTwoPercent) {
    for (const std::string name : {"elephant.off", "fandisk.off", "icosphere.off", "torus.off"}) {
        const Mesh mesh = testmesh::readBundledOff(name);
        const Partition partition = buildMeshlets(mesh, computeFaceGeometry(mesh), MeshletLimits{64, 124});
        const Aabb box = computeAabb(worldPositions(mesh));
        std::vector<Eye> eyes;
        for (double distance : {1.5, 3.0, 10.0})
            for (const Eye& eye : orbitViews(box, 32, distance)) eyes.push_back(eye);
        Counts counts;
        compare(mesh, partition, eyes, counts);
        std::cout << "[ batch    ] " << name << ": " << counts.batchCulls << " batch culls, " << counts.doubleCulls
                  << " double culls, " << counts.bothCull << " both\n";
        EXPECT_EQ(counts.levelMismatches, 0u) << name;
        EXPECT_EQ(counts.falseCulls, 0u) << name;
        EXPECT_GT(counts.doubleCulls, counts.decisions / 10) << name;
        EXPECT_GE(double(counts.bothCull), 0.98 * double(counts.doubleCulls)) << name;
    }
}
