// A granularity report as files: JSON with the mesh, settings and `rows`, one CSV row per record,
// or a table of text. `conescope-cli granularity` writes through here; the keys are in
// docs/statistics-schema.md ("granularity output").
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "core/Granularity.h"

namespace conescope {

// {"mesh", "settings", "clusters", "triangles", "views", "rows": [{"record", "bytes_per_cluster", ...}]}
nlohmann::json granularityToJson(const GranularityReport& report);

// record,bytes_per_cluster,bits_per_triangle,efficiency,culled_share,tests_per_view,false_culls,...
void writeGranularityCsv(const GranularityReport& report, std::ostream& out);

void writeGranularityText(const GranularityReport& report, std::ostream& out);

}  // namespace conescope
