#include <gtest/gtest.h>

#include <random>

#include "TestMeshes.h"
#include "core/Culling.h"
#include "core/MultiCones.h"

using namespace conescope;

namespace {

// A mesh cut into clusters of `size` consecutive faces, with its bounds (minimal cones and spheres).
struct Clustered {
    Mesh mesh;
    std::vector<glm::vec3> world;
    FaceGeometry faces;
    ClusterBounds bounds;
    Clustered(Mesh m, uint32_t size) : mesh(std::move(m)) {
        world = worldPositions(mesh);
        faces = computeFaceGeometry(mesh);
        Partition partition;
        for (uint32_t f = 0; f < mesh.faceCount(); ++f) partition.clusterOfFace.push_back(f / size);
        partition.clusterCount = uint32_t((mesh.faceCount() + size - 1) / size);
        bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
    }
};

std::vector<Eye> someEyes(std::mt19937_64& random) {
    std::vector<Eye> eyes;
    for (int i = 0; i < 24; ++i) eyes.push_back(Eye::perspective(testmesh::randomUnit(random) * (1.2 + 3.0 * (i % 4))));
    for (int i = 0; i < 8; ++i) eyes.push_back(Eye::orthographicAlong(testmesh::randomUnit(random)));
    return eyes;
}

}  // namespace

// One sub-group is the cluster: its minimal cone and the apex behind it from the sphere's centre.
TEST(MultiCones, OneConeEqualsTheApexTest) {
    std::mt19937_64 random(7);
    const Clustered c(testmesh::torus(1.0, 0.4, 24, 12), 32);
    const MultiCones one = computeMultiCones(c.mesh, c.faces, c.bounds, 1);
    const CullingInput input{c.mesh, c.world, c.faces, c.bounds};
    for (const Eye& eye : someEyes(random))
        EXPECT_EQ(cullSubGroups(c.bounds, one, eye), cullClustersExact(input, eye, CullTest::Apex));
}

TEST(MultiCones, SubGroupsHoldEveryFaceOnce) {
    const Clustered c(testmesh::icosphere(3), 40);
    for (uint32_t k : {2u, 4u, 8u}) {
        const MultiCones multi = computeMultiCones(c.mesh, c.faces, c.bounds, k);
        ASSERT_EQ(multi.groupCount(), c.bounds.count() * k);
        ASSERT_EQ(multi.groupStarts.size(), multi.groupCount() + 1);
        for (size_t cl = 0; cl < c.bounds.count(); ++cl) {
            std::vector<uint32_t> a(multi.faces.begin() + multi.groupStarts[cl * k], multi.faces.begin() + multi.groupStarts[(cl + 1) * k]);
            std::vector<uint32_t> b(c.bounds.faces.faces.begin() + c.bounds.faces.starts[cl],
                                    c.bounds.faces.faces.begin() + c.bounds.faces.starts[cl + 1]);
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            EXPECT_EQ(a, b) << "cluster " << cl << " K=" << k;
        }
    }
}

// The property: a culled sub-group's faces are all strictly back-facing, on meshes with wide and
// narrow normal spreads, degenerate-free and not.
TEST(MultiCones, NoFalseCullAndMoreCulledThanOneCone) {
    std::mt19937_64 random(11);
    const std::vector<Mesh> meshes = {testmesh::icosphere(3), testmesh::torus(1.0, 0.3, 32, 16),
                                      testmesh::randomSoup(random, 600, 120.0), testmesh::randomPatch(random, 16, 60.0)};
    for (const Mesh& m : meshes) {
        const Clustered c(m, 64);
        const std::vector<Eye> eyes = someEyes(random);
        size_t culledOne = 0, culledFour = 0;
        for (uint32_t k : {1u, 2u, 4u, 8u}) {
            const MultiCones multi = computeMultiCones(c.mesh, c.faces, c.bounds, k);
            for (const Eye& eye : eyes) {
                const std::vector<Facing> facing = classifyFaces(c.mesh, c.world, c.faces, eye);
                const std::vector<uint8_t> culled = cullSubGroups(c.bounds, multi, eye);
                for (size_t g = 0; g < culled.size(); ++g) {
                    if (!culled[g]) continue;
                    for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i)
                        ASSERT_EQ(facing[multi.faces[i]], Facing::Back) << "K=" << k << " group " << g;
                }
                if (k == 1) culledOne += culledTriangles(multi, culled);
                if (k == 4) culledFour += culledTriangles(multi, culled);
            }
        }
        EXPECT_GT(culledFour, culledOne);
    }
}

