// Where the back faces that were not culled went: the loss breakdown's identity, and the cull map's
// shares against exact areas and against each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "TestMeshes.h"
#include "core/CullMap.h"
#include "core/Pipeline.h"
#include "core/RecordTests.h"

using namespace conescope;

namespace {

// triangles_culled + test loss + partition loss = back-facing triangles, per view and over the
// views; the clusters' losses and misses add up to the result's.
void expectLossIdentity(const RunStatistics& run) {
    for (const CullTestStatistics& result : run.results) {
        const std::string name = toString(result.cone) + "/" + toString(result.test);
        size_t test = 0, partition = 0;
        for (const ViewStatistics& view : result.views) {
            EXPECT_EQ(view.trianglesCulled + view.testLossTriangles + view.partitionLossTriangles, view.backFacingTriangles)
                << name << " view " << view.view;
            test += view.testLossTriangles;
            partition += view.partitionLossTriangles;
        }
        EXPECT_EQ(test, result.testLossTriangles) << name;
        EXPECT_EQ(partition, result.partitionLossTriangles) << name;
        EXPECT_EQ(result.trianglesCulled + result.testLossTriangles + result.partitionLossTriangles, result.backFacingTriangles)
            << name;
        size_t clusterTest = 0, clusterPartition = 0, missed = 0;
        for (const ClusterStatistics& cluster : result.clusters) {
            clusterTest += cluster.testLossTriangles;
            clusterPartition += cluster.partitionLossTriangles;
            missed += cluster.timesMissed;
            EXPECT_LE(cluster.timesCulled + cluster.timesMissed, result.views.size());
            EXPECT_LE(cluster.timesMissed, cluster.timesBackFacing);
        }
        EXPECT_EQ(clusterTest, result.testLossTriangles) << name;
        EXPECT_EQ(clusterPartition, result.partitionLossTriangles) << name;
        EXPECT_EQ(missed, result.missedClusters) << name;
        if (result.test == CullTest::Oracle) EXPECT_EQ(result.testLossTriangles, 0u) << "the oracle misses nothing";
    }
}

// The cull map's promises: every round cone test's share is (1 - sin alpha)/2 of its cone, the
// octagon test's the area of its pyramid's cross-section, the oracle's share is never below either,
// and the means are the triangle-weighted means.
void expectCullMapShares(const RunStatistics& run, const Mesh& mesh, const Settings& settings) {
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition partition = buildPartition(mesh, faces, settings);
    for (const CullTestStatistics& result : run.results) {
        const ClusterBounds bounds = computeClusterBounds(mesh, worldPositions(mesh), faces, partition, result.cone, settings.sphere);
        double weighted = 0.0, triangles = 0.0;
        for (const ClusterStatistics& cluster : result.clusters) {
            const ConeOfNormals& cone = bounds.cones[cluster.cluster];
            const double coneShare = cone.cullable ? (1.0 - cone.sinHalfAngle) / 2.0 : 0.0;
            const double octagonShare = octagonCullShare(bounds.octagons[cluster.cluster]);
            if (result.test == CullTest::Oracle)
                EXPECT_EQ(cluster.cullFraction, cluster.oracleFraction);
            else if (result.test == CullTest::Octagon)
                EXPECT_DOUBLE_EQ(cluster.cullFraction, octagonShare);
            else if (result.test == CullTest::OctagonCompact)  // its best of 16 turns can beat the least-area octagon's by a little
                EXPECT_LE(cluster.cullFraction, octagonShare + 0.01) << "the compact octagon is the float one's, turned and rounded";
            else if (readsOwnRecord(result.test))
                EXPECT_TRUE(cluster.cullFraction >= 0.0 && cluster.cullFraction <= 1.0) << toString(result.test);
            else
                EXPECT_DOUBLE_EQ(cluster.cullFraction, coneShare) << toString(result.test);
            EXPECT_GE(cluster.oracleFraction, std::max(coneShare, octagonShare)) << "the oracle culls wherever a conservative test does";
            if (!result.engineRecord) EXPECT_GE(cluster.oracleFraction, cluster.cullFraction - 1e-12) << toString(result.test);
            EXPECT_LE(cluster.oracleFraction, 0.5) << "a closed cluster of faces faces away from at most half the sphere";
            weighted += cluster.cullFraction * double(cluster.triangles);
            triangles += double(cluster.triangles);
        }
        EXPECT_NEAR(result.cullFraction, weighted / triangles, 1e-12);
        if (!result.engineRecord) EXPECT_GE(result.oracleFraction, result.cullFraction);
    }
}

Settings everyTest(size_t views) {
    Settings settings;
    settings.cones = allConeMethods();
    settings.tests = allCullTests();
    settings.views = views;
    return settings;
}

}  // namespace

