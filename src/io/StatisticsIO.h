// Statistics files: a RunStatistics as JSON (one nested document) or as CSV (three flat tables in
// one file). The CLI and the GUI's export both write through here, so the same settings give the
// same file. Key and column names are plain snake_case and stable; docs/statistics-schema.md lists
// every one of them.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "core/MeshChecks.h"
#include "core/Statistics.h"

namespace conescope {

// The version string written as "conescope_version".
const char* conescopeVersion();

// Which of the large per-view and per-cluster tables go into a file. Leaving one out drops its
// key ("views" / "clusters" of each result) from the JSON and its section from the CSV.
struct StatisticsDetail {
    bool views = true;
    bool clusters = true;
};

// The MeshReport keys: open_edges, non_manifold_edges, inconsistent_edges, duplicate_faces,
// degenerate_faces, components, orientable.
nlohmann::json meshReportToJson(const MeshReport& report);

// The settings a run was made with, as written under "settings".
nlohmann::json settingsToJson(const Settings& settings);

nlohmann::json statisticsToJson(const RunStatistics& run, const StatisticsDetail& detail = {});

// Pretty-printed JSON followed by a newline.
void writeStatisticsJson(const RunStatistics& run, std::ostream& out, const StatisticsDetail& detail = {});

// "# section: totals", "# section: views", "# section: clusters", each followed by a header row and
// its rows; the totals rows end with the run's mesh report and winding_fixed_faces. Numbers use the
// shortest text that reads back to the same value, whatever the locale.
void writeStatisticsCsv(const RunStatistics& run, std::ostream& out, const StatisticsDetail& detail = {});

// A worst-cluster table: the given clusters of one result, in that order, with the keys of the
// per-cluster statistics (an array of objects; a CSV header row and one row each).
nlohmann::json clusterRowsToJson(const TestStatistics& result, const std::vector<uint32_t>& order);
void writeClusterRowsCsv(const TestStatistics& result, const std::vector<uint32_t>& order, std::ostream& out);

}  // namespace conescope
