// The granularity rows: the one-cone rows are the run's statistics, the K-cone rows cull more of the
// same partition's back faces without a false cull, the compact records fit their bytes, and the
// per-triangle row is the ceiling.
#include <gtest/gtest.h>

#include <map>

#include "TestMeshes.h"
#include "core/Granularity.h"
#include "core/MultiCones.h"

using namespace conescope;

namespace {

Settings smallRun() {
    Settings settings;
    settings.views = 24;
    settings.tests = {CullTest::Octagon, CullTest::Sphere, CullTest::MeshoptApexF32};
    settings.cones = {ConeMethod::Minimal, ConeMethod::Meshopt};
    return settings;
}

std::map<std::string, GranularityRow> byRecord(const std::vector<GranularityRow>& rows) {
    std::map<std::string, GranularityRow> map;
    for (const GranularityRow& row : rows) EXPECT_TRUE(map.emplace(row.record, row).second) << "two rows " << row.record;
    return map;
}

}  // namespace

TEST(Granularity, OneConeRowsAreTheRunsStatistics) {
    const Mesh mesh = testmesh::torus(1.0, 0.35, 48, 24);
    const GranularityReport report = runGranularity(mesh, smallRun(), "torus");
    const std::map<std::string, GranularityRow> rows = byRecord(report.rows);
    // Two cones x two conservative tests, the engine record once: 5 one-cone rows, 6 K-cone rows, triangle.
    EXPECT_EQ(report.rows.size(), 5u + 6u + 1u);
    for (const CullTestStatistics& result : report.run.results) {
        const std::string name = result.engineRecord ? toString(result.test) : toString(result.cone) + "/" + toString(result.test);
        ASSERT_TRUE(rows.count(name)) << name;
        const GranularityRow& row = rows.at(name);
        EXPECT_EQ(row.efficiency, result.efficiency) << name;
        EXPECT_EQ(row.trianglesCulled, result.trianglesCulled) << name;
        EXPECT_EQ(row.bytesPerCluster, result.bytesPerCluster) << name;
        EXPECT_DOUBLE_EQ(row.culledShare, double(result.trianglesCulled) / double(report.run.triangles * report.run.viewCount));
        EXPECT_DOUBLE_EQ(row.bitsPerTriangle, double(row.bytesPerCluster * 8 * report.run.clusters) / double(report.run.triangles));
    }
    // Every row counts the same back faces: the same partition and views.
    for (const GranularityRow& row : report.rows) EXPECT_EQ(row.backFacingTriangles, report.run.results.front().backFacingTriangles) << row.record;
}

TEST(Granularity, MoreConesCullMoreAndTheTriangleRowIsTheCeiling) {
    const Mesh mesh = testmesh::torus(1.0, 0.35, 64, 32);
    Settings settings;
    settings.views = 32;
    settings.tests = {CullTest::Octagon, CullTest::Sphere};  // the K-cone records use the sphere test
    const GranularityReport report = runGranularity(mesh, settings, "torus");
    const std::map<std::string, GranularityRow> rows = byRecord(report.rows);
    const GranularityRow& one = rows.at("chosen/octagon");
    double previous = rows.at("chosen/octagon").trianglesCulled;
    EXPECT_GT(rows.at("cones-2").trianglesCulled, rows.at("chosen/sphere").trianglesCulled);
    for (const char* name : {"cones-4", "cones-8"}) {
        EXPECT_GT(double(rows.at(name).trianglesCulled), previous) << name;
        previous = double(rows.at(name).trianglesCulled);
    }
    for (const char* name : {"cones-2", "cones-4", "cones-8", "cones-2-compact", "cones-4-compact", "cones-8-compact"}) {
        EXPECT_EQ(rows.at(name).falseCulls, 0u) << name;
        EXPECT_GE(rows.at(name).testsPerView, double(report.run.clusters)) << name;
    }
    // The compact records lose little to their rounding and fit their bytes: 4 cones in 32.
    for (const char* k : {"2", "4", "8"})
        EXPECT_GT(double(rows.at(std::string("cones-") + k + "-compact").trianglesCulled), 0.85 * double(rows.at(std::string("cones-") + k).trianglesCulled)) << k;
    EXPECT_LE(rows.at("cones-4-compact").bytesPerCluster, 32u);
    EXPECT_LT(rows.at("cones-4-compact").bytesPerCluster, rows.at("cones-4").bytesPerCluster);
    const GranularityRow& triangle = rows.at("triangle");
    EXPECT_EQ(triangle.efficiency, 1.0);
    EXPECT_EQ(triangle.trianglesCulled, one.backFacingTriangles);
    EXPECT_EQ(triangle.bytesPerCluster, one.bytesPerCluster);
    // One test per cluster, and one per triangle of the clusters the cluster test drew.
    const double drawnTriangles = double(report.run.triangles) - double(one.trianglesCulled) / double(report.run.viewCount);
    EXPECT_NEAR(triangle.testsPerView, double(report.run.clusters) + drawnTriangles, 1e-6);
}

