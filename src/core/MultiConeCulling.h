// The K-cone record measured as `stats` and `lod` report it, and one cluster's sub-groups from one
// eye as the window shows them: counted here once, from MultiCones' tests.
#pragma once

#include <cstdint>
#include <vector>

#include "Culling.h"
#include "MultiCones.h"
#include "Progress.h"
#include "Statistics.h"

namespace conescope {

// The float record's bytes for this split: the offsets' width follows its largest cluster.
size_t multiConeBytesPerCluster(const MultiCones& multi);

// One view's counts (classifyFaces' `facing`), added to `total` with both efficiencies set.
void addMultiConeView(MultiConeCulling& total, const SubGroupRecord& record, const Mesh& mesh,
                      const std::vector<Facing>& facing, const Eye& eye);

// The record from every view; `progress` hears of every view and may cancel.
MultiConeCulling measureMultiCones(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                   const SubGroupRecord& record, const std::vector<Eye>& views,
                                   const ProgressCallback& progress = {});

// K cones per cluster for these bounds, measured over the views: what `stats` adds when K > 1.
MultiConeCulling measureMultiConeRun(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                     const ClusterBounds& bounds, uint32_t conesPerCluster, const std::vector<Eye>& views,
                                     const ProgressCallback& progress = {});

// One sub-group of one cluster from one eye: what the cluster report lists.
struct SubGroupVerdict {
    uint32_t group = 0;              // index into multi.cones
    size_t faces = 0, triangles = 0;
    double halfAngleDegrees = 90.0;  // 90 or more: no cone narrower than a hemisphere
    bool cullable = false;
    bool culled = false;             // cullSubGroups' verdict
    bool allBackFacing = false;      // every face back-facing from the eye (the oracle); false when empty
};

// Every sub-group of `cluster`, from `culled` (cullSubGroups for the eye) and `facing` (classifyFaces).
std::vector<SubGroupVerdict> subGroupVerdicts(const MultiCones& multi, uint32_t cluster, const std::vector<uint8_t>& culled,
                                              const std::vector<Facing>& facing);

// Each face's sub-group within its cluster (0 to K - 1), for `faceCount` faces.
std::vector<uint8_t> subGroupOfFace(const MultiCones& multi, size_t faceCount);

// From one eye: sub-groups culled, the triangles in them and the culled ones holding a face that is
// not back-facing (`culled` from cullSubGroups, `facing` from classifyFaces for the same eye).
struct SubGroupEyeCounts {
    size_t groups = 0, groupsCulled = 0, trianglesCulled = 0, falseCulls = 0;
};
SubGroupEyeCounts countCulledSubGroups(const MultiCones& multi, const std::vector<uint8_t>& culled, const std::vector<Facing>& facing);

}  // namespace conescope