TEST(LossBreakdown, AddsUpOnBundledShapes) {
    for (const Mesh& mesh : {testmesh::torus(1.0, 0.4, 48, 24), testmesh::icosphere(3), testmesh::quadCube()}) {
        Settings settings = everyTest(24);
        settings.limits = {24, 32};
        const RunStatistics run = runStatistics(mesh, settings, "shape");
        expectLossIdentity(run);
        expectCullMapShares(run, mesh, settings);
    }
}

TEST(LossBreakdown, AddsUpOnRandomMeshesAndEyesInside) {
    std::mt19937_64 random(11);
    for (int round = 0; round < 6; ++round) {
        const Mesh mesh = testmesh::randomPatch(random, 12, 70.0);
        Settings settings = everyTest(16);
        settings.builder = round % 2 ? Builder::Meshlet : Builder::Optimized;
        settings.limits = {16, 20};
        // Close orbits put eyes among the faces, where partition losses are large.
        settings.distance = round % 3 == 0 ? 0.3 : 2.0;
        const RunStatistics run = runStatistics(mesh, settings, "patch");
        expectLossIdentity(run);
        size_t partitionLoss = 0;
        for (const CullTestStatistics& result : run.results) partitionLoss += result.partitionLossTriangles;
        EXPECT_GT(partitionLoss, 0u) << "clusters of a curved patch mix front and back faces from some eye";
    }
}

namespace {

// One cluster of three triangles meeting at a corner, normals -x, -y, -z, turned by `rotation`: every
// face faces away exactly from the directions u with u.x, u.y, u.z > 0 (rotated), an octant.
Mesh rotatedCorner(const glm::dmat3& rotation, int normals) {
    const glm::dvec3 corners[3][3] = {{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},   // normal -x
                                      {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},   // normal -y
                                      {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}};  // normal -z
    Mesh mesh;
    for (int f = 0; f < normals; ++f) {
        for (const glm::dvec3& corner : corners[f]) mesh.positions.push_back(glm::vec3(rotation * corner));
        const uint32_t base = uint32_t(3 * f);
        mesh.addFace({base, base + 1, base + 2});
    }
    return mesh;
}

double oracleShareOf(const Mesh& mesh) {
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition one = partitionFromIds(std::vector<double>(mesh.faceCount(), 0.0), mesh.faceCount(), "test");
    const ClusterBounds bounds = computeClusterBounds(mesh, worldPositions(mesh), faces, one, ConeMethod::Minimal);
    return computeCullMap(bounds).oracleFraction.at(0);
}

}  // namespace

TEST(CullMap, OracleShareIsTheExactArea) {
    // One normal: a hemisphere; two at right angles: a lune of a quarter; three: an octant. The share
    // is computed as 2 pi less the perimeter of the normals' hull on the sphere, so it is exact for
    // the normals it is given: those of corners stored in float, at right angles to within 1e-7.
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    for (int round = 0; round < 8; ++round) {
        const glm::dmat3 rotation(glm::rotate(glm::dmat4(1.0), angle(random), glm::normalize(glm::dvec3(angle(random) - 3.0, 1.0, angle(random) - 3.0))));
        EXPECT_NEAR(oracleShareOf(rotatedCorner(rotation, 1)), 0.5, 1e-7) << round;
        EXPECT_NEAR(oracleShareOf(rotatedCorner(rotation, 2)), 0.25, 1e-7) << round;
        EXPECT_NEAR(oracleShareOf(rotatedCorner(rotation, 3)), 0.125, 1e-7) << round;
    }
}

