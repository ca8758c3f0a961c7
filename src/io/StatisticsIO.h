// Statistics files: a RunStatistics as JSON (one nested document) or as CSV (three tidy tables, one
// per file, each with one header row: pandas.read_csv and spreadsheets read them as they are). The CLI and the GUI's export both write through here, so the same settings give the
// same file. Key and column names are plain snake_case and stable; docs/statistics-schema.md lists
// every one of them.
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/MeshChecks.h"
#include "core/Statistics.h"

namespace conescope {

class JsonWriter;

// A number as every CSV here writes it: the shortest text that reads back to the same value, with
// '.' whatever the locale.
std::string csvNumber(double value);

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

// The document as a tree, for callers that nest or query it. The trees here are read back from the
// text the writer below makes (JsonWriter.h), so each document has one layout in one place.
nlohmann::json statisticsToJson(const RunStatistics& run, const StatisticsDetail& detail = {});

// The document into a writer, for documents that hold it (compare's "a" and "b").
void writeStatistics(JsonWriter& json, const RunStatistics& run, const StatisticsDetail& detail = {});

// Pretty-printed JSON followed by a newline, written as it is made: the same text as
// statisticsToJson(run, detail).dump(2) without building the tree.
void writeStatisticsJson(const RunStatistics& run, std::ostream& out, const StatisticsDetail& detail = {});
// The same text, in a string sized for it at the start (no copies as it grows; the CLI writes it
// out as it is).
std::string statisticsJsonText(const RunStatistics& run, const StatisticsDetail& detail = {});

// The CSV tables: one row per (cone, test); per view of each; per cluster of each. Every row starts
// with cone,test so the tables join on them.
enum class CsvTable { Totals, Views, Clusters };
std::string toString(CsvTable table);  // "totals", "views", "clusters"
CsvTable parseCsvTable(const std::string& name);  // throws std::invalid_argument

// One table: a header row and its rows; the totals rows carry the run's mesh report and
// winding_fixed_faces. Numbers use the shortest text that reads back to the same value, whatever
// the locale.
void writeStatisticsCsv(const RunStatistics& run, std::ostream& out, CsvTable table);

// Where each table of a CSV export goes: the totals at `path` itself, the others beside it as
// NAME.views.csv and NAME.clusters.csv (path NAME.csv), those the detail keeps.
std::vector<std::pair<CsvTable, std::string>> csvTableFiles(const std::string& path, const StatisticsDetail& detail = {});

// A worst-cluster table: the given clusters of one result, in that order, with the keys of the
// per-cluster statistics (an array of objects; a CSV header row and one row each).
nlohmann::json clusterRowsToJson(const CullTestStatistics& result, const std::vector<uint32_t>& order);
void writeClusterRowsCsv(const CullTestStatistics& result, const std::vector<uint32_t>& order, std::ostream& out);

}  // namespace conescope
