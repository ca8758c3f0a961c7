// A lesson on one cluster's cull decision from one eye: seven steps, each a title and a few plain
// sentences with this cluster's numbers, in the order seed 000 builds the argument (faces and
// normals, the Gauss sphere, the cone, the bound, the eye and the test, the verdict), then the cluster
// beside one the same eye sees decided the other way. Every number comes from explainCull and the
// clusters' bounds, so the window's lesson dock, its cross-section and the explanation export all say
// what the test computed.
#pragma once

#include <string>

#include "LessonData.h"
#include "Pipeline.h"

namespace conescope {

std::string toString(LessonOutcome outcome);  // "culled", "lost to the test", "lost to the partition", ...

// What happened to a cluster, from the test's decision and its faces' facing (the oracle's).
LessonOutcome outcomeOf(bool culled, size_t frontFaces, size_t backFaces);

// The lesson on `cluster` of `clusters` from `eye` with `test` (the cone is the clusters' own).
Lesson makeLesson(const PreparedMesh& prepared, const ClusterSet& clusters, uint32_t cluster, const Eye& eye, CullTest test);

// The test's name in words: "the apex test", "the bounding-sphere test", ...
std::string testInWords(CullTest test);

// One view's statistics (a single eye's) in two sentences for an orbit slide: how many clusters and
// back-facing triangles the test culls, its efficiency, and what is lost to the test and the partition.
std::string viewInWords(const CullTestStatistics& view, size_t clusterCount);

}  // namespace conescope