TEST(Granularity, RecordBytes) {
    EXPECT_EQ(multiConeRecordBytes(4, 124, true), 32u);    // 8 sphere + 4 x 5 cones and apexes + 3 offsets, padded
    EXPECT_EQ(multiConeRecordBytes(2, 124, true), 20u);
    EXPECT_EQ(multiConeRecordBytes(8, 124, true), 56u);
    EXPECT_EQ(multiConeRecordBytes(4, 124, false), 100u);  // 16 sphere + 4 x 20 cones and apexes + 3 offsets, padded
    EXPECT_EQ(multiConeRecordBytes(4, 255, true), 32u);    // 3 x 8 offset bits
    EXPECT_EQ(multiConeRecordBytes(4, 256, true), 32u);    // 3 x 9 bits in 4 bytes: 28 + 4
    EXPECT_EQ(multiConeRecordBytes(4, 1023, true), 32u);   // 3 x 10 bits
    EXPECT_EQ(multiConeRecordBytes(4, 1024, true), 36u);   // 3 x 11 bits take 5 bytes
    EXPECT_EQ(multiConeRecordBytes(8, 512, true), 60u);    // 8 + 40 + 7 x 10 bits (9 bytes), padded
    EXPECT_EQ(multiConeRecordBytes(2, 65535, true), 20u);  // one 16-bit offset: 8 + 10 + 2
}

// The compact sphere holds the float one, and the compact cone every normal of its sub-group.
TEST(Granularity, CompactRecordsHoldTheirFloatOriginals) {
    const Mesh mesh = testmesh::icosphere(3);
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    Partition partition;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) partition.clusterOfFace.push_back(f / 40);
    partition.clusterCount = uint32_t((mesh.faceCount() + 39) / 40);
    const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
    const MultiCones multi = computeMultiCones(mesh, faces, bounds, 4);
    const CompactMultiCones compact = compactMultiCones(faces, bounds, multi, computeAabb(world));
    for (size_t c = 0; c < bounds.count(); ++c)
        EXPECT_LE(glm::length(bounds.spheres[c].center - compact.spheres[c].center) + bounds.spheres[c].radius, compact.spheres[c].radius);
    size_t cullable = 0;
    for (size_t g = 0; g < multi.groupCount(); ++g) {
        const ConeOfNormals& cone = compact.cones[g];
        if (!cone.cullable) continue;
        ++cullable;
        EXPECT_GE(cone.sinHalfAngle, multi.cones[g].sinHalfAngle - 1e-12);
        for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i)
            EXPECT_GE(glm::dot(faces.normals[multi.faces[i]], cone.axis), cone.cosHalfAngle);
    }
    EXPECT_GT(cullable, multi.groupCount() / 2);
}
