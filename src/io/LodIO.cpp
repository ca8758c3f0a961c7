#include "io/LodIO.h"

#include <functional>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/ColumnTable.h"
#include "io/MultiConeColumns.h"
#include "io/StatisticsIO.h"

namespace conescope {

// In the CSV only when K cones were measured; the JSON nests them under "multi_cone".
const std::vector<NamedColumn<MultiConeCulling>>& multiConeColumns() {
    using Column = NamedColumn<MultiConeCulling>;
    static const std::vector<Column> columns{
        {"cones_per_cluster", [](const MultiConeCulling& m) { return m.cones; }},
        {"efficiency", [](const MultiConeCulling& m) { return m.efficiency; }},
        {"false_culls", [](const MultiConeCulling& m) { return m.falseCulls; }},
        {"triangles_culled", [](const MultiConeCulling& m) { return m.trianglesCulled; }},
        {"back_facing_triangles", [](const MultiConeCulling& m) { return m.backFacingTriangles; }},
    };
    return columns;
}

namespace {

using LevelColumn = NamedColumn<LodLevelStatistics>;
const std::vector<LevelColumn>& levelColumns() {
    static const std::vector<LevelColumn> columns{
        {"level", [](const LodLevelStatistics& l) { return l.level; }},
        {"clusters", [](const LodLevelStatistics& l) { return l.clusters; }},
        {"triangles", [](const LodLevelStatistics& l) { return l.triangles; }},
        {"groups", [](const LodLevelStatistics& l) { return l.groups; }},
        {"efficiency", [](const LodLevelStatistics& l) { return l.culling.efficiency; }},
        {"expected_efficiency", [](const LodLevelStatistics& l) { return l.culling.expectedEfficiency; }},
        {"false_culls", [](const LodLevelStatistics& l) { return l.culling.falseCulls; }},
        {"triangles_culled", [](const LodLevelStatistics& l) { return l.culling.trianglesCulled; }},
        {"back_facing_triangles", [](const LodLevelStatistics& l) { return l.culling.backFacingTriangles; }},
        {"uncullable_clusters", [](const LodLevelStatistics& l) { return l.culling.uncullableClusters; }},
        {"mean_half_angle_deg", [](const LodLevelStatistics& l) { return l.meanHalfAngleDegrees; }},
        {"max_half_angle_deg", [](const LodLevelStatistics& l) { return l.maxHalfAngleDegrees; }},
        {"min_error", [](const LodLevelStatistics& l) { return l.minError; }},
        {"max_error", [](const LodLevelStatistics& l) { return l.maxError; }},
    };
    return columns;
}

// Adds "multi_cone" to a level's, the cut's or a view's object when K cones were measured.
void addMultiCone(nlohmann::json& json, const LodMultiConeCulling& multi) {
    if (multi.cones > 0) json["multi_cone"] = rowToJson(multiConeColumns(), multi);
}

// The CSV's columns: the level's, then with K cones measured "multi_cone_" and each K-cone key.
std::vector<LevelColumn> csvColumns(bool multi) {
    std::vector<LevelColumn> columns = levelColumns();
    if (!multi) return columns;
    static std::vector<std::string> keys;
    if (keys.empty())
        for (const auto& column : multiConeColumns()) keys.push_back(std::string("multi_cone_") + column.key);
    for (size_t i = 0; i < keys.size(); ++i)
        columns.push_back({keys[i].c_str(), [i](const LodLevelStatistics& l) { return multiConeColumns()[i].value(l.multiCones); }});
    return columns;
}

nlohmann::json thresholdToJson(const LodThreshold& threshold) {
    nlohmann::json json{{"value", threshold.value}, {"unit", threshold.worldUnits ? "world" : "pixels"}};
    if (!threshold.worldUnits) json["screen_height"] = threshold.screenHeight, json["fov_degrees"] = threshold.fovDegrees;
    return json;
}

nlohmann::json cutViewToJson(const LodCutView& view) {
    nlohmann::json json{{"view", view.view},
            {"eye", {view.eye.position.x, view.eye.position.y, view.eye.position.z}},
            {"clusters", view.clusters},
            {"triangles", view.triangles},
            {"clusters_culled", view.clustersCulled},
            {"triangles_culled", view.trianglesCulled},
            {"back_facing_triangles", view.backFacingTriangles},
            {"efficiency", view.efficiency},
            {"false_culls", view.falseCulls},
            {"clusters_per_level", view.clustersPerLevel}};
    addMultiCone(json, view.multiCones);
    return json;
}


}  // namespace

nlohmann::json lodStatisticsToJson(const LodStatistics& statistics, const Settings& settings, bool perView) {
    nlohmann::json json;
    json["settings"] = settingsToJson(settings);
    json["threshold"] = thresholdToJson(statistics.threshold);
    json["build_seconds"] = statistics.buildSeconds;
    json["views"] = statistics.cut.views.size();
    nlohmann::json& levels = json["levels"] = nlohmann::json::array();
    for (const LodLevelStatistics& level : statistics.levels) {
        levels.push_back(rowToJson(levelColumns(), level));
        addMultiCone(levels.back(), level.multiCones);
    }
    const LodCutStatistics& cut = statistics.cut;
    json["cut"] = {{"triangles", cut.meanTriangles},
                   {"clusters", cut.meanClusters},
                   {"triangles_culled", cut.trianglesCulled},
                   {"back_facing_triangles", cut.backFacingTriangles},
                   {"efficiency", cut.efficiency},
                   {"false_culls", cut.falseCulls},
                   {"levels_used", cut.levelsUsed}};
    addMultiCone(json["cut"], cut.multiCones);
    if (perView) {
        nlohmann::json& views = json["cut"]["views"] = nlohmann::json::array();
        for (const LodCutView& view : cut.views) views.push_back(cutViewToJson(view));
    }
    return json;
}

void writeLodCsv(const LodStatistics& statistics, std::ostream& out) {
    const std::vector<LevelColumn> columns = csvColumns(statistics.cut.multiCones.cones > 0);
    writeCsvHeader(columns, out);
    for (const LodLevelStatistics& level : statistics.levels) writeCsvRow(columns, level, out);
    // The cut: its mean size over the views, its culling summed over them; no groups, cones or errors.
    const LodCutStatistics& cut = statistics.cut;
    std::map<std::string, nlohmann::json> cells{{"level", "cut"},
                                                      {"clusters", cut.meanClusters},
                                                      {"triangles", cut.meanTriangles},
                                                      {"efficiency", cut.efficiency},
                                                      {"false_culls", cut.falseCulls},
                                                      {"triangles_culled", cut.trianglesCulled},
                                                      {"back_facing_triangles", cut.backFacingTriangles}};
    for (const auto& column : multiConeColumns()) cells[std::string("multi_cone_") + column.key] = column.value(cut.multiCones);
    for (size_t i = 0; i < columns.size(); ++i) {
        const auto at = cells.find(columns[i].key);
        out << (i ? "," : "") << (at == cells.end() ? "" : csvCell(at->second));
    }
    out << "\n";
}

void writeLodText(const LodStatistics& statistics, const Settings& settings, std::ostream& out) {
    out << "LOD hierarchy: " << statistics.levels.size() << " levels, built in " << std::fixed << std::setprecision(2)
        << statistics.buildSeconds << " s; " << toString(displayedCone(settings)) << " cone, " << toString(displayedTest(settings))
        << " test, " << statistics.cut.views.size() << " views\n";
    const uint32_t cones = statistics.cut.multiCones.cones;
    out << "level  clusters  triangles  mean alpha  efficiency  expected  false culls";
    if (cones > 0) out << "  " << cones << " cones  false culls";
    out << "\n";
    for (const LodLevelStatistics& level : statistics.levels) {
        // A level none of whose clusters can be culled has no cone width to average (its JSON reads 0).
        std::ostringstream alpha;
        if (level.culling.uncullableClusters == level.clusters)
            alpha << "none";
        else
            alpha << std::fixed << std::setprecision(1) << level.meanHalfAngleDegrees << "\u00b0";
        out << std::setw(5) << level.level << std::setw(10) << level.clusters << std::setw(11) << level.triangles
            << std::setw(alpha.str() == "none" ? 12 : 13) << alpha.str() << std::setw(11) << std::setprecision(4) << level.culling.efficiency
            << std::setw(10) << level.culling.expectedEfficiency << std::setw(13) << level.culling.falseCulls;
        if (cones > 0) out << std::setw(9 + (cones > 9)) << level.multiCones.efficiency << std::setw(13) << level.multiCones.falseCulls;
        out << "\n";
    }
    const LodCutStatistics& cut = statistics.cut;
    out << "cut at " << std::setprecision(2) << statistics.threshold.value << (statistics.threshold.worldUnits ? " world units" : " px")
        << ": " << std::setprecision(0) << cut.meanTriangles << " triangles and " << cut.meanClusters << " clusters drawn per view from levels";
    for (size_t level : cut.levelsUsed) out << " " << level;
    out << "; efficiency " << std::setprecision(4) << cut.efficiency << ", false culls " << cut.falseCulls;
    if (cones > 0) out << "; with " << cones << " cones " << cut.multiCones.efficiency << ", false culls " << cut.multiCones.falseCulls;
    out << "\n";
}

}  // namespace conescope
