// The debugger's drawings of a test: the margin agrees with the decision, the drawn cull region is
// where the exact test culls, and the Gauss map's cones hold the normals they are drawn around.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "TestMeshes.h"
#include "core/CullTestGeometry.h"

using namespace conescope;
using testmesh::randomUnit;

namespace {

struct Prepared {
    PreparedMesh mesh;
    ClusterSet clusters;
};

Prepared preparedTorus(ConeMethod cone) {
    Settings settings;
    settings.builder = Builder::Meshlet;
    settings.limits.maxTriangles = 24;
    settings.limits.maxVertices = 24;
    settings.cones = {cone};
    PreparedMesh mesh = prepareMesh(std::make_shared<Mesh>(testmesh::torus(1.0, 0.35, 48, 24)), "torus", false);
    ClusterSet clusters = buildClusters(mesh, settings);
    return {std::move(mesh), std::move(clusters)};
}

// Some direction perpendicular to `axis`.
glm::dvec3 perpendicular(const glm::dvec3& axis) {
    const glm::dvec3 other = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, other));
}

}  // namespace

TEST(CullTestGeometry, MarginIsPositiveExactlyWhenTheExactTestCulls) {
    const Prepared p = preparedTorus(ConeMethod::Minimal);
    const CullingInput input = cullingInput(p.mesh, p.clusters);
    std::mt19937_64 random(7);
    size_t culled = 0, drawn = 0;
    for (int trial = 0; trial < 40; ++trial) {
        Eye eye;
        eye.orthographic = trial % 5 == 4;
        eye.direction = randomUnit(random);
        eye.position = randomUnit(random) * (1.2 + 3.0 * (trial % 4));
        for (CullTest test : {CullTest::Vertices, CullTest::Aabb, CullTest::Sphere, CullTest::Apex, CullTest::MeshoptSphere,
                              CullTest::Octagon}) {
            for (uint32_t c = 0; c < p.clusters.bounds.count(); c += 3) {
                const CullExplanation why = explainCull(input, c, eye, test);
                if (std::isnan(why.margin)) {
                    EXPECT_FALSE(why.exactCulled) << toString(test) << " cluster " << c;
                    continue;
                }
                if (std::abs(why.margin) < 1e-9) continue;  // within rounding of the threshold
                EXPECT_EQ(why.margin > 0.0, why.exactCulled) << toString(test) << " cluster " << c << " margin " << why.margin;
                (why.exactCulled ? culled : drawn)++;
            }
        }
    }
    EXPECT_GT(culled, 50u);
    EXPECT_GT(drawn, 50u);
}

TEST(CullTestGeometry, VerticesTestGivesEveryVertexItsVerdict) {
    const Prepared p = preparedTorus(ConeMethod::Minimal);
    const CullingInput input = cullingInput(p.mesh, p.clusters);
    Eye eye;
    eye.position = {0.3, -2.5, 1.0};
    const CullExplanation why = explainCull(input, 5, eye, CullTest::Vertices);
    const ClusterBounds& bounds = p.clusters.bounds;
    ASSERT_EQ(why.vertices.size(), size_t(bounds.vertexStarts[6] - bounds.vertexStarts[5]));
    ASSERT_EQ(why.vertexBack.size(), why.vertices.size());
    size_t back = 0;
    for (uint8_t b : why.vertexBack) back += b;
    EXPECT_EQ(back, why.pointsBack);
    EXPECT_EQ(why.exactCulled, back == why.vertices.size());
}

// Eyes just inside the drawn region are culled by the exact test, eyes just outside are not.
TEST(CullTestGeometry, CullRegionIsWhereTheExactTestCulls) {
    for (ConeMethod cone : {ConeMethod::Minimal, ConeMethod::Meshopt}) {
        const Prepared p = preparedTorus(cone);
        const CullingInput input = cullingInput(p.mesh, p.clusters);
        size_t checked = 0;
        for (CullTest test : {CullTest::Apex, CullTest::Sphere, CullTest::MeshoptSphere}) {
            for (bool orthographic : {false, true}) {
                for (uint32_t c = 0; c < p.clusters.bounds.count(); c += 2) {
                    const CullRegion region = cullRegion(p.clusters.bounds, c, test, orthographic, 20.0);
                    if (region.empty()) continue;
                    const glm::dvec3 side = perpendicular(region.direction);
                    for (size_t i = 1; i < region.distances.size(); i += 7) {
                        const double d = region.distances[i];
                        for (double factor : {0.97, 1.03}) {
                            const double angle = region.angles[i] * factor;
                            if (region.angles[i] < 1e-3) continue;
                            const glm::dvec3 direction = std::cos(angle) * region.direction + std::sin(angle) * side;
                            Eye eye;
                            eye.orthographic = orthographic;
                            eye.direction = -direction;  // looking from there towards the cluster
                            eye.position = region.origin + d * direction;
                            EXPECT_EQ(cullCluster(input, c, eye, test), factor < 1.0)
                                << toString(test) << (orthographic ? " ortho" : "") << " cluster " << c << " d " << d;
                            ++checked;
                        }
                    }
                }
            }
        }
        EXPECT_GT(checked, 200u);
    }
}

