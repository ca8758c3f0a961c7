#include "LessonExamples.h"

#include <stdexcept>

#include "Lesson.h"

namespace conescope {

const std::vector<LessonOutcome>& exampleOutcomes() {
    static const std::vector<LessonOutcome> outcomes = {LessonOutcome::Culled, LessonOutcome::Visible, LessonOutcome::LostToTest,
                                                        LessonOutcome::LostToPartition};
    return outcomes;
}

std::string exampleName(LessonOutcome outcome) {
    switch (outcome) {
        case LessonOutcome::Culled: return "culled";
        case LessonOutcome::Visible: return "drawn";
        case LessonOutcome::LostToTest: return "test-loss";
        case LessonOutcome::LostToPartition: return "partition-loss";
        case LessonOutcome::FalseCull: break;
    }
    return "false-cull";
}

LessonOutcome parseExample(const std::string& text) {
    std::string names;
    for (LessonOutcome outcome : exampleOutcomes()) {
        if (text == exampleName(outcome)) return outcome;
        names += (names.empty() ? "" : ", ") + exampleName(outcome);
    }
    throw std::invalid_argument("unknown example '" + text + "' (expected one of: " + names + ")");
}

ClusterSortKey exampleRanking(LessonOutcome outcome) {
    switch (outcome) {
        case LessonOutcome::LostToTest: return ClusterSortKey::TestLoss;
        case LessonOutcome::LostToPartition: return ClusterSortKey::PartitionLoss;
        case LessonOutcome::Culled:
        case LessonOutcome::Visible:
        case LessonOutcome::FalseCull: break;
    }
    return ClusterSortKey::MostCulled;
}

ClusterExample findExample(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                           const CullTestStatistics& orbit, LessonOutcome outcome, size_t candidates) {
    const std::vector<Eye> views = orbitOf(settings, prepared.box);
    for (uint32_t cluster : rankClusters(orbit, exampleRanking(outcome), candidates)) {
        const std::vector<ClusterInView> seen = clusterOverOrbit(prepared, clusters, settings, cluster);
        const ConeOfNormals& cone = clusters.bounds.cones[cluster];
        const glm::dvec3 centre = clusters.bounds.spheres[cluster].center;
        long best = -1;
        double bestAlong = 0.0;
        for (size_t v = 0; v < seen.size(); ++v) {
            if (outcomeOf(seen[v].culled, seen[v].frontFaces, seen[v].backFaces) != outcome) continue;
            if (outcome == LessonOutcome::LostToTest || outcome == LessonOutcome::LostToPartition) return {long(cluster), long(v)};
            // How nearly the view vector runs along V1 (a cull) or against it (a cluster facing the eye).
            const glm::dvec3 towards = views[v].orthographic ? views[v].direction : centre - views[v].position;
            const double along = cone.cullable && glm::length(towards) > 0.0 ? glm::dot(glm::normalize(towards), cone.axis) : 0.0;
            const double score = outcome == LessonOutcome::Culled ? along : -along;
            if (best < 0 || score > bestAlong) {
                best = long(v);
                bestAlong = score;
            }
        }
        if (best >= 0) return {long(cluster), best};
    }
    return {};
}

}  // namespace conescope
