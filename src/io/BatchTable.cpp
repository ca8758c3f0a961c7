#include "io/BatchTable.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/SettingsSchema.h"
#include "io/ComparisonIO.h"
#include "io/StatisticsIO.h"

namespace conescope {

namespace {

// Columns the batch adds around the statistics: who, whether, where.
const std::vector<std::string> identityColumns = {"file", "status", "error", "error_kind", "json", "compare_json"};
const std::vector<std::string> meshColumns = {"vertices", "faces", "triangles", "warnings", "seconds", "content_hash",
                                              "settings_hash", "note"};
const std::vector<std::string> comparisonColumns = {"triangles_culled_only_a", "triangles_culled_only_b",
                                                    "triangles_culled_both", "cluster_count_warning"};

// The finer records of a granularity report, as column prefixes: cones_2, cones_2_compact, ... triangle.
const std::vector<std::string>& granularityRecords() {
    static const std::vector<std::string> records = [] {
        std::vector<std::string> names;
        for (uint32_t k : kGranularityCones)
            for (const char* form : {"", "_compact"}) names.push_back("cones_" + std::to_string(k) + form);
        names.push_back("triangle");
        return names;
    }();
    return records;
}
const std::vector<std::string> granularityKeys = {"efficiency", "culled_share", "bytes_per_cluster", "tests_per_view"};

std::string columnPrefix(std::string record) {
    std::replace(record.begin(), record.end(), '-', '_');
    return record;
}

// A number in a cell, read back to the same double.
std::string text(double value) {
    std::ostringstream out;
    out.precision(17);
    out << value;
    return out.str();
}

// The stats CSV's totals table of a run: its header and its rows, each split into cells.
std::vector<std::vector<std::string>> totalsTable(const RunStatistics& run) {
    std::ostringstream text;
    writeStatisticsCsv(run, text, CsvTable::Totals);
    std::vector<std::vector<std::string>> table;
    std::istringstream lines(text.str());
    for (std::string line; std::getline(lines, line);) table.push_back(splitCsvLine(line));
    return table;
}

const std::vector<std::string>& totalsColumns() {
    static const std::vector<std::string> columns = totalsTable(RunStatistics{}).front();
    return columns;
}

// Of A's totals, those that describe A's clusters and culling: not the views or the mesh check, which
// the mesh and the shared options fix for both sides.
bool describesSide(const std::string& column) {
    static const nlohmann::json report = meshReportToJson(MeshReport{});
    return column != "views" && column != "winding_fixed_faces" && !report.contains(column);
}

std::vector<std::string> makeColumns() {
    std::vector<std::string> columns = identityColumns;
    columns.insert(columns.end(), totalsColumns().begin(), totalsColumns().end());
    columns.insert(columns.end(), meshColumns.begin(), meshColumns.end());
    // A batch measures one cone per cluster (K cones are its granularity columns): no column for K.
    for (const SettingField& field : settingFields())
        if (!field.omittedAtDefault) columns.push_back("setting_" + field.key);
    columns.push_back("a_options");
    for (const std::string& column : totalsColumns())
        if (describesSide(column)) columns.push_back("a_" + column);
    columns.insert(columns.end(), comparisonColumns.begin(), comparisonColumns.end());
    columns.push_back("culled_share");
    for (const std::string& record : granularityRecords())
        for (const std::string& key : granularityKeys) columns.push_back(record + "_" + key);
    for (const char* column : {"lod_levels", "lod_false_culls", "lod_cut_triangles", "lod_cut_efficiency", "lod_cut_false_culls"})
        columns.push_back(column);
    for (size_t level = 0; level < kLodLevelColumns; ++level)
        for (const char* key : {"triangles", "efficiency"}) columns.push_back("lod_level_" + std::to_string(level) + "_" + key);
    return columns;
}

// Cells are one line each: results.csv is appended to a line at a time and read back by lines.
std::string oneLine(std::string text) {
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return text;
}

std::string quoted(const std::string& cell) {
    if (cell.find_first_of(",\"") == std::string::npos) return cell;
    std::string text = "\"";
    for (char c : cell) text += c == '"' ? std::string("\"\"") : std::string(1, c);
    return text + "\"";
}

std::string joined(const std::vector<std::string>& texts, const std::string& separator) {
    std::string text;
    for (const std::string& part : texts) text += (text.empty() ? "" : separator) + part;
    return text;
}

// The displayed result's totals row of a run, column by column, `prefix` before each name.
void addTotals(BatchRow& row, const RunStatistics& run, const std::string& prefix, bool sideOnly) {
    const std::vector<std::vector<std::string>> table = totalsTable(run);
    if (table.size() < 2) throw std::invalid_argument("a run without results has no batch row");
    for (size_t k = 0; k < table[0].size(); ++k)
        if (!sideOnly || describesSide(table[0][k])) row[prefix + table[0][k]] = table[1][k];
}

}  // namespace

const std::vector<std::string>& batchColumns() {
    static const std::vector<std::string> columns = makeColumns();
    return columns;
}

void addRunCells(BatchRow& row, const RunStatistics& run, const std::vector<std::string>& warnings) {
    addTotals(row, run, "", false);
    row["vertices"] = std::to_string(run.vertices);
    row["faces"] = std::to_string(run.faces);
    row["triangles"] = std::to_string(run.triangles);
    row["warnings"] = joined(warnings, " | ");
    // Why best gave balanced's partition, and why a mesh culls little or nothing when most of its
    // clusters never can.
    const CullTestStatistics& shown = run.results.front();
    std::vector<std::string> notes;
    for (std::string said : {bestEffortNote(run.bestEffort), uncullableNote(shown.uncullableClusters, shown.clusters.size())})
        if (!said.empty()) notes.push_back(std::move(said));
    row["note"] = joined(notes, " | ");
}

void addSettingCells(BatchRow& row, const Settings& settings) {
    for (const SettingField& field : settingFields())
        if (!field.omittedAtDefault) row["setting_" + field.key] = settingText(field, settings);
}

void addComparisonCells(BatchRow& row, const ComparedRuns& runs) {
    addTotals(row, runs.a, "a_", true);
    const nlohmann::json diff = comparisonToJson(runs.comparison);
    for (const std::string& column : comparisonColumns)
        row[column] = diff[column].is_null() ? "" : diff[column].is_string() ? diff[column].get<std::string>() : diff[column].dump();
}

void addGranularityCells(BatchRow& row, const GranularityReport& report) {
    row["culled_share"] = text(report.rows.front().culledShare);
    for (const GranularityRow& record : report.rows) {
        const std::string prefix = columnPrefix(record.record);
        if (std::find(granularityRecords().begin(), granularityRecords().end(), prefix) == granularityRecords().end()) continue;
        row[prefix + "_efficiency"] = text(record.efficiency);
        row[prefix + "_culled_share"] = text(record.culledShare);
        row[prefix + "_bytes_per_cluster"] = std::to_string(record.bytesPerCluster);
        row[prefix + "_tests_per_view"] = text(record.testsPerView);
    }
}

void addLodCells(BatchRow& row, const LodStatistics& lod) {
    size_t falseCulls = lod.cut.falseCulls;
    for (const LodLevelStatistics& level : lod.levels) {
        falseCulls += level.culling.falseCulls;
        if (level.level >= kLodLevelColumns) continue;
        const std::string prefix = "lod_level_" + std::to_string(level.level) + "_";
        row[prefix + "triangles"] = std::to_string(level.triangles);
        row[prefix + "efficiency"] = text(level.culling.efficiency);
    }
    row["lod_levels"] = std::to_string(lod.levels.size());
    row["lod_false_culls"] = std::to_string(falseCulls);
    row["lod_cut_triangles"] = text(lod.cut.meanTriangles);
    row["lod_cut_efficiency"] = text(lod.cut.efficiency);
    row["lod_cut_false_culls"] = std::to_string(lod.cut.falseCulls);
}

std::string batchCsvHeader() { return joined(batchColumns(), ",") + "\n"; }

std::string batchCsvLine(const BatchRow& row) {
    std::string line;
    for (size_t k = 0; k < batchColumns().size(); ++k) {
        const auto cell = row.find(batchColumns()[k]);
        if (k > 0) line += ',';
        if (cell != row.end()) line += quoted(oneLine(cell->second));
    }
    return line + "\n";
}

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells(1);
    bool inQuotes = false;
    for (size_t k = 0; k < line.size(); ++k) {
        const char c = line[k];
        if (inQuotes && c == '"' && k + 1 < line.size() && line[k + 1] == '"') {
            cells.back() += '"';
            ++k;
        } else if (c == '"') {
            inQuotes = !inQuotes;
        } else if (c == ',' && !inQuotes) {
            cells.emplace_back();
        } else {
            cells.back() += c;
        }
    }
    if (inQuotes) throw std::invalid_argument("a quote is not closed");
    return cells;
}

BatchTable readBatchCsv(const std::string& path) {
    BatchTable table;
    std::ifstream in(path, std::ios::binary);
    if (!in) return table;
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw std::runtime_error(path + ": cannot read");
    // Only lines that end in a newline were written whole.
    text.erase(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
    std::istringstream lines(text);
    std::string line;
    if (!std::getline(lines, line)) return table;
    const std::vector<std::string> header = splitCsvLine(line);
    table.sameColumns = header == batchColumns();
    if (!table.sameColumns) return table;
    while (std::getline(lines, line)) {
        std::vector<std::string> cells;
        try {
            cells = splitCsvLine(line);
        } catch (const std::invalid_argument&) {
        }
        if (cells.size() != header.size()) {
            ++table.unreadableRows;
            continue;
        }
        BatchRow row;
        for (size_t k = 0; k < cells.size(); ++k)
            if (!cells[k].empty()) row[header[k]] = cells[k];
        table.rows.push_back(std::move(row));
    }
    return table;
}

std::string batchCsvText(const std::vector<BatchRow>& rows) {
    std::string text = batchCsvHeader();
    for (const BatchRow& row : rows) text += batchCsvLine(row);
    return text;
}

}  // namespace conescope
