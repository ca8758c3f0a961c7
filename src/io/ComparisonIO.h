// A/B comparisons as files: JSON with `a` and `b` exactly as `stats` writes each configuration and a
// `diff` object, a tidy per-view CSV table, or a short text for people. `conescope-cli compare`
// writes through here; docs/statistics-schema.md lists the keys.
#pragma once

#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/Comparison.h"
#include "io/StatisticsIO.h"

namespace conescope {

// The `diff` object: totals over the views, the cluster counts and their warning, and per view.
nlohmann::json comparisonToJson(const Comparison& comparison);

// {"a": statisticsToJson(a), "b": statisticsToJson(b), "diff": comparisonToJson(comparison)},
// pretty-printed as dump(2) would and followed by a newline; each side written as it is made
// (writeStatistics), so neither becomes a tree.
void writeComparisonJson(const RunStatistics& a, const RunStatistics& b, const Comparison& comparison,
                         const StatisticsDetail& detail, std::ostream& out);

// One row per view: view,eye_x,eye_y,eye_z,back_facing_triangles,triangles_culled_only_a,
// triangles_culled_only_b,triangles_culled_both,efficiency_a,efficiency_b.
void writeComparisonCsv(const Comparison& comparison, std::ostream& out);

// Each side's configuration where it differs from `base`, clusters, efficiency, what only each side
// culls and the cluster-count warning.
void writeComparisonText(const RunStatistics& a, const RunStatistics& b, const Comparison& comparison, const Settings& base,
                         std::ostream& out);

}  // namespace conescope
