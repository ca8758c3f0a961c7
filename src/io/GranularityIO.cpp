#include "io/GranularityIO.h"

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "io/ColumnTable.h"
#include "io/StatisticsIO.h"

namespace conescope {

namespace {

const std::vector<NamedColumn<GranularityRow>>& rowColumns() {
    static const std::vector<NamedColumn<GranularityRow>> columns{
        {"record", [](const GranularityRow& r) { return r.record; }},
        {"bytes_per_cluster", [](const GranularityRow& r) { return r.bytesPerCluster; }},
        {"bits_per_triangle", [](const GranularityRow& r) { return r.bitsPerTriangle; }},
        {"efficiency", [](const GranularityRow& r) { return r.efficiency; }},
        {"culled_share", [](const GranularityRow& r) { return r.culledShare; }},
        {"tests_per_view", [](const GranularityRow& r) { return r.testsPerView; }},
        {"false_culls", [](const GranularityRow& r) { return r.falseCulls; }},
        {"triangles_culled", [](const GranularityRow& r) { return r.trianglesCulled; }},
        {"back_facing_triangles", [](const GranularityRow& r) { return r.backFacingTriangles; }},
    };
    return columns;
}

}  // namespace

nlohmann::json granularityToJson(const GranularityReport& report) {
    const RunStatistics& run = report.run;
    nlohmann::json json{{"mesh", run.meshName},         {"settings", settingsToJson(run.settings)},
                        {"clusters", run.clusters},     {"triangles", run.triangles},
                        {"views", run.viewCount}};
    nlohmann::json& rows = json["rows"] = nlohmann::json::array();
    for (const GranularityRow& row : report.rows) rows.push_back(rowToJson(rowColumns(), row));
    return json;
}

void writeGranularityCsv(const GranularityReport& report, std::ostream& out) {
    writeCsvHeader(rowColumns(), out);
    for (const GranularityRow& row : report.rows) writeCsvRow(rowColumns(), row, out);
}

void writeGranularityText(const GranularityReport& report, std::ostream& out) {
    const RunStatistics& run = report.run;
    out << run.meshName << ": " << run.clusters << " clusters, " << run.triangles << " triangles, " << run.viewCount << " views\n";
    out << "record                     bytes/cluster  bits/triangle  efficiency  culled share  tests/view  false culls\n";
    for (const GranularityRow& row : report.rows)
        out << std::left << std::setw(27) << row.record << std::right << std::setw(13) << row.bytesPerCluster << std::fixed
            << std::setprecision(2) << std::setw(15) << row.bitsPerTriangle << std::setprecision(4) << std::setw(12) << row.efficiency
            << std::setw(14) << row.culledShare << std::setprecision(0) << std::setw(12) << row.testsPerView << std::setw(13)
            << row.falseCulls << "\n";
    out << "efficiency: culled / back-facing triangles; culled share: of all triangles; triangle: per-triangle culling after the "
        << toString(displayedCone(run.settings)) << "/" << toString(displayedTest(run.settings)) << " cluster test, the ceiling\n";
}

}  // namespace conescope
