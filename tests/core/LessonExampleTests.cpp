// Lessons that show a cull and a miss: the partner a cluster is set beside (the nearest the same eye
// decides the other way), the examples of each outcome and the views they are shown from, the eye
// swept across the cull boundary, and the bound step's words for an apex at the centre.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "TestMeshes.h"
#include "core/EyeSweep.h"
#include "core/Lesson.h"
#include "core/LessonExamples.h"
#include "core/LessonSteps.h"
#include "core/LessonText.h"

using namespace conescope;
using testmesh::randomUnit;

namespace {

// A torus in meshlets of 24 triangles (the same as LessonTests'), its orbit measured with `test`.
struct Torus {
    explicit Torus(CullTest test = CullTest::Apex)
        : mesh(prepareMesh(std::make_shared<Mesh>(testmesh::torus(1.0, 0.35, 48, 24)), "torus", false)) {
        settings.builder = Builder::Meshlet;
        settings.limits.maxTriangles = settings.limits.maxVertices = 24;
        settings.tests = {test};
        settings.views = 64;
        clusters = buildClusters(mesh, settings);
        orbit = measureOrbit(mesh, clusters, settings);
    }
    PreparedMesh mesh;
    Settings settings;
    ClusterSet clusters;
    CullTestStatistics orbit;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// The partner is decided the other way by the same test from the same eye, and no cluster so decided
// is nearer (among those with a cone, which come first); step 7 names both and their comparisons.
TEST(LessonPartner, TheNearestClusterTheSameEyeDecidesTheOtherWay) {
    const Torus t(CullTest::Apex);
    const CullingInput input = cullingInput(t.mesh, t.clusters);
    const ClusterBounds& bounds = t.clusters.bounds;
    std::mt19937_64 random(17);
    size_t withPartner = 0;
    for (int trial = 0; trial < 10; ++trial) {
        Eye eye = Eye::perspective(randomUnit(random) * (1.5 + trial % 4));
        if (trial % 5 == 4) eye = Eye::orthographicAlong(randomUnit(random));
        for (CullTest test : {CullTest::Apex, CullTest::Sphere, CullTest::Aabb, CullTest::Octagon}) {
            const std::vector<uint8_t> culled = cullClusters(input, eye, test);
            for (uint32_t c = 0; c < bounds.count(); c += 6) {
                const Lesson lesson = makeLesson(t.mesh, t.clusters, c, eye, test);
                ASSERT_EQ(lesson.steps.size(), size_t(kLessonStepCount));
                const std::string& words = lesson.steps[kSideBySideStep - 1].text;
                if (!lesson.partner) {
                    for (uint32_t other = 0; other < bounds.count(); ++other) EXPECT_EQ(culled[other] != 0, lesson.why.culled);
                    EXPECT_TRUE(contains(words, "every cluster alike")) << words;
                    continue;
                }
                ++withPartner;
                const LessonPartner& partner = *lesson.partner;
                EXPECT_NE(partner.why.culled, lesson.why.culled);
                EXPECT_EQ(partner.why.culled, culled[partner.cluster] != 0);
                const double distance = glm::distance(partner.sphere.center, lesson.sphere.center);
                for (uint32_t other = 0; other < bounds.count(); ++other)
                    if (other != c && (culled[other] != 0) != lesson.why.culled && bounds.cones[other].cullable == bounds.cones[partner.cluster].cullable)
                        EXPECT_GE(glm::distance(bounds.spheres[other].center, lesson.sphere.center), distance);
                EXPECT_EQ(partner.outcome, outcomeOf(partner.why.culled, partner.why.frontFaces, partner.why.backFaces));
                const uint32_t culledOne = lesson.why.culled ? c : partner.cluster;
                const uint32_t drawnOne = lesson.why.culled ? partner.cluster : c;
                EXPECT_TRUE(contains(words, "Cluster " + std::to_string(culledOne) + " is culled")) << words;
                EXPECT_TRUE(contains(words, "Cluster " + std::to_string(drawnOne) + " is drawn")) << words;
                // The comparisons are the ones each decision made.
                EXPECT_TRUE(contains(words, decisionLine(lesson.why, test, eye.orthographic))) << words;
                EXPECT_TRUE(contains(words, decisionLine(partner.why, test, eye.orthographic))) << words;
            }
        }
    }
    EXPECT_GT(withPartner, 50u);
}

// The apex at the cluster's centre (a patch hollow towards V1) is said in words, never "a point 0 from
// the centre"; elsewhere the step gives the apex's true distance.
TEST(LessonWords, AnApexAtTheCentreIsTheCentreItself) {
    const Torus t(CullTest::Apex);
    const Eye eye = Eye::perspective({0.5, 2.5, 1.0});
    size_t atCentre = 0, behind = 0;
    for (uint32_t c = 0; c < t.clusters.bounds.count(); ++c) {
        const Lesson lesson = makeLesson(t.mesh, t.clusters, c, eye, CullTest::Apex);
        if (!lesson.why.cullable) continue;
        const std::string& words = lesson.steps[3].text;
        EXPECT_FALSE(contains(words, "a point 0 ")) << words;
        const double distance = glm::distance(lesson.why.apex, lesson.sphere.center);
        // The apex is the centre moved back by next to nothing (1e-300) when the centre is behind every face.
        if (distance <= 1e-9 * lesson.sphere.radius) {
            EXPECT_TRUE(contains(words, "the apex is that centre itself")) << words;
            ++atCentre;
        } else {
            EXPECT_TRUE(contains(words, "a point " + lessontext::number(distance) + " from the cluster's centre")) << words;
            ++behind;
        }
    }
    // The torus has both: its outer clusters bulge, its inner ones are hollow.
    EXPECT_GT(atCentre, 0u);
    EXPECT_GT(behind, 0u);
}

TEST(LessonExamples, NamesParseAndRankings) {
    for (LessonOutcome outcome : exampleOutcomes()) EXPECT_EQ(parseExample(exampleName(outcome)), outcome);
    EXPECT_THROW(parseExample("visible"), std::invalid_argument);
    try {
        parseExample("cull");
    } catch (const std::invalid_argument& error) {
        EXPECT_TRUE(contains(error.what(), "culled, drawn, test-loss, partition-loss")) << error.what();
    }
    EXPECT_EQ(parseClusterSortKey("most-culled"), ClusterSortKey::MostCulled);
    const Torus t;
    const std::vector<uint32_t> ranked = rankClusters(t.orbit, ClusterSortKey::MostCulled);
    for (size_t i = 1; i < ranked.size(); ++i)
        EXPECT_GE(t.orbit.clusters[ranked[i - 1]].timesCulled, t.orbit.clusters[ranked[i]].timesCulled);
}

// Each example has its outcome from its view, as the lesson from that eye says, and comes from the
// outcome's ranking; a cull is shown from the view looking most nearly along its cone's axis.
TEST(LessonExamples, EachExampleHasItsOutcomeFromItsView) {
    for (CullTest test : {CullTest::Apex, CullTest::Sphere, CullTest::Aabb, CullTest::Octagon}) {
        const Torus t(test);
        const std::vector<Eye> views = orbitOf(t.settings, t.mesh.box);
        for (LessonOutcome outcome : exampleOutcomes()) {
            const ClusterExample example = findExample(t.mesh, t.clusters, t.settings, t.orbit, outcome);
            ASSERT_GE(example.cluster, 0) << exampleName(outcome) << " " << toString(test);
            ASSERT_GE(example.view, 0);
            const Lesson lesson = makeLesson(t.mesh, t.clusters, uint32_t(example.cluster), views[size_t(example.view)], test);
            EXPECT_EQ(lesson.outcome, outcome) << exampleName(outcome) << " " << toString(test);
            const std::vector<uint32_t> ranked = rankClusters(t.orbit, exampleRanking(outcome));
            EXPECT_NE(std::find(ranked.begin(), ranked.begin() + 64, uint32_t(example.cluster)), ranked.begin() + 64);
            if (outcome != LessonOutcome::Culled) continue;
            // No view with the same outcome looks more nearly along the axis.
            const std::vector<ClusterInView> seen = clusterOverOrbit(t.mesh, t.clusters, t.settings, uint32_t(example.cluster));
            const glm::dvec3 axis = t.clusters.bounds.cones[size_t(example.cluster)].axis;
            const glm::dvec3 centre = t.clusters.bounds.spheres[size_t(example.cluster)].center;
            const double chosen = glm::dot(glm::normalize(centre - views[size_t(example.view)].position), axis);
            for (size_t v = 0; v < seen.size(); ++v)
                if (seen[v].culled) EXPECT_LE(glm::dot(glm::normalize(centre - views[v].position), axis), chosen + 1e-12);
        }
    }
}

// The eye swept across the boundary: every frame at the arc's distance, each frame's decision the
// test's own (as the lesson from that eye says), the decision flipping between the first and the last
// frame; for the apex test exactly once, at the angle B from V1 (seen from the apex).
TEST(EyeSweep, CrossesTheBoundaryWithTheTestsOwnDecisions) {
    const Torus apex(CullTest::Apex);
    const Eye start = Eye::perspective({0.5, 2.5, 1.0});
    size_t swept = 0;
    for (CullTest test : {CullTest::Apex, CullTest::Sphere, CullTest::Aabb, CullTest::Octagon, CullTest::MeshoptApexF32}) {
        Settings settings = apex.settings;
        settings.tests = {test};
        for (uint32_t c = 0; c < apex.clusters.bounds.count(); c += 5) {
            if (!apex.clusters.bounds.cones[c].cullable) continue;
            const EyeSweep sweep = sweepAcrossCull(apex.mesh, apex.clusters, settings, c, start.position, 9);
            ASSERT_EQ(sweep.positions.size(), 9u);
            EXPECT_NE(sweep.culled.front(), sweep.culled.back()) << toString(test) << " cluster " << c;
            for (size_t k = 0; k < sweep.positions.size(); ++k) {
                EXPECT_NEAR(glm::distance(sweep.positions[k], sweep.centre), sweep.distance, 1e-9 * sweep.distance);
                const Lesson lesson = makeLesson(apex.mesh, apex.clusters, c, Eye::perspective(sweep.positions[k]), test);
                EXPECT_EQ(lesson.why.culled, sweep.culled[k] != 0);
            }
            if (test == CullTest::Apex) {
                size_t flips = 0;
                for (size_t k = 1; k < sweep.culled.size(); ++k) flips += sweep.culled[k] != sweep.culled[k - 1];
                EXPECT_EQ(flips, 1u);
                // Just either side of the boundary, v makes the angle B with V1 (v runs to the apex, the arc turns around the centre).
                const EyeSweep fine = sweepAcrossCull(apex.mesh, apex.clusters, settings, c, start.position, 2, 1e-4);
                for (const glm::dvec3& eye : fine.positions) {
                    const Lesson lesson = makeLesson(apex.mesh, apex.clusters, c, Eye::perspective(eye), test);
                    EXPECT_NEAR(lesson.why.viewDotAxis, lesson.why.threshold, 1e-5);
                }
            }
            ++swept;
        }
    }
    EXPECT_GT(swept, 20u);
    // An orthographic eye turns around the mesh centre: each frame's direction is the arc's.
    Settings orthographic = apex.settings;
    orthographic.orthographic = true;
    const EyeSweep far = sweepAcrossCull(apex.mesh, apex.clusters, orthographic, 0, start.position, 6);
    EXPECT_NE(far.culled.front(), far.culled.back());
    EXPECT_EQ(far.centre, glm::dvec3(apex.mesh.box.center()));
}

TEST(EyeSweep, AClusterWithoutAConeHasNoBoundary) {
    PreparedMesh prepared = prepareMesh(std::make_shared<Mesh>(testmesh::quadCube()), "cube", false);
    Settings settings;
    settings.builder = Builder::KMeans;
    settings.clusterCount = 1;
    const ClusterSet clusters = buildClusters(prepared, settings);
    try {
        sweepAcrossCull(prepared, clusters, settings, 0, {3.0, 2.0, 4.0}, 8);
        FAIL() << "no throw";
    } catch (const std::invalid_argument& error) {
        EXPECT_TRUE(contains(error.what(), "has no cone: its normals span more than a half-space")) << error.what();
    }
    EXPECT_THROW(sweepAcrossCull(prepared, clusters, settings, 0, {3.0, 2.0, 4.0}, 1), std::invalid_argument);
}
