#include "io/StatisticsIO.h"


#include "core/SettingsSchema.h"
#include "io/JsonWriter.h"
#include "io/MultiConeColumns.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#ifndef CONESCOPE_VERSION
#error "CONESCOPE_VERSION must be defined by the build"
#endif

namespace conescope {

const char* conescopeVersion() { return CONESCOPE_VERSION; }

// Shortest round-trip form from to_chars, which ignores the C locale (a decimal comma would break
// the table).
std::string csvNumber(double value) {
    std::array<char, 64> buffer{};
    const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
    return std::string(buffer.data(), end);
}

namespace {

// One scalar of a table row. The JSON object and the CSV row of a row type are both made from one
// list of named cells, so a key cannot exist in one format and be missing from the other.
using Cell = std::variant<size_t, double, bool>;

template <typename Row>
struct Column {
    const char* name;
    Cell (*value)(const Row&);
};

// Totals of one (cone, test); the run-wide cluster and view counts are columns of the CSV only.
const std::vector<Column<CullTestStatistics>>& totalColumns() {
    static const std::vector<Column<CullTestStatistics>> columns = {
        {"clusters_culled", [](const CullTestStatistics& r) -> Cell { return r.clustersCulled; }},
        {"triangles_culled", [](const CullTestStatistics& r) -> Cell { return r.trianglesCulled; }},
        {"back_facing_triangles", [](const CullTestStatistics& r) -> Cell { return r.backFacingTriangles; }},
        {"missed_clusters", [](const CullTestStatistics& r) -> Cell { return r.missedClusters; }},
        {"false_culls", [](const CullTestStatistics& r) -> Cell { return r.falseCulls; }},
        {"efficiency", [](const CullTestStatistics& r) -> Cell { return r.efficiency; }},
        {"expected_efficiency", [](const CullTestStatistics& r) -> Cell { return r.expectedEfficiency; }},
        {"uncullable_clusters", [](const CullTestStatistics& r) -> Cell { return r.uncullableClusters; }},
        {"ns_per_cluster", [](const CullTestStatistics& r) -> Cell { return r.nanosecondsPerCluster; }},
    };
    return columns;
}

// Totals added later: the loss breakdown and the partition summary. The CSV writes them after the
// mesh report, so older columns keep their positions.
const std::vector<Column<CullTestStatistics>>& laterTotalColumns() {
    static const std::vector<Column<CullTestStatistics>> columns = {
        {"test_loss_triangles", [](const CullTestStatistics& r) -> Cell { return r.testLossTriangles; }},
        {"partition_loss_triangles", [](const CullTestStatistics& r) -> Cell { return r.partitionLossTriangles; }},
        {"mean_view_efficiency", [](const CullTestStatistics& r) -> Cell { return r.meanViewEfficiency; }},
        {"mean_cluster_triangles", [](const CullTestStatistics& r) -> Cell { return r.meanClusterTriangles; }},
        {"mean_cluster_vertices", [](const CullTestStatistics& r) -> Cell { return r.meanClusterVertices; }},
        {"mean_sphere_radius", [](const CullTestStatistics& r) -> Cell { return r.meanSphereRadius; }},
        {"max_sphere_radius", [](const CullTestStatistics& r) -> Cell { return r.maxSphereRadius; }},
        {"cull_fraction", [](const CullTestStatistics& r) -> Cell { return r.cullFraction; }},
        {"oracle_fraction", [](const CullTestStatistics& r) -> Cell { return r.oracleFraction; }},
        {"bytes_per_cluster", [](const CullTestStatistics& r) -> Cell { return r.bytesPerCluster; }},
        {"engine_record", [](const CullTestStatistics& r) -> Cell { return r.engineRecord; }},
        {"quantisation_loss_triangles", [](const CullTestStatistics& r) -> Cell { return r.quantisationLossTriangles; }},
        {"uncullable_share", [](const CullTestStatistics& r) -> Cell { return uncullableShare(r.uncullableClusters, r.clusters.size()); }},
    };
    return columns;
}

// Per view, after "view" and the eye; the eye is an array in JSON and three columns in CSV.
const std::vector<Column<ViewStatistics>>& viewColumns() {
    static const std::vector<Column<ViewStatistics>> columns = {
        {"orthographic", [](const ViewStatistics& v) -> Cell { return v.eye.orthographic; }},
        {"clusters_culled", [](const ViewStatistics& v) -> Cell { return v.clustersCulled; }},
        {"triangles_culled", [](const ViewStatistics& v) -> Cell { return v.trianglesCulled; }},
        {"back_facing_triangles", [](const ViewStatistics& v) -> Cell { return v.backFacingTriangles; }},
        {"front_facing_triangles", [](const ViewStatistics& v) -> Cell { return v.frontFacingTriangles; }},
        {"back_facing_clusters", [](const ViewStatistics& v) -> Cell { return v.backFacingClusters; }},
        {"missed_clusters", [](const ViewStatistics& v) -> Cell { return v.missedClusters; }},
        {"false_culls", [](const ViewStatistics& v) -> Cell { return v.falseCulls; }},
        {"efficiency", [](const ViewStatistics& v) -> Cell { return v.efficiency; }},
        {"ns_per_cluster", [](const ViewStatistics& v) -> Cell { return v.nanosecondsPerCluster; }},
        {"test_loss_triangles", [](const ViewStatistics& v) -> Cell { return v.testLossTriangles; }},
        {"partition_loss_triangles", [](const ViewStatistics& v) -> Cell { return v.partitionLossTriangles; }},
        {"quantisation_loss_triangles", [](const ViewStatistics& v) -> Cell { return v.quantisationLossTriangles; }},
    };
    return columns;
}

const std::vector<Column<ClusterStatistics>>& clusterColumns() {
    static const std::vector<Column<ClusterStatistics>> columns = {
        {"cluster", [](const ClusterStatistics& c) -> Cell { return size_t(c.cluster); }},
        {"faces", [](const ClusterStatistics& c) -> Cell { return c.faces; }},
        {"triangles", [](const ClusterStatistics& c) -> Cell { return c.triangles; }},
        {"vertices", [](const ClusterStatistics& c) -> Cell { return c.vertices; }},
        {"half_angle_deg", [](const ClusterStatistics& c) -> Cell { return c.halfAngleDegrees; }},
        {"cullable", [](const ClusterStatistics& c) -> Cell { return c.cullable; }},
        {"times_culled", [](const ClusterStatistics& c) -> Cell { return c.timesCulled; }},
        {"times_back_facing", [](const ClusterStatistics& c) -> Cell { return c.timesBackFacing; }},
        {"false_culls", [](const ClusterStatistics& c) -> Cell { return c.falseCulls; }},
        {"times_missed", [](const ClusterStatistics& c) -> Cell { return c.timesMissed; }},
        {"test_loss_triangles", [](const ClusterStatistics& c) -> Cell { return c.testLossTriangles; }},
        {"partition_loss_triangles", [](const ClusterStatistics& c) -> Cell { return c.partitionLossTriangles; }},
        {"sphere_radius", [](const ClusterStatistics& c) -> Cell { return c.sphereRadius; }},
        {"cull_fraction", [](const ClusterStatistics& c) -> Cell { return c.cullFraction; }},
        {"oracle_fraction", [](const ClusterStatistics& c) -> Cell { return c.oracleFraction; }},
        {"quantisation_loss_triangles", [](const ClusterStatistics& c) -> Cell { return c.quantisationLossTriangles; }},
    };
    return columns;
}

// The mesh check before culling: mesh.report in JSON, and columns of every CSV totals row, where
// (like clusters and views) they repeat the run's values so each row stands alone.
const std::vector<Column<MeshReport>>& reportColumns() {
    static const std::vector<Column<MeshReport>> columns = {
        {"open_edges", [](const MeshReport& m) -> Cell { return m.openEdges; }},
        {"non_manifold_edges", [](const MeshReport& m) -> Cell { return m.nonManifoldEdges; }},
        {"inconsistent_edges", [](const MeshReport& m) -> Cell { return m.inconsistentEdges; }},
        {"duplicate_faces", [](const MeshReport& m) -> Cell { return m.duplicateFaces; }},
        {"double_sided_faces", [](const MeshReport& m) -> Cell { return m.doubleSidedFaces; }},
        {"degenerate_faces", [](const MeshReport& m) -> Cell { return m.degenerateFaces; }},
        {"components", [](const MeshReport& m) -> Cell { return m.components; }},
        {"orientable", [](const MeshReport& m) -> Cell { return m.orientable; }},
    };
    return columns;
}

void writeCell(JsonWriter& json, const Cell& cell) {
    std::visit([&json](auto value) { json.value(value); }, cell);
}

// The members of one object, written in key order whatever order they were added in.
class Members {
public:
    using Write = std::function<void(JsonWriter&)>;
    void add(std::string_view key, Write write) { members_.emplace_back(key, std::move(write)); }
    template <typename Row>
    void addColumns(const std::vector<Column<Row>>& columns, const Row& row) {
        for (const Column<Row>& column : columns)
            add(column.name, [&column, &row](JsonWriter& json) { writeCell(json, column.value(row)); });
    }
    void write(JsonWriter& json) {
        std::sort(members_.begin(), members_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        json.beginObject();
        for (const auto& [key, write] : members_) {
            json.key(key);
            write(json);
        }
        json.endObject();
    }

private:
    std::vector<std::pair<std::string_view, Write>> members_;
};

// A table's columns in key order, for rows written many times over.
template <typename Row>
std::vector<const Column<Row>*> inKeyOrder(const std::vector<Column<Row>>& columns) {
    std::vector<const Column<Row>*> sorted;
    for (const Column<Row>& column : columns) sorted.push_back(&column);
    std::sort(sorted.begin(), sorted.end(), [](const auto* a, const auto* b) { return std::string_view(a->name) < b->name; });
    return sorted;
}

void writeVector(JsonWriter& json, const glm::dvec3& v) {
    json.beginArray();
    for (int k = 0; k < 3; ++k) json.value(v[k]);
    json.endArray();
}

// The per-cluster rows of `order` (every cluster when null), each an object of the cluster columns.
void writeClusterRows(JsonWriter& json, const CullTestStatistics& result, const std::vector<uint32_t>* order) {
    const std::vector<const Column<ClusterStatistics>*> columns = inKeyOrder(clusterColumns());
    const auto writeRow = [&](const ClusterStatistics& cluster) {
        json.beginObject();
        for (const Column<ClusterStatistics>* column : columns) {
            json.key(column->name);
            writeCell(json, column->value(cluster));
        }
        json.endObject();
    };
    json.beginArray();
    if (order)
        for (uint32_t c : *order) writeRow(result.clusters.at(c));
    else
        for (const ClusterStatistics& cluster : result.clusters) writeRow(cluster);
    json.endArray();
}

void writeView(JsonWriter& json, const ViewStatistics& view) {
    Members members;
    members.add("view", [&view](JsonWriter& j) { j.value(view.view); });
    members.add("eye", [&view](JsonWriter& j) { writeVector(j, view.eye.position); });
    members.add("direction", [&view](JsonWriter& j) { writeVector(j, view.eye.direction); });
    members.addColumns(viewColumns(), view);
    members.write(json);
}

void writeResult(JsonWriter& json, const CullTestStatistics& result, const StatisticsDetail& detail) {
    Members members;
    members.add("cone", [&result](JsonWriter& j) { j.value(nlohmann::json(toString(result.cone))); });
    members.add("test", [&result](JsonWriter& j) { j.value(nlohmann::json(toString(result.test))); });
    members.addColumns(totalColumns(), result);
    members.addColumns(laterTotalColumns(), result);
    if (detail.views)
        members.add("views", [&result](JsonWriter& j) {
            j.beginArray();
            for (const ViewStatistics& view : result.views) writeView(j, view);
            j.endArray();
        });
    if (detail.clusters) members.add("clusters", [&result](JsonWriter& j) { writeClusterRows(j, result, nullptr); });
    members.write(json);
}

// A schema value as JSON; an unset point and an empty path are null.
nlohmann::json settingToJson(const SettingField& field, const SettingValue& value) {
    if (const auto* point = std::get_if<std::optional<glm::dvec3>>(&value))
        return *point ? nlohmann::json::array({(**point).x, (**point).y, (**point).z}) : nlohmann::json(nullptr);
    if (const auto* text = std::get_if<std::string>(&value))
        return field.kind == SettingKind::Path && text->empty() ? nlohmann::json(nullptr) : nlohmann::json(*text);
    if (const auto* names = std::get_if<std::vector<std::string>>(&value)) return nlohmann::json(*names);
    if (const size_t* count = std::get_if<size_t>(&value)) return nlohmann::json(*count);
    if (const double* number = std::get_if<double>(&value)) return nlohmann::json(*number);
    return nlohmann::json(std::get<bool>(value));
}

void writeMeshReport(JsonWriter& json, const MeshReport& report) {
    Members members;
    members.addColumns(reportColumns(), report);
    // Added after the others; the CSV writes it last so columns keep their positions.
    members.add("inside_out_components", [&report](JsonWriter& j) { j.value(report.insideOutComponents); });
    members.write(json);
}

// The K-cone record's object: lod's keys and the record's bytes per cluster.
nlohmann::json multiConeJson(const MultiConeCulling& multi) {
    nlohmann::json json = rowToJson(multiConeColumns(), multi);
    json["bytes_per_cluster"] = multi.bytesPerCluster;
    return json;
}

// Which of --effort best's two searches made the partition, and what each made.
nlohmann::json bestEffortJson(const BestEffortChoice& choice) {
    return {{"kept", choice.keptBalanced ? "balanced" : "best"},
            {"own_clusters", choice.ownClusters},
            {"own_efficiency", choice.ownEfficiency},
            {"balanced_clusters", choice.balancedClusters},
            {"balanced_efficiency", choice.balancedEfficiency},
            {"own_expected_efficiency", choice.ownExpected},
            {"balanced_expected_efficiency", choice.balancedExpected}};
}

void writeSettings(JsonWriter& json, const Settings& settings) {
    Members members;
    for (const SettingField& field : settingFields()) {
        if (field.omittedAtDefault && settingText(field, settings) == settingText(field, Settings{})) continue;
        members.add(field.key, [&field, &settings](JsonWriter& j) { j.value(settingToJson(field, field.value(settings))); });
    }
    members.write(json);
}

}  // namespace

void writeStatistics(JsonWriter& json, const RunStatistics& run, const StatisticsDetail& detail) {
    Members mesh;
    mesh.add("name", [&run](JsonWriter& j) { j.value(nlohmann::json(run.meshName)); });
    mesh.add("vertices", [&run](JsonWriter& j) { j.value(run.vertices); });
    mesh.add("faces", [&run](JsonWriter& j) { j.value(run.faces); });
    mesh.add("triangles", [&run](JsonWriter& j) { j.value(run.triangles); });
    mesh.add("degenerate_faces", [&run](JsonWriter& j) { j.value(run.degenerateFaces); });
    mesh.add("report", [&run](JsonWriter& j) { writeMeshReport(j, run.meshReport); });
    mesh.add("winding_fixed_faces", [&run](JsonWriter& j) { j.value(run.windingFixedFaces); });
    Members top;
    top.add("conescope_version", [](JsonWriter& j) { j.value(nlohmann::json(conescopeVersion())); });
    top.add("mesh", [&mesh](JsonWriter& j) { mesh.write(j); });
    top.add("settings", [&run](JsonWriter& j) { writeSettings(j, run.settings); });
    top.add("clusters", [&run](JsonWriter& j) { j.value(run.clusters); });
    top.add("view_count", [&run](JsonWriter& j) { j.value(run.viewCount); });
    top.add("results", [&run, &detail](JsonWriter& j) {
        j.beginArray();
        for (const CullTestStatistics& result : run.results) writeResult(j, result, detail);
        j.endArray();
    });
    if (run.multiCones.cones > 0) top.add("multi_cone", [&run](JsonWriter& j) { j.value(multiConeJson(run.multiCones)); });
    if (run.bestEffort.ran) top.add("best_effort", [&run](JsonWriter& j) { j.value(bestEffortJson(run.bestEffort)); });
    top.write(json);
}

namespace {

// The tree of what `write` writes: the one layout of each document is the writer's.
template <typename Write>
nlohmann::json treeOf(Write write) {
    std::string text;
    JsonWriter json(text);
    write(json);
    return nlohmann::json::parse(text);
}

std::string csvCell(const Cell& cell) {
    if (const size_t* count = std::get_if<size_t>(&cell)) return std::to_string(*count);
    if (const bool* flag = std::get_if<bool>(&cell)) return *flag ? "1" : "0";
    return csvNumber(std::get<double>(cell));
}

template <typename Row>
void writeHeader(std::ostream& out, const std::vector<Column<Row>>& columns) {
    for (const Column<Row>& column : columns) out << ',' << column.name;
}

template <typename Row>
void writeCells(std::ostream& out, const std::vector<Column<Row>>& columns, const Row& row) {
    for (const Column<Row>& column : columns) out << ',' << csvCell(column.value(row));
}

}  // namespace

nlohmann::json clusterRowsToJson(const CullTestStatistics& result, const std::vector<uint32_t>& order) {
    return treeOf([&](JsonWriter& json) { writeClusterRows(json, result, &order); });
}

void writeClusterRowsCsv(const CullTestStatistics& result, const std::vector<uint32_t>& order, std::ostream& out) {
    out << "cone,test";
    writeHeader(out, clusterColumns());
    out << '\n';
    for (uint32_t c : order) {
        out << toString(result.cone) << ',' << toString(result.test);
        writeCells(out, clusterColumns(), result.clusters.at(c));
        out << '\n';
    }
}

nlohmann::json meshReportToJson(const MeshReport& report) {
    return treeOf([&](JsonWriter& json) { writeMeshReport(json, report); });
}

nlohmann::json settingsToJson(const Settings& settings) {
    return treeOf([&](JsonWriter& json) { writeSettings(json, settings); });
}

nlohmann::json statisticsToJson(const RunStatistics& run, const StatisticsDetail& detail) {
    return treeOf([&](JsonWriter& json) { writeStatistics(json, run, detail); });
}

// Written as it is made: no tree of the whole document (JsonWriter.h). Reserved from the rows it
// will hold (a cluster row takes about 550 bytes, a view row about 450), so that growing it does
// not copy it again and again: on 1.2M triangles the report holds 13,401 cluster rows.
std::string statisticsJsonText(const RunStatistics& run, const StatisticsDetail& detail) {
    size_t rows = 0;
    for (const CullTestStatistics& result : run.results)
        rows += (detail.clusters ? result.clusters.size() : 0) + (detail.views ? result.views.size() : 0);
    std::string text;
    text.reserve(4096 + 640 * rows);
    JsonWriter json(text);
    writeStatistics(json, run, detail);
    text += '\n';
    return text;
}

void writeStatisticsJson(const RunStatistics& run, std::ostream& out, const StatisticsDetail& detail) {
    out << statisticsJsonText(run, detail);
}

std::string toString(CsvTable table) {
    switch (table) {
    case CsvTable::Totals: return "totals";
    case CsvTable::Views: return "views";
    case CsvTable::Clusters: return "clusters";
    }
    return "totals";
}

CsvTable parseCsvTable(const std::string& name) {
    for (CsvTable table : {CsvTable::Totals, CsvTable::Views, CsvTable::Clusters})
        if (toString(table) == name) return table;
    throw std::invalid_argument("unknown table '" + name + "' (expected totals, views or clusters)");
}

void writeStatisticsCsv(const RunStatistics& run, std::ostream& out, CsvTable table) {
    if (table == CsvTable::Totals) {
        out << "cone,test,clusters,views";
        writeHeader(out, totalColumns());
        writeHeader(out, reportColumns());
        out << ",winding_fixed_faces,inside_out_components";
        writeHeader(out, laterTotalColumns());
        const nlohmann::json multi = run.multiCones.cones > 0 ? multiConeJson(run.multiCones) : nlohmann::json::object();
        for (const auto& [key, value] : multi.items()) out << ",multi_cone_" << key;
        out << '\n';
        for (const CullTestStatistics& result : run.results) {
            out << toString(result.cone) << ',' << toString(result.test) << ',' << run.clusters << ',' << run.viewCount;
            writeCells(out, totalColumns(), result);
            writeCells(out, reportColumns(), run.meshReport);
            out << ',' << run.windingFixedFaces << ',' << run.meshReport.insideOutComponents;
            writeCells(out, laterTotalColumns(), result);
            for (const auto& [key, value] : multi.items()) out << ',' << (value.is_number_float() ? csvNumber(value.get<double>()) : value.dump());
            out << '\n';
        }
    } else if (table == CsvTable::Views) {
        out << "cone,test,view,eye_x,eye_y,eye_z,direction_x,direction_y,direction_z";
        writeHeader(out, viewColumns());
        out << '\n';
        for (const CullTestStatistics& result : run.results)
            for (const ViewStatistics& view : result.views) {
                out << toString(result.cone) << ',' << toString(result.test) << ',' << view.view;
                for (int k = 0; k < 3; ++k) out << ',' << csvNumber(view.eye.position[k]);
                for (int k = 0; k < 3; ++k) out << ',' << csvNumber(view.eye.direction[k]);
                writeCells(out, viewColumns(), view);
                out << '\n';
            }
    } else {
        out << "cone,test";
        writeHeader(out, clusterColumns());
        out << '\n';
        for (const CullTestStatistics& result : run.results)
            for (const ClusterStatistics& cluster : result.clusters) {
                out << toString(result.cone) << ',' << toString(result.test);
                writeCells(out, clusterColumns(), cluster);
                out << '\n';
            }
    }
}

std::vector<std::pair<CsvTable, std::string>> csvTableFiles(const std::string& path, const StatisticsDetail& detail) {
    // NAME.csv -> NAME.views.csv; a path without the extension gets it appended.
    std::string stem = path;
    if (stem.size() >= 4) {
        std::string tail = stem.substr(stem.size() - 4);
        for (char& c : tail) c = char(std::tolower(static_cast<unsigned char>(c)));
        if (tail == ".csv") stem.resize(stem.size() - 4);
    }
    std::vector<std::pair<CsvTable, std::string>> files = {{CsvTable::Totals, path}};
    if (detail.views) files.emplace_back(CsvTable::Views, stem + ".views.csv");
    if (detail.clusters) files.emplace_back(CsvTable::Clusters, stem + ".clusters.csv");
    return files;
}

}  // namespace conescope
