// A cluster LOD hierarchy's statistics as files: JSON with `levels` and `cut`, one CSV row per level
// and one for the cut, or a short text. `conescope-cli lod` writes through here; the keys are in
// docs/statistics-schema.md ("LOD hierarchy").
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "core/lod/LodCut.h"

namespace conescope {

// {"settings", "threshold", "build_seconds", "views", "levels": [...], "cut": {...}}; `perView` adds
// the cut of every view under cut.views.
nlohmann::json lodStatisticsToJson(const LodStatistics& statistics, const Settings& settings, bool perView = true);

// level,clusters,triangles,groups,efficiency,expected_efficiency,false_culls,... with a last row
// whose level is "cut".
void writeLodCsv(const LodStatistics& statistics, std::ostream& out);

void writeLodText(const LodStatistics& statistics, const Settings& settings, std::ostream& out);

}  // namespace conescope