TEST(MultiCones, SplitSeparatesTwoOpposedFans) {
    // Two faces up, two faces down: one cone cannot cull, two cones of zero width can.
    const std::vector<glm::dvec3> normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}, {0, 0, -1}};
    const std::vector<uint32_t> tris = {1, 1, 1, 1};
    const std::vector<uint8_t> group = splitForCones(normals.data(), tris.data(), normals.size(), 2);
    EXPECT_EQ(group[0], group[2]);
    EXPECT_EQ(group[1], group[3]);
    EXPECT_NE(group[0], group[1]);
}

// Each sub-group's apex, float and compact, lies behind every plane of its faces (up to the apex's
// own rounding slack), and the float apex test culls wherever the sphere test on the cluster's
// sphere culls (that test is the apex test from r / cos(alpha) behind the centre).
TEST(MultiCones, ApexesBehindEveryFacePlaneAndCullAtLeastTheSphereTest) {
    std::mt19937_64 random(5);
    for (const Mesh& m : {testmesh::torus(1.0, 0.3, 32, 16), testmesh::randomPatch(random, 16, 60.0)}) {
        const Clustered c(m, 48);
        const Aabb box = computeAabb(c.world);
        for (uint32_t k : {2u, 4u}) {
            const MultiCones multi = computeMultiCones(c.mesh, c.faces, c.bounds, k, c.world);
            const CompactMultiCones compact = compactMultiCones(c.faces, c.bounds, multi, box);
            for (size_t g = 0; g < multi.groupCount(); ++g)
                for (const auto& [cone, apex] : {std::make_pair(multi.cones[g], multi.apexes[g]), std::make_pair(compact.cones[g], compact.apexes[g])}) {
                    if (!cone.cullable) continue;
                    for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i) {
                        const uint32_t f = multi.faces[i];
                        for (size_t v = 0; v < c.mesh.faceSize(f); ++v) {
                            const glm::dvec3 q(c.world[c.mesh.faceBegin(f)[v]]);
                            EXPECT_LE(glm::dot(c.faces.normals[f], apex - q), 1e-12) << "group " << g << " K=" << k;
                        }
                    }
                }
            size_t apexOnly = 0;
            for (const Eye& eye : someEyes(random)) {
                const std::vector<uint8_t> culled = cullSubGroups(c.bounds, multi, eye);
                for (size_t g = 0; g < culled.size(); ++g) {
                    const bool sphere = !eye.orthographic && sphereSeesBack(multi.cones[g], c.bounds.spheres[g / k], eye.position);
                    EXPECT_TRUE(culled[g] || !sphere) << "sphere test culls sub-group " << g << " and the apex test does not";
                    apexOnly += culled[g] && !sphere && !eye.orthographic;
                }
            }
            EXPECT_GT(apexOnly, 0u);  // and culls more
        }
    }
}

// A small cluster is split by trying every split: its value is the largest over every assignment of
// its faces to K groups, enumerated here independently (K^n of them).
TEST(MultiCones, SmallClustersGetTheBestSplitOfAll) {
    std::mt19937_64 random(11);
    auto valueOf = [](const std::vector<glm::dvec3>& normals, const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& group,
                      uint32_t k) {
        double value = 0.0;
        for (uint32_t g = 0; g < k; ++g) {
            std::vector<glm::dvec3> members;
            size_t t = 0;
            for (size_t i = 0; i < normals.size(); ++i)
                if (group[i] == g) members.push_back(normals[i]), t += triangles[i];
            if (!members.empty()) value += expectedCulledTriangles(minimalCone(members.data(), members.size()), t);
        }
        return value;
    };
    for (uint32_t k : {2u, 4u}) {
        for (int trial = 0; trial < 6; ++trial) {
            const size_t n = k == 2 ? 9 : 6;
            std::vector<glm::dvec3> normals;
            std::vector<uint32_t> triangles;
            // Normals around a few directions, so that some splits gain and many do not.
            const glm::dvec3 a = testmesh::randomUnit(random), b = testmesh::randomUnit(random);
            for (size_t i = 0; i < n; ++i) {
                normals.push_back(glm::normalize((i % 2 ? a : b) + 0.35 * testmesh::randomUnit(random)));
                triangles.push_back(1 + uint32_t(i % 3));
            }
            double best = 0.0;
            std::vector<uint8_t> group(n, 0);
            size_t assignments = 1;
            for (size_t i = 0; i < n; ++i) assignments *= k;
            for (size_t code = 0; code < assignments; ++code) {
                size_t c = code;
                for (size_t i = 0; i < n; ++i) group[i] = uint8_t(c % k), c /= k;
                best = std::max(best, valueOf(normals, triangles, group, k));
            }
            const std::vector<uint8_t> split = splitForCones(normals.data(), triangles.data(), n, k);
            EXPECT_NEAR(valueOf(normals, triangles, split, k), best, 1e-9 * std::max(best, 1.0)) << "K=" << k << " trial " << trial;
        }
    }
}
