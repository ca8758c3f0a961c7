// The lesson's words: the numbers in the sentences are the ones the test compared, the verdict and
// the oracle's outcome are the decision's (the cross-section's figure: CrossSectionTests.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "TestMeshes.h"
#include "core/Lesson.h"
#include "core/LessonText.h"
#include "core/RecordTests.h"

using namespace conescope;
using testmesh::randomUnit;

namespace {

// A small torus in clusters of 24 triangles, every cone its own method's.
struct Prepared {
    explicit Prepared(ConeMethod cone) : mesh(prepareMesh(std::make_shared<Mesh>(testmesh::torus(1.0, 0.35, 48, 24)), "torus", false)) {
        Settings settings;
        settings.builder = Builder::Meshlet;
        settings.limits.maxTriangles = settings.limits.maxVertices = 24;
        settings.cones = {cone};
        clusters = buildClusters(mesh, settings);
    }
    PreparedMesh mesh;
    ClusterSet clusters;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(LessonText, ComparedNumbersAreWrittenFarEnoughToDiffer) {
    using namespace lessontext;
    EXPECT_EQ(compared(0.41201, 0.41204), std::make_pair(std::string("0.41201"), std::string("0.41204")));
    EXPECT_EQ(compared(0.5, 0.25), std::make_pair(std::string("0.5000"), std::string("0.2500")));
    EXPECT_EQ(inequality(0.41204, 0.41201), "0.41204 > 0.41201");
    EXPECT_EQ(inequality(-0.25, 0.5), "\u22120.2500 \u2264 0.5000");
    EXPECT_EQ(degrees(23.449), "23.4\u00b0");
    EXPECT_EQ(percent(0.3014), "30.1%");
    EXPECT_EQ(amount(0.0012345), "0.0012");
    EXPECT_EQ(count(1, "face", "faces"), "1 face");
    EXPECT_EQ(count(3, "face", "faces"), "3 faces");
}

TEST(Lesson, SixStepsWithTheDecisionsNumbersAndOutcome) {
    const Prepared p(ConeMethod::Minimal);
    const CullingInput input = cullingInput(p.mesh, p.clusters);
    std::mt19937_64 random(11);
    std::map<LessonOutcome, size_t> seen;
    for (int trial = 0; trial < 24; ++trial) {
        Eye eye = Eye::perspective(randomUnit(random) * (1.2 + 1.5 * (trial % 4)));
        if (trial % 6 == 5) eye = Eye::orthographicAlong(randomUnit(random));
        for (CullTest test : {CullTest::Apex, CullTest::Octagon, CullTest::Sphere, CullTest::Aabb, CullTest::Oracle}) {
            for (uint32_t c = 0; c < p.clusters.bounds.count(); c += 7) {
                const Lesson lesson = makeLesson(p.mesh, p.clusters, c, eye, test);
                const CullExplanation why = explainCull(input, c, eye, test);
                ASSERT_EQ(lesson.steps.size(), size_t(kLessonStepCount));
                for (const LessonStep& step : lesson.steps) {
                    EXPECT_FALSE(step.title.empty());
                    EXPECT_GT(step.text.size(), 80u) << step.title;
                }
                EXPECT_EQ(lesson.why.culled, why.culled);
                EXPECT_EQ(lesson.verdict(), why.culled ? "culled" : "drawn");
                EXPECT_DOUBLE_EQ(lesson.alphaDegrees(), glm::degrees(p.clusters.bounds.cones[c].halfAngle()));
                // The outcome is the oracle's, as the statistics count it.
                LessonOutcome expected = LessonOutcome::Visible;
                if (why.culled) expected = LessonOutcome::Culled;
                else if (why.backFaces > 0) expected = why.frontFaces == 0 ? LessonOutcome::LostToTest : LessonOutcome::LostToPartition;
                EXPECT_EQ(lesson.outcome, expected);
                ++seen[lesson.outcome];
                EXPECT_TRUE(contains(lesson.steps[5].text, lesson.outcome == LessonOutcome::LostToTest ? "lost to the test"
                                                           : lesson.outcome == LessonOutcome::LostToPartition ? "lost to the partition"
                                                                                                              : ""));
                EXPECT_TRUE(contains(lesson.steps[5].text, why.culled ? "Culled" : "Drawn"));
                EXPECT_TRUE(contains(lesson.steps[0].text, "Cluster " + std::to_string(c) + " of torus"));
            }
        }
    }
    EXPECT_GT(seen[LessonOutcome::Culled], 0u);
    EXPECT_GT(seen[LessonOutcome::LostToTest], 0u);
    EXPECT_GT(seen[LessonOutcome::LostToPartition], 0u);
    EXPECT_GT(seen[LessonOutcome::Visible], 0u);
    EXPECT_EQ(seen[LessonOutcome::FalseCull], 0u);
}

// The inequality the step writes is the one the test decided by, with the numbers it compared.
TEST(Lesson, TheTestStepWritesTheComparedNumbersAndTheRightSign) {
    const Prepared p(ConeMethod::Average);
    std::mt19937_64 random(3);
    for (int trial = 0; trial < 30; ++trial) {
        const Eye eye = Eye::perspective(randomUnit(random) * (1.3 + trial % 5));
        for (uint32_t c = 0; c < p.clusters.bounds.count(); c += 5) {
            const Lesson apex = makeLesson(p.mesh, p.clusters, c, eye, CullTest::Apex);
            if (!apex.why.cullable) continue;
            const std::string& text = apex.steps[4].text;
            EXPECT_TRUE(contains(text, lessontext::inequality(apex.why.viewDotAxis, apex.why.threshold))) << text;
            EXPECT_TRUE(contains(text, apex.why.margin > 0.0 ? "so the test holds" : "so the test fails")) << text;
            EXPECT_TRUE(contains(apex.steps[2].text, lessontext::degrees(apex.why.halfAngleDegrees)));
            EXPECT_TRUE(contains(apex.steps[2].text, "average cone")) << apex.steps[2].text;
            const Lesson sphere = makeLesson(p.mesh, p.clusters, c, eye, CullTest::Sphere);
            if (!std::isnan(sphere.why.margin))
                EXPECT_TRUE(contains(sphere.steps[4].text, lessontext::inequality(sphere.why.viewDotAxis, sphere.why.threshold)));
            const Lesson octagon = makeLesson(p.mesh, p.clusters, c, eye, CullTest::Octagon);
            EXPECT_TRUE(contains(octagon.steps[4].text, std::to_string(octagon.why.edgesBack) + " of 8 edges pass"));
        }
    }
}

// The engines' records are told by their own rule and decision: the verdict and the margin's side
// are the record's, and a record that culls a visible face says it is a false cull.
TEST(Lesson, ARecordsTestIsToldByItsRuleAndItsOwnDecision) {
    const Prepared p(ConeMethod::Minimal);
    const CullingInput input = cullingInput(p.mesh, p.clusters);
    std::mt19937_64 random(5);
    std::map<bool, size_t> verdicts;
    for (int trial = 0; trial < 12; ++trial) {
        const Eye eye = Eye::perspective(randomUnit(random) * (1.3 + trial % 4));
        for (CullTest test : {CullTest::MeshoptApexF32, CullTest::MeshoptSphereS8, CullTest::CadsceneBoxS8, CullTest::OctagonCompact}) {
            for (uint32_t c = 0; c < p.clusters.bounds.count(); c += 9) {
                const Lesson lesson = makeLesson(p.mesh, p.clusters, c, eye, test);
                const CullExplanation why = explainCull(input, c, eye, test);
                EXPECT_EQ(lesson.why.culled, why.culled);
                EXPECT_TRUE(contains(lesson.steps[3].text, std::to_string(recordBytes(test)) + " bytes a cluster")) << lesson.steps[3].text;
                EXPECT_TRUE(contains(lesson.steps[4].text, ownRecordRule(test))) << lesson.steps[4].text;
                EXPECT_TRUE(contains(lesson.steps[4].text, why.margin > 0.0 ? "so the test holds" : "so the test fails"));
                if (why.culled && why.frontFaces > 0) EXPECT_EQ(lesson.outcome, LessonOutcome::FalseCull);
                EXPECT_DOUBLE_EQ(lesson.cullFraction, testCullFraction(p.clusters.cullMap, input, c, test));
                ++verdicts[why.culled];
            }
        }
    }
    EXPECT_GT(verdicts[true], 0u);
    EXPECT_GT(verdicts[false], 0u);
}

TEST(Lesson, AClusterWithoutAConeIsNeverCulledAndSaysSo) {
    // A closed cube as one cluster: its normals point every way.
    const Mesh cube = testmesh::quadCube();
    PreparedMesh prepared = prepareMesh(std::make_shared<Mesh>(cube), "cube", false);
    Settings settings;
    settings.builder = Builder::KMeans;
    settings.clusterCount = 1;
    const ClusterSet clusters = buildClusters(prepared, settings);
    ASSERT_EQ(clusters.partition.clusterCount, 1u);
    const Lesson lesson = makeLesson(prepared, clusters, 0, Eye::perspective({3.0, 2.0, 4.0}), CullTest::Apex);
    EXPECT_FALSE(lesson.why.cullable);
    EXPECT_EQ(lesson.verdict(), "drawn");
    EXPECT_TRUE(contains(lesson.steps[2].text, "This cluster has no cone: its normals span more than a half-space")) << lesson.steps[2].text;
    // No apex is described for a cluster without a cone.
    EXPECT_TRUE(contains(lesson.steps[3].text, "no apex either")) << lesson.steps[3].text;
    EXPECT_FALSE(contains(lesson.steps[3].text, "from the cluster's centre along")) << lesson.steps[3].text;
    EXPECT_TRUE(contains(lesson.steps[4].text, "Without a cone"));
    EXPECT_EQ(lesson.outcome, LessonOutcome::LostToPartition);
}

// An orbit slide's words are one eye's statistics: the same counts, the efficiency as a percentage.
TEST(Lesson, ViewInWordsSaysTheEyesCountsAndEfficiency) {
    const Prepared p(ConeMethod::Minimal);
    const EyeMeasurement measured = measureEye(p.mesh, p.clusters, Eye::perspective({0.3, 2.5, 0.4}), CullTest::Octagon);
    const CullTestStatistics& view = measured.statistics;
    ASSERT_GT(view.clustersCulled, 0u);
    const std::string text = viewInWords(view, p.clusters.bounds.count());
    EXPECT_EQ(text.rfind("The octagon test culls " + std::to_string(view.clustersCulled) + " of " +
                             std::to_string(p.clusters.bounds.count()) + " clusters: " + std::to_string(view.trianglesCulled) +
                             " of the " + std::to_string(view.backFacingTriangles) + " back-facing triangles, an efficiency of " +
                             lessontext::percent(view.efficiency) + ".",
                         0),
              0u)
        << text;
    EXPECT_TRUE(contains(text, std::to_string(view.testLossTriangles) + " are lost to the test")) << text;
    EXPECT_TRUE(contains(text, std::to_string(view.partitionLossTriangles) + " to the partition")) << text;
}
