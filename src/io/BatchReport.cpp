#include "io/BatchReport.h"

#include <nlohmann/json.hpp>

#include "core/SettingsSchema.h"

namespace conescope {

namespace {

// What the page shows of each row; the rest is in results.csv and the JSON files. The page reads
// each by name: a column it reads and this list leaves out would be empty on every row.
const std::vector<std::string>& reportColumns() {
    static const std::vector<std::string> columns = [] {
        std::vector<std::string> shown = {
            "file", "status", "error", "error_kind", "json", "compare_json", "cone", "test", "triangles", "clusters", "efficiency",
            "back_facing_triangles", "triangles_culled", "test_loss_triangles", "partition_loss_triangles", "false_culls",
            "cull_fraction", "oracle_fraction", "mean_sphere_radius", "seconds", "warnings", "a_clusters", "a_efficiency",
            "triangles_culled_only_a", "triangles_culled_only_b", "uncullable_clusters", "uncullable_share", "note",
            "bytes_per_cluster", "culled_share"};
        // batch --granularity's finer records and --lod's levels, for their plots.
        for (const std::string& column : batchColumns())
            if (column.rfind("cones_", 0) == 0 || column.rfind("triangle_", 0) == 0 || column.rfind("lod_", 0) == 0) shown.push_back(column);
        return shown;
    }();
    return columns;
}

// JSON inside a <script> element: no "<" may end it early, so every "<" is written as \u003c (it
// occurs only inside strings).
std::string scriptSafe(const std::string& json) {
    std::string text;
    text.reserve(json.size());
    for (char c : json) text += c == '<' ? std::string("\\u003c") : std::string(1, c);
    return text;
}

nlohmann::json reportData(const std::vector<BatchRow>& rows, const BatchReportInfo& info) {
    nlohmann::json table = nlohmann::json::array();
    for (const BatchRow& row : rows) {
        nlohmann::json cells = nlohmann::json::array();
        for (const std::string& column : reportColumns()) {
            const auto cell = row.find(column);
            cells.push_back(cell == row.end() ? std::string() : cell->second);
        }
        table.push_back(std::move(cells));
    }
    nlohmann::json settings = nlohmann::json::object();
    if (!rows.empty())
        for (const SettingField& field : settingFields()) {
            const auto cell = rows.front().find("setting_" + field.key);
            if (cell != rows.front().end()) settings[field.flag] = cell->second;
        }
    return {{"title", info.title}, {"meshes", info.meshes}, {"compare", info.compare},
            {"settings", settings}, {"columns", reportColumns()}, {"rows", table}};
}

}  // namespace

std::string batchReportHtml(const std::vector<BatchRow>& rows, const BatchReportInfo& info) {
    const std::string data =
        scriptSafe(reportData(rows, info).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    std::string page = batchReportPage();
    page.replace(page.find("@DATA@"), 6, data);
    return page;
}

}  // namespace conescope
