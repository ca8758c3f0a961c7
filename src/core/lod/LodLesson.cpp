#include "LodLesson.h"

#include <cmath>
#include <stdexcept>

#include "core/ExpectedCull.h"
#include "core/LessonText.h"

namespace conescope {

using namespace lessontext;

namespace {

// "levels 0, 1 and 2".
std::string levelList(const std::vector<size_t>& levels) {
    if (levels.empty()) return "no level";
    std::string text = levels.size() == 1 ? "level " : "levels ";
    for (size_t i = 0; i < levels.size(); ++i)
        text += (i == 0 ? "" : i + 1 == levels.size() ? " and " : ", ") + std::to_string(levels[i]);
    return text;
}

std::string levelName(const LodLessonLevel& level) { return "level " + std::to_string(level.level); }

std::string sizeStep(const LodLesson& lesson) {
    const LodLessonLevel &fine = lesson.fine, &coarse = lesson.coarse;
    std::string text = "An engine that draws a cluster hierarchy builds it level by level: it groups neighbouring clusters, "
                       "simplifies each group to about half its triangles and splits it into clusters again. The hierarchy of " +
                       (lesson.meshName.empty() ? std::string("this mesh") : lesson.meshName) + " has " +
                       std::to_string(lesson.levels) + " levels. Level 0 splits its " + count(fine.triangles, "triangle", "triangles") +
                       " into " + count(fine.clusters, "cluster", "clusters") + " of " + number(fine.trianglesPerCluster) +
                       " triangles on average; " + levelName(coarse) + " keeps " + count(coarse.triangles, "triangle", "triangles") +
                       " in " + count(coarse.clusters, "cluster", "clusters") + " of " + number(coarse.trianglesPerCluster) + " each. ";
    if (fine.meanSphereRadius > 0.0 && coarse.meanSphereRadius > fine.meanSphereRadius)
        return text + "Each of its clusters covers more of the surface, with larger triangles: the mean radius of a cluster's "
                      "bounding sphere grows from " + number(fine.meanSphereRadius) + " to " + number(coarse.meanSphereRadius) +
               ", " + number(coarse.meanSphereRadius / fine.meanSphereRadius) + " times as far.";
    return text + "Here its clusters are no larger than level 0's: the mean radius of a cluster's bounding sphere is " +
           number(coarse.meanSphereRadius) + " against " + number(fine.meanSphereRadius) + ".";
}

std::string spreadStep(const LodLesson& lesson) {
    const LodLessonLevel &fine = lesson.fine, &coarse = lesson.coarse;
    std::string text = "A larger patch of a curved surface bends more, so its face normals spread further over the Gauss "
                       "sphere and the cone that holds them must open wider, until no cone narrower than a hemisphere holds "
                       "them and no eye can cull the cluster. ";
    text += percent(fine.uncullableShare) + " of level 0's clusters and " + percent(coarse.uncullableShare) + " of " +
            levelName(coarse) + "'s have no such cone. The mean half-angle \u03b1 of those that have one (weighted by "
            "triangles) is " + degrees(fine.meanHalfAngleDegrees) + " at level 0 and " + degrees(coarse.meanHalfAngleDegrees) +
            " at " + levelName(coarse) + "; the widest open " + degrees(fine.maxHalfAngleDegrees) + " and " +
            degrees(coarse.maxHalfAngleDegrees) + ".";
    const bool moreConeless = coarse.uncullableShare > fine.uncullableShare;
    if (coarse.meanHalfAngleDegrees > fine.meanHalfAngleDegrees) return text;
    if (moreConeless)
        return text + " The cones left are not wider here: the widest ones were lost altogether, to clusters with no cone.";
    return text + " On this mesh the coarse cones are not wider: its coarse patches stay about as flat as the fine ones.";
}

std::string cullStep(const LodLesson& lesson) {
    const LodLessonLevel &fine = lesson.fine, &coarse = lesson.coarse;
    const auto share = [](double degreesValue) { return percent(coneCullShare(std::sin(degreesValue * M_PI / 180.0))); };
    std::string text = "Seen from far away, a cone of half-angle \u03b1 is culled from (1 \u2212 sin \u03b1)/2 of all directions: " +
                       share(fine.meanHalfAngleDegrees) + " at " + degrees(fine.meanHalfAngleDegrees) + ", " +
                       share(coarse.meanHalfAngleDegrees) + " at " + degrees(coarse.meanHalfAngleDegrees) + ". " +
                       "Summed over the clusters, \u03a3 T(1 \u2212 sin \u03b1)/2 / T (a cluster without a cone adds nothing), level 0's "
                       "cones cull " +
                       percent(fine.expectedCulledShare) + " of all triangles from a random direction and " + levelName(coarse) +
                       "'s " + percent(coarse.expectedCulledShare) + "; half the triangles face away, so that is an expected " +
                       "efficiency of " + percent(fine.expectedEfficiency) + " against " + percent(coarse.expectedEfficiency) + ". ";
    text += "Measured from the " + count(fine.views, "view", "views") + ", the test culled " + percent(fine.efficiency) +
            " of level 0's back faces and " + percent(coarse.efficiency) + " of " + levelName(coarse) + "'s";
    if (!(coarse.efficiency < fine.efficiency)) return text + ": here the coarser level culls no less.";
    if (coarse.expectedEfficiency < fine.expectedEfficiency)
        return text + ": the coarser clusters cull less, as the widths of their cones predicted.";
    return text + ": the coarser clusters cull less, although the widths of their cones predicted no loss.";
}

std::string engineStep(const LodLesson& lesson) {
    const LodLessonLevel& fine = lesson.fine;
    const bool one = lesson.threshold.value == 1.0;
    const std::string threshold = number(lesson.threshold.value) + (lesson.threshold.worldUnits ? (one ? " world unit" : " world units")
                                                                                                : (one ? " pixel" : " pixels"));
    std::string text = "An engine does not draw one level: from each eye it draws a cut, the coarsest clusters whose error "
                       "looks smaller than a threshold there, and only the cut is culled. From the same views with an error of at "
                       "most " + threshold + ", the cut drew " + std::to_string(std::lround(lesson.cutMeanTriangles)) + " triangles on average (level 0 has " +
                       std::to_string(fine.triangles) + "), from " + levelList(lesson.cutLevels) + ", and the cone test culled " +
                       percent(lesson.cutEfficiency) + " of its back faces, against " + percent(fine.efficiency) + " of level 0's. ";
    if (lesson.cutEfficiency < fine.efficiency)
        return text + "The hierarchy saves triangles by drawing coarse clusters far away, and the cones lose the most exactly "
                      "there: the farther the eye, the coarser the cut and the less a normal cone can skip. Engines that store "
                      "no cone at all lose all of it.";
    return text + "From these views the cut culls no less than level 0. Engines that store no cone at all lose all of it.";
}

}  // namespace

LodLessonLevel lodLessonLevel(const LodLevelStatistics& level) {
    LodLessonLevel numbers;
    numbers.level = level.level;
    numbers.clusters = level.clusters;
    numbers.triangles = level.triangles;
    numbers.trianglesPerCluster = level.clusters > 0 ? double(level.triangles) / double(level.clusters) : 0.0;
    numbers.meanSphereRadius = level.culling.meanSphereRadius;
    numbers.meanHalfAngleDegrees = level.meanHalfAngleDegrees;
    numbers.maxHalfAngleDegrees = level.maxHalfAngleDegrees;
    numbers.uncullableShare = uncullableShare(level.culling.uncullableClusters, level.clusters);
    numbers.expectedEfficiency = level.culling.expectedEfficiency;
    // From a random direction half the triangles face away: the culled share of all is half the efficiency.
    numbers.expectedCulledShare = 0.5 * level.culling.expectedEfficiency;
    numbers.efficiency = level.culling.efficiency;
    numbers.views = level.culling.views.size();
    return numbers;
}

size_t lodLessonCoarseLevel(const LodStatistics& statistics, size_t minClusters) {
    if (statistics.levels.size() < 2) throw std::invalid_argument("The hierarchy has a single level: there is no coarser level to compare.");
    for (size_t l = statistics.levels.size() - 1; l > 0; --l)
        if (statistics.levels[l].clusters >= minClusters) return l;
    return 1;
}

LodLesson makeLodLesson(const LodStatistics& statistics, const std::string& meshName, size_t coarseLevel) {
    if (coarseLevel == 0 || coarseLevel >= statistics.levels.size())
        throw std::invalid_argument("No level " + std::to_string(coarseLevel) + " to compare with level 0: the hierarchy has " +
                                    std::to_string(statistics.levels.size()) + " levels.");
    LodLesson lesson;
    lesson.meshName = meshName;
    lesson.levels = statistics.levels.size();
    lesson.fine = lodLessonLevel(statistics.levels.front());
    lesson.coarse = lodLessonLevel(statistics.levels[coarseLevel]);
    lesson.cutMeanTriangles = statistics.cut.meanTriangles;
    lesson.cutEfficiency = statistics.cut.efficiency;
    lesson.cutLevels = statistics.cut.levelsUsed;
    lesson.threshold = statistics.threshold;
    lesson.steps = {{"Coarser levels, bigger clusters", sizeStep(lesson)},
                    {"Wider patches, wider cones", spreadStep(lesson)},
                    {"Wider cones cull from fewer directions", cullStep(lesson)},
                    {"What an engine drawing the hierarchy keeps", engineStep(lesson)}};
    return lesson;
}

LodLesson makeLodLesson(const LodStatistics& statistics, const std::string& meshName) {
    return makeLodLesson(statistics, meshName, lodLessonCoarseLevel(statistics));
}

}  // namespace conescope