// The octagon test's pyramid: eyes just inside each of its faces are culled, eyes just outside not.
TEST(CullTestGeometry, OctagonPyramidIsWhereTheExactTestCulls) {
    const Prepared p = preparedTorus(ConeMethod::Minimal);
    const CullingInput input = cullingInput(p.mesh, p.clusters);
    size_t checked = 0;
    for (bool orthographic : {false, true})
        for (uint32_t c = 0; c < p.clusters.bounds.count(); c += 2) {
            const CullRegion region = cullRegion(p.clusters.bounds, c, CullTest::Octagon, orthographic, 20.0);
            if (region.empty()) continue;
            ASSERT_TRUE(region.pyramid());
            ASSERT_EQ(region.edges.size(), 8u);
            glm::dvec3 centre(0.0);
            for (const glm::dvec3& edge : region.edges) centre += edge;
            centre = glm::normalize(centre);
            for (size_t k = 0; k < 8; ++k) {
                const glm::dvec3 face = glm::normalize(region.edges[k] + region.edges[(k + 1) % 8]);
                if (glm::length(region.edges[k] - region.edges[(k + 1) % 8]) < 1e-3) continue;  // a repeated edge
                for (double toward : {0.03, -0.03}) {
                    const glm::dvec3 direction = glm::normalize(face + toward * (centre - face));
                    Eye eye;
                    eye.orthographic = orthographic;
                    eye.direction = -direction;
                    eye.position = region.origin + 5.0 * direction;
                    EXPECT_EQ(cullCluster(input, c, eye, CullTest::Octagon), toward > 0.0)
                        << (orthographic ? "ortho " : "") << "cluster " << c << " face " << k;
                    ++checked;
                }
            }
        }
    EXPECT_GT(checked, 200u);
}

TEST(CullTestGeometry, RegionIsEmptyWhereTheTestHasNoSolidOfRevolution) {
    const Prepared p = preparedTorus(ConeMethod::Minimal);
    for (CullTest test : {CullTest::Oracle, CullTest::Vertices, CullTest::Aabb, CullTest::AabbFast})
        EXPECT_TRUE(cullRegion(p.clusters.bounds, 0, test, false, 10.0).empty()) << toString(test);
    // The sphere tests start where the sphere no longer covers the cone's opening.
    const CullRegion sphere = cullRegion(p.clusters.bounds, 0, CullTest::Sphere, false, 10.0);
    ASSERT_FALSE(sphere.empty());
    EXPECT_NEAR(sphere.angles.front(), 0.0, 1e-9);
    EXPECT_GT(sphere.angles.back(), sphere.angles.front());
}

TEST(CullTestGeometry, GaussMapConesHoldEveryNormalAndTheMinimalIsNarrowest) {
    const Prepared p = preparedTorus(ConeMethod::Average);
    const CullingInput input = cullingInput(p.mesh, p.clusters);
    Eye eye;
    eye.position = {0.0, 0.0, 4.0};
    for (uint32_t c = 0; c < p.clusters.bounds.count(); c += 5) {
        const CullExplanation why = explainCull(input, c, eye, CullTest::Apex);
        const GaussMap map = gaussMapOf(p.mesh, p.clusters, c, why);
        ASSERT_EQ(map.normals.size(), size_t(p.clusters.bounds.faces.starts[c + 1] - p.clusters.bounds.faces.starts[c]));
        ASSERT_EQ(map.cones.size(), allConeMethods().size());
        double minimal = 0.0;
        for (const auto& [method, cone] : map.cones) {
            if (method == ConeMethod::Minimal) minimal = cone.halfAngle();
            if (method == ConeMethod::Average) {
                EXPECT_EQ(cone.axis, p.clusters.bounds.cones[c].axis);  // the displayed method's own cone
                EXPECT_EQ(cone.sinHalfAngle, p.clusters.bounds.cones[c].sinHalfAngle);
            }
            if (!cone.cullable) continue;
            for (const glm::dvec3& n : map.normals) EXPECT_GE(glm::dot(n, cone.axis), cone.cosHalfAngle - 1e-12) << toString(method);
        }
        for (const auto& [method, cone] : map.cones)
            if (cone.cullable) EXPECT_LE(minimal, cone.halfAngle() + 1e-9) << toString(method) << " cluster " << c;
        EXPECT_NEAR(glm::length(map.view), 1.0, 1e-12);
    }
}
