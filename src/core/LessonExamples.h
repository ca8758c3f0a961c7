// Clusters a lesson can show one outcome on: a culled cluster, a drawn one, one lost to the test, one
// lost to the partition, each with the orbit view that shows it so (the lesson dock's one-click
// choices, the replay's {"example": ...}). The candidates come from the orbit's ranking; the view is
// one of the orbit's, where the displayed test decides as the statistics counted.
#pragma once

#include <string>
#include <vector>

#include "ClusterRanking.h"
#include "LessonData.h"

namespace conescope {

// The outcomes a lesson offers examples of, in the dock's order: culled, drawn (every face turned to
// the eye), lost to the test, lost to the partition.
const std::vector<LessonOutcome>& exampleOutcomes();
// "culled", "drawn", "test-loss", "partition-loss".
std::string exampleName(LessonOutcome outcome);
// Throws std::invalid_argument listing the names.
LessonOutcome parseExample(const std::string& text);
// The ranking whose first clusters make the best examples: the clusters culled most often for a cull
// (and, seen from in front, for a drawn one), the test's and the partition's losses for theirs.
ClusterSortKey exampleRanking(LessonOutcome outcome);

struct ClusterExample {
    long cluster = -1;  // -1: no cluster shows the outcome from any orbit view
    long view = -1;     // the orbit view (0-based) it is shown from
};

// The first of the orbit's ranked clusters (at most `candidates` of them) that has the outcome from
// some orbit view, and that view: for a cull the one looking most nearly along the cone's axis (deep
// inside what the test culls), for a drawn cluster the one most nearly against it, for a loss the
// first.
ClusterExample findExample(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                           const CullTestStatistics& orbit, LessonOutcome outcome, size_t candidates = 64);

}  // namespace conescope
