#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "core/Culling.h"
#include "core/RecordTests.h"
#include "core/Settings.h"

#include <glm/gtc/matrix_transform.hpp>
#include <random>

using namespace conescope;

namespace {
// One flat square facing +z, as a single cluster.
struct FlatSquare {
    Mesh mesh;
    std::vector<glm::vec3> world;
    FaceGeometry faces;
    Partition partition;
    FlatSquare() {
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        mesh.addFace({0, 1, 2});
        mesh.addFace({0, 2, 3});
        world = worldPositions(mesh);
        faces = computeFaceGeometry(mesh);
        partition.clusterOfFace = {0, 0};
        partition.clusterCount = 1;
    }
};
}  // namespace

TEST(Culling, OracleIsStrictAboutEdgeOn) {
    FlatSquare square;
    EXPECT_EQ(classifyFace(square.mesh, square.world, square.faces, 0, Eye::perspective({0.5, 0.5, -1})), Facing::Back);
    EXPECT_EQ(classifyFace(square.mesh, square.world, square.faces, 0, Eye::perspective({0.5, 0.5, 1})), Facing::Front);
    EXPECT_EQ(classifyFace(square.mesh, square.world, square.faces, 0, Eye::perspective({5, 5, 0})), Facing::Front);
    EXPECT_EQ(classifyFace(square.mesh, square.world, square.faces, 0, Eye::orthographicAlong({0, 0, 1})), Facing::Back);
    EXPECT_EQ(classifyFace(square.mesh, square.world, square.faces, 0, Eye::orthographicAlong({1, 0, 0})), Facing::Front);
}

TEST(Culling, FlatClusterIsCulledByEveryTestFromBehindAndByNoneFromTheSide) {
    FlatSquare square;
    for (ConeMethod method : allConeMethods()) {
        const ClusterBounds bounds = computeClusterBounds(square.mesh, square.world, square.faces, square.partition, method);
        const CullingInput input{square.mesh, square.world, square.faces, bounds};
        for (CullTest test : allCullTests()) {
            const std::string name = toString(method) + "/" + toString(test);
            EXPECT_TRUE(cullCluster(input, 0, Eye::perspective({0.5, 0.5, -10}), test)) << name;
            EXPECT_TRUE(cullCluster(input, 0, Eye::orthographicAlong({0.1, 0, 1}), test)) << name;
            EXPECT_FALSE(cullCluster(input, 0, Eye::perspective({0.5, 0.5, 10}), test)) << name;
            // Edge-on faces are visible; meshoptimizer's apex test culls them (its >= with a cutoff of 0
            // for a flat cluster), which is that engine record's false cull.
            const bool edgeOnCulled = test == CullTest::MeshoptApexF32;
            EXPECT_EQ(cullCluster(input, 0, Eye::perspective({10, 0.5, 0}), test), edgeOnCulled) << name;
            EXPECT_EQ(cullCluster(input, 0, Eye::orthographicAlong({1, 0, 0}), test), edgeOnCulled) << name;
        }
    }
}

TEST(Culling, SphereTestNeverCullsWithTheEyeInside) {
    FlatSquare square;
    const ClusterBounds bounds =
        computeClusterBounds(square.mesh, square.world, square.faces, square.partition, ConeMethod::Minimal);
    // Just behind the square but inside its bounding sphere (radius ~0.707 around the centre).
    EXPECT_FALSE(sphereSeesBack(bounds.cones[0], bounds.spheres[0], {0.5, 0.5, -0.1}));
    EXPECT_TRUE(sphereSeesBack(bounds.cones[0], bounds.spheres[0], {0.5, 0.5, -10}));
}

TEST(Culling, TighterTestsCullAtLeastWhatLooserOnesCull) {
    // The vertex hull is inside the box, so the vertex test culls whenever the box test does; the
    // seed's unnormalised box test is the same test as the normalised one.
    const Mesh mesh = testmesh::torus(1.0, 0.35, 48, 24);
    const auto world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition partition = buildMeshlets(mesh, faces, {});
    const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
    const CullingInput input{mesh, world, faces, bounds};
    size_t boxCulls = 0;
    for (const Eye& eye : orbitViews(computeAabb(world), 64, 2.0)) {
        const auto vertices = cullClusters(input, eye, CullTest::Vertices);
        const auto box = cullClusters(input, eye, CullTest::Aabb);
        const auto boxFast = cullClusters(input, eye, CullTest::AabbFast);
        const auto oracle = cullClusters(input, eye, CullTest::Oracle);
        for (size_t c = 0; c < bounds.count(); ++c) {
            EXPECT_GE(vertices[c], box[c]);
            EXPECT_EQ(box[c], boxFast[c]);
            EXPECT_GE(oracle[c], vertices[c]);
            boxCulls += box[c];
        }
    }
    EXPECT_GT(boxCulls, 0u);
}