TEST(CullMap, OctagonShareMatchesExactAreas) {
    // One normal: the octagon is a point, its pyramid the hemisphere behind it; two at right angles:
    // a segment, the lune of a quarter; three (an octant's): more than the round cone's cap, less
    // than the octant the oracle culls from.
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    for (int round = 0; round < 8; ++round) {
        const glm::dmat3 rotation(glm::rotate(glm::dmat4(1.0), angle(random), glm::normalize(glm::dvec3(angle(random) - 3.0, 1.0, angle(random) - 3.0))));
        const double expected[3] = {0.5, 0.25, 0.0};
        for (int normals = 1; normals <= 3; ++normals) {
            const Mesh mesh = rotatedCorner(rotation, normals);
            const FaceGeometry faces = computeFaceGeometry(mesh);
            const Partition one = partitionFromIds(std::vector<double>(mesh.faceCount(), 0.0), mesh.faceCount(), "test");
            const ClusterBounds bounds = computeClusterBounds(mesh, worldPositions(mesh), faces, one, ConeMethod::Minimal);
            const CullMap map = computeCullMap(bounds);
            EXPECT_DOUBLE_EQ(cullFraction(map, 0, CullTest::Octagon), octagonCullShare(bounds.octagons[0]));
            if (normals < 3) {
                EXPECT_NEAR(map.octagonFraction[0], expected[normals - 1], 1e-6) << round << " " << normals;
            } else {
                EXPECT_GT(map.octagonFraction[0], map.coneFraction[0] + 0.005) << round;
                EXPECT_LT(map.octagonFraction[0], 0.125) << round;
            }
        }
    }
}

TEST(CullMap, ConeShareIsTheCapArea) {
    EXPECT_DOUBLE_EQ(coneCullShare(0.0), 0.5);  // a flat cluster: the hemisphere behind it
    EXPECT_DOUBLE_EQ(coneCullShare(1.0), 0.0);  // a hemisphere of normals: nowhere
    EXPECT_DOUBLE_EQ(coneCullShare(0.5), 0.25);
}

TEST(LossBreakdown, PerFaceArraysAgreeWithTheViewsCounts) {
    const std::shared_ptr<const Mesh> mesh = std::make_shared<Mesh>(testmesh::torus(1.0, 0.4, 48, 24));
    Settings settings;
    settings.limits = {24, 32};
    const PreparedMesh prepared = prepareMesh(mesh, "torus.off", false);
    const ClusterSet clusters = buildClusters(prepared, settings);
    for (const glm::dvec3& position : {glm::dvec3(0.3, 2.5, 1.0), glm::dvec3(0.0, 0.1, 0.0), glm::dvec3(-4.0, 0.5, -1.0)}) {
        const EyeMeasurement measurement = measureEye(prepared, clusters, eyeAt(settings, position, prepared.box), CullTest::Apex);
        const auto arrays = eyeFaceArrays(prepared, clusters, measurement);
        size_t triangles[4] = {0, 0, 0, 0}, back = 0;
        for (size_t f = 0; f < mesh->faceCount(); ++f) {
            triangles[size_t(arrays.at("loss")[f])] += mesh->faceSize(f) - 2;
            back += arrays.at("back_facing")[f] > 0.0 ? mesh->faceSize(f) - 2 : 0;
            EXPECT_EQ(arrays.at("culled")[f], measurement.culled[clusters.partition.clusterOfFace[f]]);
        }
        const ViewStatistics& view = measurement.view();
        EXPECT_EQ(back, view.backFacingTriangles);
        EXPECT_EQ(triangles[size_t(FaceLoss::Culled)], view.trianglesCulled);
        EXPECT_EQ(triangles[size_t(FaceLoss::Test)], view.testLossTriangles);
        EXPECT_EQ(triangles[size_t(FaceLoss::Partition)], view.partitionLossTriangles);
    }
    const auto partitionArrays = partitionFaceArrays(prepared, clusters, CullTest::Octagon);
    for (size_t f = 0; f < mesh->faceCount(); f += 7)
        EXPECT_GE(partitionArrays.at("oracle_fraction")[f], partitionArrays.at("cull_fraction")[f]);
}
