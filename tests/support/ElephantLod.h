// The elephant's cluster LOD statistics over an orbit, as `conescope-cli lod elephant.off --views N`
// gives them: what the chart and widget tests plot. Header only, since the support library links
// neither the core nor the readers its users link.
#pragma once

#include <cstddef>
#include <string>

#include "core/lod/LodCut.h"
#include "io/MeshReader.h"

namespace conescope::testing {

inline LodStatistics elephantLod(size_t views) {
    Settings settings;
    settings.views = views;
    return lodOfMesh(readMesh(std::string(CONESCOPE_DATASETS_DIR) + "/elephant.off"), "elephant.off", settings, LodThreshold{});
}

}  // namespace conescope::testing