TEST(Culling, ExplanationMatchesTheDecision) {
    const Mesh mesh = testmesh::icosphere(2);
    const auto world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition partition = buildMeshlets(mesh, faces, {});
    const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
    const CullingInput input{mesh, world, faces, bounds};
    const Eye eye = Eye::perspective({0, 0, 4});
    for (CullTest test : allCullTests())
        for (uint32_t c = 0; c < bounds.count(); ++c) {
            const CullExplanation why = explainCull(input, c, eye, test);
            EXPECT_EQ(why.exactCulled, cullCluster(input, c, eye, test));
            EXPECT_EQ(why.culled, cullClusters(input, eye, test)[c] != 0);
            EXPECT_NEAR(why.angleBDegrees + why.halfAngleDegrees, 90.0, 1e-9);
            EXPECT_EQ(why.frontFaces + why.backFaces + why.degenerateFaces,
                      bounds.faces.starts[c + 1] - bounds.faces.starts[c]);
            if (why.culled) EXPECT_EQ(why.frontFaces, 0u);
            if (test == CullTest::Aabb) EXPECT_EQ(why.culled, why.pointsBack == 8);
            if (test == CullTest::Vertices) EXPECT_EQ(why.culled, why.pointsTested > 0 && why.pointsBack == why.pointsTested);
            // What the picking panel shows for the default test: v·V1 against sin α decides.
            if (test == CullTest::Apex && why.cullable) EXPECT_EQ(why.culled, why.viewDotAxis > why.threshold) << c;
        }
}

// meshoptimizer squares coordinates in float; at 1e30 that overflowed to a NaN normal and aborted
// inside meshopt_computeClusterBounds (found by fuzz_mesh_ingestion). The meshopt cone must work at
// any scale a float holds, and cull the same way at every scale.
TEST(Culling, MeshoptConeWorksAtExtremeScales) {
    for (double scale : {1e-30, 1e-6, 1.0, 1e6, 1e30}) {
        Mesh mesh;
        const float s = float(scale);
        mesh.positions = {{0, 0, 0}, {s, 0, 0}, {s, s, 0.2f * s}, {0, s, 0}};
        mesh.addFace({0, 1, 2});
        mesh.addFace({0, 2, 3});
        const std::vector<glm::vec3> world = worldPositions(mesh);
        const FaceGeometry faces = computeFaceGeometry(mesh);
        const Partition partition{{0, 0}, 1};
        const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Meshopt);
        ASSERT_TRUE(bounds.cones[0].cullable) << scale;
        const CullingInput input{mesh, world, faces, bounds};
        for (CullTest test : {CullTest::Apex, CullTest::MeshoptSphere, CullTest::Sphere}) {
            EXPECT_TRUE(cullCluster(input, 0, Eye::perspective(glm::dvec3(0.5, 0.5, -10) * scale), test)) << scale << " " << toString(test);
            EXPECT_FALSE(cullCluster(input, 0, Eye::perspective(glm::dvec3(0.5, 0.5, 10) * scale), test)) << scale << " " << toString(test);
        }
    }
}

