#include "GranularityLesson.h"

#include <stdexcept>

#include "LessonText.h"

namespace conescope {

using namespace lessontext;

namespace {

// What the lesson reads: the displayed one-cone record, each K's float and compact rows, the ceiling.
struct LessonNumbers {
    const RunStatistics* run = nullptr;
    const CullTestStatistics* oneCone = nullptr;
    const GranularityRow* oneConeRow = nullptr;
    std::vector<const GranularityRow*> floats, compacts;  // one per kGranularityCones
    const GranularityRow* triangle = nullptr;
    const std::vector<GranularityConeWidths>* widths = nullptr;
};

const GranularityRow* rowNamed(const GranularityReport& report, const std::string& name) {
    for (const GranularityRow& row : report.rows)
        if (row.record == name) return &row;
    throw std::invalid_argument("The granularity report has no row " + name + ".");
}

LessonNumbers numbersOf(const GranularityReport& report) {
    LessonNumbers numbers;
    numbers.run = &report.run;
    const ConeMethod cone = displayedCone(report.run.settings);
    const CullTest test = displayedTest(report.run.settings);
    for (const CullTestStatistics& result : report.run.results)
        if (result.test == test && (result.engineRecord || result.cone == cone)) {
            numbers.oneCone = &result;
            break;
        }
    if (!numbers.oneCone) throw std::invalid_argument("The granularity report has no statistics of its displayed test.");
    numbers.oneConeRow = rowNamed(report, numbers.oneCone->engineRecord ? toString(test) : toString(cone) + "/" + toString(test));
    for (uint32_t k : kGranularityCones) {
        numbers.floats.push_back(rowNamed(report, "cones-" + std::to_string(k)));
        numbers.compacts.push_back(rowNamed(report, "cones-" + std::to_string(k) + "-compact"));
    }
    numbers.triangle = rowNamed(report, "triangle");
    if (report.widths.size() != std::size(kGranularityCones) + 1)
        throw std::invalid_argument("The granularity report has no cone widths.");
    numbers.widths = &report.widths;
    return numbers;
}

double share(size_t part, size_t whole) { return whole == 0 ? 0.0 : double(part) / double(whole); }

std::string bytes(size_t value) { return count(value, "byte", "bytes"); }

std::string bits(double value) { return format("%.2f", value) + " bits a triangle"; }

std::string partitionStep(const LessonNumbers& n) {
    const CullTestStatistics& one = *n.oneCone;
    const GranularityRow& row = *n.oneConeRow;
    const double partition = share(one.partitionLossTriangles, one.backFacingTriangles);
    const double test = share(one.testLossTriangles, one.backFacingTriangles);
    return "With one normal cone per cluster (the " + row.record + " record, " + bytes(row.bytesPerCluster) +
           " a cluster), the test culled " + percent(row.efficiency) + " of the back faces from the " +
           count(n.run->viewCount, "view", "views") + " of " + count(n.run->clusters, "cluster", "clusters") + ", " +
           percent(row.culledShare) + " of all triangles. " + percent(partition) +
           " of the back faces lie in clusters that also hold a face turned to the eye: they are lost to the partition, and "
           "no test on a single cone could cull them. The test itself lost " + percent(test) +
           (test < partition ? ", less than the partition" : "") +
           ". One cone must hold every normal of its cluster, and a cluster drawn for one face draws all its back faces too.";
}

std::string widthStep(const LessonNumbers& n) {
    const std::vector<GranularityConeWidths>& widths = *n.widths;
    std::string angles, coneless, expected, counts;
    bool narrowing = true;
    for (size_t i = 0; i < widths.size(); ++i) {
        const std::string sep = i == 0 ? "" : i + 1 == widths.size() ? " and " : ", ";
        // No sub-group with a cone: no width to quote (its mean reads 0).
        angles += sep + (widths[i].conelessShare >= 1.0 ? std::string("none") : degrees(widths[i].meanHalfAngleDegrees));
        coneless += sep + percent(widths[i].conelessShare);
        expected += sep + percent(widths[i].expectedCulledShare);
        counts += sep + std::to_string(widths[i].cones);
        if (widths[i].conelessShare >= 1.0 || (i > 0 && !(widths[i].meanHalfAngleDegrees < widths[i - 1].meanHalfAngleDegrees)))
            narrowing = false;
    }
    return "Split each cluster's triangles into K sub-groups of similar normals, each with a cone and an apex of its "
           "own: each cone holds fewer normals, and a sub-group facing away is culled even when another "
           "sub-group of its cluster faces the eye. With " + counts + " cones per cluster the mean half-angle \u03b1 of the "
           "cones (weighted by triangles, over the sub-groups that have one) is " + angles + (narrowing ? ": the more cones, the narrower. " : ". ") +
           "The sub-groups no cone narrower than a hemisphere holds (never culled) hold " + coneless + " of all triangles. "
           "A cone of half-angle \u03b1 is culled from (1 \u2212 sin \u03b1)/2 of the far view directions, so the cones promise " +
           expected + " of all triangles culled from a random direction.";
}

std::string costStep(const LessonNumbers& n) {
    const GranularityRow& one = *n.oneConeRow;
    std::string text = "What the views measured, against what a renderer stores per cluster: one cone culls " + percent(one.culledShare) +
                       " of all triangles in " + bytes(one.bytesPerCluster) + " (" + bits(one.bitsPerTriangle) + "). ";
    for (size_t i = 0; i < n.floats.size(); ++i) {
        const GranularityRow &f = *n.floats[i], &c = *n.compacts[i];
        text += std::to_string(kGranularityCones[i]) + " cones cull " + percent(f.culledShare) +
                (one.culledShare > 0.0 ? " (" + format("%.2f", f.culledShare / one.culledShare) + "\u00d7 one cone)" : std::string()) + " in " +
                bytes(f.bytesPerCluster) + ", or " + percent(c.culledShare) + " in a compact " + bytes(c.bytesPerCluster) + " (" +
                bits(c.bitsPerTriangle) + ")" + (i + 1 == n.floats.size() ? ". " : "; ");
    }
    // The gain of each doubling, in points of all triangles.
    std::string gains;
    double previous = one.culledShare;
    std::vector<double> steps;
    for (size_t i = 0; i < n.floats.size(); ++i) {
        steps.push_back(n.floats[i]->culledShare - previous);
        previous = n.floats[i]->culledShare;
        gains += std::string(i == 0 ? "" : i + 1 == n.floats.size() ? " and " : ", ") + format("%+.1f", 100.0 * steps.back());
    }
    text += "From one cone to " + std::to_string(kGranularityCones[0]) + " and each doubling after, the culled share moves by " + gains +
            " points of all triangles";
    if (steps.back() < steps[steps.size() - 2])
        return text + ": the last doubling gains less than the one before, while its cones cost bytes in every cluster.";
    return text + ": on this mesh the last doubling still gains no less than the one before.";
}

std::string ceilingStep(const LessonNumbers& n) {
    const GranularityRow& ceiling = *n.triangle;
    const GranularityRow& eight = *n.floats.back();
    const GranularityRow& one = *n.oneConeRow;
    std::string text = "Culling every triangle on its own, after the cluster test, culls every back face: " + percent(ceiling.culledShare) +
                       " of all triangles, the ceiling no record passes. It costs tests, not bytes: " + number(ceiling.testsPerView) +
                       " tests per view (each cluster once, then each triangle of the clusters drawn), against " +
                       number(one.testsPerView) + " for one cone and " + number(eight.testsPerView) + " for " +
                       std::to_string(kGranularityCones[std::size(kGranularityCones) - 1]) + " cones per cluster. ";
    if (ceiling.culledShare > 0.0)
        text += "One cone reaches " + percent(one.culledShare / ceiling.culledShare) + " of the ceiling, " +
                std::to_string(kGranularityCones[std::size(kGranularityCones) - 1]) + " cones " +
                percent(eight.culledShare / ceiling.culledShare) + ". ";
    size_t falseCulls = 0;
    for (const GranularityRow* row : n.floats) falseCulls += row->falseCulls;
    for (const GranularityRow* row : n.compacts) falseCulls += row->falseCulls;
    return text + (falseCulls == 0 ? "None of the K-cone records culled a visible face."
                                   : "The K-cone records culled " + count(falseCulls, "sub-group", "sub-groups") + " holding a visible face.");
}

}  // namespace

GranularityLesson makeGranularityLesson(const GranularityReport& report) {
    const LessonNumbers numbers = numbersOf(report);
    GranularityLesson lesson;
    lesson.meshName = report.run.meshName;
    lesson.steps = {{"What one cone loses to the partition", partitionStep(numbers)},
                    {"More cones, narrower cones", widthStep(numbers)},
                    {"Culled share against bytes", costStep(numbers)},
                    {"The per-triangle ceiling and its tests", ceilingStep(numbers)}};
    return lesson;
}

std::string granularityLessonMarkdown(const GranularityLesson& lesson) {
    std::string text = "# Why more cones cull more, and what they cost: " + (lesson.meshName.empty() ? std::string("this mesh") : lesson.meshName) + "\n";
    for (const LessonStep& step : lesson.steps) text += "\n## " + step.title + "\n\n" + step.text + "\n";
    return text;
}

}  // namespace conescope
