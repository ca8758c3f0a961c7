// What the session keeps of a cluster LOD hierarchy (Session's LOD part, SessionLod.cpp): the
// hierarchy of the shown snapshot, the threshold, what is shown of it (a level or the cut from the
// cull eye), its measurement from the eye and the scene of what is shown.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/lod/LodCut.h"
#include "core/lod/LodFamily.h"
#include "scene/ClusterScene.h"

namespace conescope {

// What the LOD view shows: nothing (the snapshot's partition), a level (0 and up) or the cut.
constexpr int kLodNone = -1;
constexpr int kLodCut = -2;

struct SessionLod {
    std::shared_ptr<const ClusterHierarchy> hierarchy;
    std::shared_ptr<const ClusterSet> madeFrom;  // the snapshot's level 0 it was built with
    LodThreshold threshold;
    int shown = kLodNone;
    // Each level and the cut from the cull eye, with the snapshot's settings (measureHierarchy).
    std::optional<LodStatistics> statistics;
    std::vector<std::vector<uint8_t>> cut;        // cutFrom the cull eye
    std::optional<LodLevel> cutLevel;             // the cut as one level (levelOfCut), while it is shown
    std::vector<LodClusterId> cutOrigin;
    std::unique_ptr<ClusterScene> scene;          // of the level or cut shown
    int sceneShows = kLodNone;                    // what the scene was made for
    std::optional<EyeMeasurement> measurement;    // of the level or cut shown, from the cull eye
    int picked = -1;                              // a cluster of the scene
};

}  // namespace conescope