TEST(ClusterBounds, ManyClustersAreBoundedOnAllCoresTheSameAsOneByOne) {
    // 4,096 clusters: enough for the clusters to be bounded in pieces on several threads. Each
    // cluster's bounds, vertex list and triangle count must be what it gets as the only cluster.
    const Mesh mesh = testmesh::torus(1.0, 0.3, 256, 64);
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    Partition partition;
    partition.clusterCount = 4096;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) partition.clusterOfFace.push_back(f / 8);
    for (ConeMethod cone : {ConeMethod::Minimal, ConeMethod::Meshopt}) {
        const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, cone);
        ASSERT_EQ(bounds.count(), 4096u);
        ASSERT_EQ(bounds.vertexStarts.back(), bounds.vertexIds.size());
        for (uint32_t c = 0; c < bounds.count(); c += 127) {
            Mesh single;
            single.positions = mesh.positions;
            for (uint32_t i = bounds.faces.starts[c]; i < bounds.faces.starts[c + 1]; ++i) {
                const uint32_t f = bounds.faces.faces[i];
                single.addFace(mesh.faceBegin(f), mesh.faceSize(f));
            }
            const Partition alone{std::vector<uint32_t>(single.faceCount(), 0), 1};
            const ClusterBounds one = computeClusterBounds(single, world, computeFaceGeometry(single), alone, cone);
            EXPECT_EQ(std::vector<uint32_t>(bounds.vertexIds.begin() + bounds.vertexStarts[c], bounds.vertexIds.begin() + bounds.vertexStarts[c + 1]),
                      one.vertexIds) << "cluster " << c;
            EXPECT_EQ(bounds.triangles[c], one.triangles[0]);
            EXPECT_EQ(bounds.cones[c].axis, one.cones[0].axis);
            EXPECT_EQ(bounds.cones[c].sinHalfAngle, one.cones[0].sinHalfAngle);
            EXPECT_EQ(bounds.cones[c].cullable, one.cones[0].cullable);
            EXPECT_EQ(bounds.boxes[c].min, one.boxes[0].min);
            EXPECT_EQ(bounds.boxes[c].max, one.boxes[0].max);
            EXPECT_EQ(bounds.spheres[c].center, one.spheres[0].center);
            EXPECT_EQ(bounds.spheres[c].radius, one.spheres[0].radius);
            EXPECT_EQ(bounds.apexes[c], one.apexes[0]);
        }
    }
}

// A cluster a few nanometres across placed 2.9e19 from the origin (found by fuzz_mesh_ingestion):
// its world positions are floats, so every corner gets the same z, while its normals, made from
// the untranslated geometry, keep their tilt. Moving the apex behind the face planes then moved it
// by less than a coordinate's rounding, and the apex and octagon tests culled from an eye beside
// the cluster that sees a face's front. No test may cull there.
TEST(Culling, ATinyClusterFarFromTheOriginIsNeverCulledFromBesideIt) {
    Mesh mesh;
    const float s = 1e-9f;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const float x = s * float(i), y = s * float(j);
            mesh.positions.emplace_back(x, y, 0.05f * x + 0.02f * y * float(j) / 3.0f);  // a gentle fold
        }
    for (uint32_t i = 0; i < 3; ++i)
        for (uint32_t j = 0; j < 3; ++j) {
            const uint32_t a = i * 4 + j;
            mesh.addFace({a, a + 4, a + 5});
            mesh.addFace({a, a + 5, a + 1});
        }
    mesh.model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -2.9229375e19));
    const std::vector<glm::vec3> world = worldPositions(mesh);
    ASSERT_EQ(world.front().z, world.back().z);  // the fold is below the float's resolution there
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition partition{std::vector<uint32_t>(mesh.faceCount(), 0), 1};
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> around(-1.0 * s, 4.0 * s);
    size_t eyesSeeingAFront = 0;
    for (ConeMethod cone : allConeMethods()) {
        const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, cone);
        const CullingInput input{mesh, world, faces, bounds};
        // Far behind it, where every face shows its back, the apex tests still cull.
        const Eye behind = Eye::perspective(glm::dvec3(0.0, 0.0, double(world[0].z) - 1e12));
        for (Facing facing : classifyFaces(mesh, world, faces, behind)) ASSERT_EQ(facing, Facing::Back);
        if (bounds.cones[0].cullable) {
            EXPECT_TRUE(cullCluster(input, 0, behind, CullTest::Apex)) << toString(cone);
            EXPECT_TRUE(cullCluster(input, 0, behind, CullTest::Octagon)) << toString(cone);
        }
        for (int k = 0; k < 2000; ++k) {
            // Eyes beside the cluster, in the plane its corners share, and a little off it.
            const double off = k % 4 == 0 ? 0.0 : around(random) * (k % 2 ? 1.0 : -1.0);
            const Eye eye = Eye::perspective(glm::dvec3(around(random), around(random), double(world[0].z) + off));
            size_t front = 0;
            for (Facing facing : classifyFaces(mesh, world, faces, eye)) front += facing == Facing::Front;
            if (front == 0) continue;
            ++eyesSeeingAFront;
            for (CullTest test : allCullTests())
                EXPECT_FALSE(cullCluster(input, 0, eye, test)) << toString(cone) << " / " << toString(test) << ", eye " << k;
        }
    }
    EXPECT_GT(eyesSeeingAFront, 5000u);
}
