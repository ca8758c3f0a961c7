// A short lesson on why coarse clusters cull less, told with one measured hierarchy: level 0 beside a
// coarser level of the same mesh (how much surface a cluster covers, how wide its cone opens, what
// the cones promise and what the test culled), then what the cut an engine draws keeps of cone
// culling. Every number is read from the LodStatistics it is made from (measureHierarchy, lodOfMesh).
#pragma once

#include <string>
#include <vector>

#include "LodCut.h"
#include "core/LessonData.h"

namespace conescope {

// The numbers the lesson quotes for one level.
struct LodLessonLevel {
    size_t level = 0, clusters = 0, triangles = 0;
    double trianglesPerCluster = 0.0;
    double meanSphereRadius = 0.0;      // of the clusters' bounding spheres: the surface one covers
    double meanHalfAngleDegrees = 0.0;  // triangle-weighted, over the clusters with a cone
    double maxHalfAngleDegrees = 0.0;
    double uncullableShare = 0.0;       // clusters with no cone narrower than a hemisphere
    // sum T (1 - sin alpha) / 2 / T: the share of all triangles culled from a random far direction.
    double expectedCulledShare = 0.0;
    double expectedEfficiency = 0.0;    // the same of the back faces (half face away): twice that
    double efficiency = 0.0;            // measured over the views
    size_t views = 0;
};

struct LodLesson {
    std::string meshName;
    size_t levels = 0;
    LodLessonLevel fine, coarse;  // level 0 and the coarser level
    // The cut from the same views: mean triangles drawn, levels used, efficiency.
    double cutMeanTriangles = 0.0, cutEfficiency = 0.0;
    std::vector<size_t> cutLevels;
    LodThreshold threshold;
    std::vector<LessonStep> steps;  // kLodLessonStepCount of them
};

constexpr int kLodLessonStepCount = 4;

// The level the lesson sets beside level 0: the coarsest with at least `minClusters` clusters (so that
// its means mean something), else level 1. Throws std::invalid_argument for fewer than two levels.
size_t lodLessonCoarseLevel(const LodStatistics& statistics, size_t minClusters = 8);

// The numbers of one level, from its statistics.
LodLessonLevel lodLessonLevel(const LodLevelStatistics& level);

// The lesson on `statistics` (of the mesh named `meshName`) comparing level 0 with `coarseLevel`.
// Throws std::invalid_argument when the level does not exist or is level 0.
LodLesson makeLodLesson(const LodStatistics& statistics, const std::string& meshName, size_t coarseLevel);
LodLesson makeLodLesson(const LodStatistics& statistics, const std::string& meshName);

}  // namespace conescope
