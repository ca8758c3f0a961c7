// The lesson on why more cones cull more: every number it quotes is its report's, its claims follow
// the numbers, and the Markdown is the steps.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

#include "TestMeshes.h"
#include "core/GranularityLesson.h"
#include "core/LessonText.h"

using namespace conescope;
using namespace conescope::lessontext;

namespace {

GranularityReport torusReport() {
    Settings settings;
    settings.views = 24;
    return runGranularity(testmesh::torus(1.0, 0.35, 48, 24), settings, "torus");
}

const GranularityRow& row(const GranularityReport& report, const std::string& name) {
    for (const GranularityRow& r : report.rows)
        if (r.record == name) return r;
    throw std::out_of_range(name);
}

}  // namespace

TEST(GranularityLesson, ConeWidthsNarrowWithMoreCones) {
    const GranularityReport report = torusReport();
    ASSERT_EQ(report.widths.size(), 4u);
    EXPECT_EQ(report.widths[0].cones, 1u);
    for (size_t i = 1; i < report.widths.size(); ++i) {
        EXPECT_EQ(report.widths[i].cones, kGranularityCones[i - 1]);
        EXPECT_LE(report.widths[i].meanHalfAngleDegrees, report.widths[i - 1].meanHalfAngleDegrees + 1e-9) << i;
        EXPECT_GE(report.widths[i].expectedCulledShare, 0.0);
        EXPECT_LE(report.widths[i].expectedCulledShare, 0.5);
    }
    // The minimal cones of K = 1 promise what the displayed minimal cones promise: sum T (1 - sin a) / 2 / T.
    double expected = 0.0, triangles = 0.0;
    Settings minimal = report.run.settings;
    minimal.cones = {ConeMethod::Minimal};
    const ClusterSet clusters = buildClusters(prepareBorrowed(testmesh::torus(1.0, 0.35, 48, 24), "torus", false), minimal);
    for (size_t c = 0; c < clusters.bounds.count(); ++c) {
        triangles += clusters.bounds.triangles[c];
        if (clusters.bounds.cones[c].cullable) expected += clusters.bounds.triangles[c] * 0.5 * (1.0 - clusters.bounds.cones[c].sinHalfAngle);
    }
    EXPECT_NEAR(report.widths[0].expectedCulledShare, expected / triangles, 1e-9);
}

TEST(GranularityLesson, QuotesTheReportsNumbers) {
    const GranularityReport report = torusReport();
    const GranularityLesson lesson = makeGranularityLesson(report);
    ASSERT_EQ(lesson.steps.size(), size_t(kGranularityLessonStepCount));
    EXPECT_EQ(lesson.meshName, "torus");
    const GranularityRow& one = row(report, "chosen/octagon");
    const CullTestStatistics& result = report.run.results.front();
    const std::string& first = lesson.steps[0].text;
    EXPECT_NE(first.find(percent(one.efficiency) + " of the back faces"), std::string::npos) << first;
    EXPECT_NE(first.find(percent(double(result.partitionLossTriangles) / double(result.backFacingTriangles))), std::string::npos) << first;
    EXPECT_NE(first.find(count(report.run.clusters, "cluster", "clusters")), std::string::npos) << first;
    for (const GranularityConeWidths& widths : report.widths)
        EXPECT_NE(lesson.steps[1].text.find(degrees(widths.meanHalfAngleDegrees)), std::string::npos) << lesson.steps[1].text;
    for (uint32_t k : kGranularityCones) {
        const GranularityRow& f = row(report, "cones-" + std::to_string(k));
        const GranularityRow& c = row(report, "cones-" + std::to_string(k) + "-compact");
        const std::string& text = lesson.steps[2].text;
        EXPECT_NE(text.find(std::to_string(k) + " cones cull " + percent(f.culledShare)), std::string::npos) << k << ": " << text;
        EXPECT_NE(text.find("in " + std::to_string(f.bytesPerCluster) + " bytes"), std::string::npos) << k << ": " << text;
        EXPECT_NE(text.find(percent(c.culledShare) + " in a compact " + std::to_string(c.bytesPerCluster) + " bytes"), std::string::npos) << k;
    }
    const GranularityRow& triangle = row(report, "triangle");
    EXPECT_NE(lesson.steps[3].text.find(percent(triangle.culledShare) + " of all triangles, the ceiling"), std::string::npos);
    EXPECT_NE(lesson.steps[3].text.find(number(triangle.testsPerView) + " tests per view"), std::string::npos) << lesson.steps[3].text;
    EXPECT_NE(lesson.steps[3].text.find("None of the K-cone records culled a visible face"), std::string::npos);
}

TEST(GranularityLesson, MarkdownIsTheSteps) {
    const GranularityLesson lesson = makeGranularityLesson(torusReport());
    const std::string markdown = granularityLessonMarkdown(lesson);
    EXPECT_EQ(markdown.rfind("# Why more cones cull more, and what they cost: torus\n", 0), 0u);
    size_t at = 0;
    for (const LessonStep& step : lesson.steps) {
        at = markdown.find("\n## " + step.title + "\n\n" + step.text + "\n", at);
        ASSERT_NE(at, std::string::npos) << step.title;
    }
}

TEST(GranularityLesson, ReportWithoutItsRowsIsRefused) {
    GranularityReport report = torusReport();
    report.rows.pop_back();  // no triangle row
    EXPECT_THROW(makeGranularityLesson(report), std::invalid_argument);
    report = torusReport();
    report.widths.clear();
    EXPECT_THROW(makeGranularityLesson(report), std::invalid_argument);
}

// A cube is one cluster whose normals no cone narrower than a hemisphere holds: the lesson quotes no
// width for it and claims no narrowing it did not measure.
TEST(GranularityLesson, AClusterWithoutAConeHasNoWidth) {
    Settings settings;
    settings.views = 16;
    const GranularityReport report = runGranularity(testmesh::quadCube(), settings, "cube");
    ASSERT_EQ(report.run.clusters, 1u);
    EXPECT_EQ(report.widths[0].conelessShare, 1.0);
    const GranularityLesson lesson = makeGranularityLesson(report);
    EXPECT_NE(lesson.steps[1].text.find("is none, "), std::string::npos) << lesson.steps[1].text;
    EXPECT_EQ(lesson.steps[1].text.find("the more cones, the narrower"), std::string::npos) << lesson.steps[1].text;
    EXPECT_EQ(lesson.steps[0].text.find("culled 0.0% of the back faces"), lesson.steps[0].text.find("culled ")) << lesson.steps[0].text;
}
