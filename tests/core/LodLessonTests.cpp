// The lesson on why coarse clusters cull less: its numbers are the measured hierarchy's (recomputed
// here from the levels' clusters), its words quote them as the lessons write numbers, and it says
// what the numbers say (coarser, wider, culls less) on a curved mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "TestMeshes.h"
#include "core/LessonText.h"
#include "core/lod/LodLesson.h"

namespace conescope {
namespace {

using namespace lessontext;

const LodStatistics& sphereLevels() {
    static const LodStatistics statistics = [] {
        Settings settings;
        settings.views = 32;
        settings.distance = 6.0;
        LodThreshold pixels;
        pixels.value = 4.0;
        return lodOfMesh(testmesh::icosphere(5), "icosphere", settings, pixels);
    }();
    return statistics;
}

bool says(const LodLesson& lesson, const std::string& words) {
    for (const LessonStep& step : lesson.steps)
        if (step.text.find(words) != std::string::npos) return true;
    return false;
}

// A level's numbers recomputed from its clusters: triangle-weighted mean half-angle over those with a
// cone, and sum T (1 - sin alpha) / 2 / T over all triangles (no cone: never culled).
void expectLevelFromClusters(const LodLessonLevel& numbers, const LodLevelStatistics& level) {
    double weighted = 0.0, withCone = 0.0, culledShare = 0.0, all = 0.0;
    size_t coneless = 0;
    for (const ClusterStatistics& cluster : level.culling.clusters) {
        all += double(cluster.triangles);
        if (!cluster.cullable) {
            ++coneless;
            continue;
        }
        weighted += cluster.halfAngleDegrees * double(cluster.triangles);
        withCone += double(cluster.triangles);
        culledShare += double(cluster.triangles) * (1.0 - std::sin(cluster.halfAngleDegrees * M_PI / 180.0)) / 2.0;
    }
    EXPECT_EQ(numbers.level, level.level);
    EXPECT_EQ(numbers.clusters, level.culling.clusters.size());
    EXPECT_EQ(numbers.triangles, size_t(all));
    EXPECT_NEAR(numbers.meanHalfAngleDegrees, withCone > 0.0 ? weighted / withCone : 0.0, 1e-9);
    EXPECT_NEAR(numbers.expectedCulledShare, culledShare / all, 1e-6);
    EXPECT_DOUBLE_EQ(numbers.expectedEfficiency, 2.0 * numbers.expectedCulledShare);
    EXPECT_DOUBLE_EQ(numbers.uncullableShare, double(coneless) / double(level.culling.clusters.size()));
    EXPECT_EQ(numbers.efficiency, level.culling.efficiency);
    EXPECT_EQ(numbers.views, level.culling.views.size());
}

TEST(LodLesson, NumbersAreTheMeasuredHierarchys) {
    const LodStatistics& statistics = sphereLevels();
    const size_t coarse = lodLessonCoarseLevel(statistics);
    ASSERT_GT(coarse, 0u);
    EXPECT_GE(statistics.levels[coarse].clusters, 8u);
    const LodLesson lesson = makeLodLesson(statistics, "icosphere");
    ASSERT_EQ(lesson.steps.size(), size_t(kLodLessonStepCount));
    EXPECT_EQ(lesson.coarse.level, coarse);
    EXPECT_EQ(lesson.levels, statistics.levels.size());
    expectLevelFromClusters(lesson.fine, statistics.levels.front());
    expectLevelFromClusters(lesson.coarse, statistics.levels[coarse]);
    EXPECT_EQ(lesson.cutEfficiency, statistics.cut.efficiency);
    EXPECT_EQ(lesson.cutMeanTriangles, statistics.cut.meanTriangles);
    EXPECT_EQ(lesson.cutLevels, statistics.cut.levelsUsed);
}

TEST(LodLesson, WordsQuoteTheNumbers) {
    const LodStatistics& statistics = sphereLevels();
    const LodLesson lesson = makeLodLesson(statistics, "icosphere");
    const LodLevelStatistics &fine = statistics.levels.front(), &coarse = statistics.levels[lesson.coarse.level];
    for (const LodLevelStatistics* level : {&fine, &coarse}) {
        EXPECT_TRUE(says(lesson, degrees(level->meanHalfAngleDegrees))) << level->level;
        EXPECT_TRUE(says(lesson, percent(level->culling.efficiency))) << level->level;
        EXPECT_TRUE(says(lesson, percent(level->culling.expectedEfficiency))) << level->level;
        EXPECT_TRUE(says(lesson, percent(level->culling.expectedEfficiency / 2.0))) << level->level;
        EXPECT_TRUE(says(lesson, std::to_string(level->triangles) + " triangles")) << level->level;
        EXPECT_TRUE(says(lesson, std::to_string(level->clusters) + " clusters")) << level->level;
    }
    EXPECT_TRUE(says(lesson, percent(statistics.cut.efficiency)));
    EXPECT_TRUE(says(lesson, "drew " + std::to_string(std::lround(statistics.cut.meanTriangles)) + " triangles"));
    EXPECT_TRUE(says(lesson, "level " + std::to_string(lesson.coarse.level)));
    EXPECT_TRUE(says(lesson, std::to_string(statistics.levels.size()) + " levels"));
}

// On a sphere the coarse patches bend more: wider cones, and the lesson says the coarse level culls less.
TEST(LodLesson, SaysCoarseClustersCullLessWhereTheyDo) {
    const LodLesson lesson = makeLodLesson(sphereLevels(), "icosphere");
    EXPECT_GT(lesson.coarse.meanSphereRadius, lesson.fine.meanSphereRadius);
    EXPECT_GT(lesson.coarse.meanHalfAngleDegrees, lesson.fine.meanHalfAngleDegrees);
    EXPECT_LT(lesson.coarse.efficiency, lesson.fine.efficiency);
    EXPECT_TRUE(says(lesson, "the coarser clusters cull less"));
    EXPECT_FALSE(says(lesson, "culls no less"));
    EXPECT_FALSE(says(lesson, "are not wider"));
}

// Where the coarse level's remaining cones are narrower but more of its clusters have none (as on
// CGAL's anchor), the lesson says so rather than that the cones widened; where the coarse level culls
// no less, it does not claim it does.
TEST(LodLesson, WordsFollowTheNumbersTheyQuote) {
    LodStatistics statistics;
    for (size_t l = 0; l < 2; ++l) {
        LodLevelStatistics& level = statistics.levels.emplace_back();
        level.level = l;
        level.clusters = 10;
        level.triangles = 1000 / (l + 1);
        level.culling.views.resize(4);
    }
    LodLevelStatistics &fine = statistics.levels[0], &coarse = statistics.levels[1];
    fine.meanHalfAngleDegrees = 54.0, coarse.meanHalfAngleDegrees = 46.0;
    fine.culling.uncullableClusters = 5, coarse.culling.uncullableClusters = 8;
    fine.culling.expectedEfficiency = 0.09, coarse.culling.expectedEfficiency = 0.04;
    fine.culling.efficiency = 0.10, coarse.culling.efficiency = 0.04;
    LodLesson lesson = makeLodLesson(statistics, "made up", 1);
    EXPECT_TRUE(says(lesson, "The cones left are not wider here"));
    EXPECT_TRUE(says(lesson, "as the widths of their cones predicted"));
    coarse.culling.efficiency = 0.12;
    lesson = makeLodLesson(statistics, "made up", 1);
    EXPECT_TRUE(says(lesson, "here the coarser level culls no less"));
    EXPECT_FALSE(says(lesson, "the coarser clusters cull less"));
}

TEST(LodLesson, RefusesLevelsItCannotCompare) {
    const LodStatistics& statistics = sphereLevels();
    EXPECT_THROW(makeLodLesson(statistics, "icosphere", 0), std::invalid_argument);
    EXPECT_THROW(makeLodLesson(statistics, "icosphere", statistics.levels.size()), std::invalid_argument);
    LodStatistics single;
    single.levels.push_back(statistics.levels.front());
    EXPECT_THROW(makeLodLesson(single, "one level"), std::invalid_argument);
}

}  // namespace
}  // namespace conescope
