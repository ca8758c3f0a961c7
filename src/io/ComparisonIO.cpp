#include "io/ComparisonIO.h"

#include <cstdio>

#include "core/SettingsSchema.h"
#include "io/JsonWriter.h"

namespace conescope {

namespace {

nlohmann::json viewToJson(const ViewComparison& view) {
    return {{"view", view.view},
            {"eye", {view.eye.position.x, view.eye.position.y, view.eye.position.z}},
            {"direction", {view.eye.direction.x, view.eye.direction.y, view.eye.direction.z}},
            {"orthographic", view.eye.orthographic},
            {"back_facing_triangles", view.backFacingTriangles},
            {"triangles_culled_only_a", view.trianglesCulledOnlyA},
            {"triangles_culled_only_b", view.trianglesCulledOnlyB},
            {"triangles_culled_both", view.trianglesCulledBoth},
            {"efficiency_a", view.efficiencyA},
            {"efficiency_b", view.efficiencyB}};
}

// "key=value" for every option the configuration sets otherwise than `base`.
std::string differences(const Settings& settings, const Settings& base) {
    std::string text;
    for (const SettingField& field : settingFields()) {
        const std::string value = settingText(field, settings);
        if (value != settingText(field, base)) text += (text.empty() ? "" : ",") + field.flag + "=" + value;
    }
    return text.empty() ? "(the common options)" : text;
}

// "1 cluster", "2 clusters": the summary is read by people.
std::string counted(size_t count, const std::string& noun) { return std::to_string(count) + " " + noun + (count == 1 ? "" : "s"); }

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%%", 100.0 * fraction);
    return text;
}

}  // namespace

nlohmann::json comparisonToJson(const Comparison& comparison) {
    nlohmann::json views = nlohmann::json::array();
    for (const ViewComparison& view : comparison.views) views.push_back(viewToJson(view));
    const std::string warning = clusterCountWarning(comparison);
    return {{"cone_a", toString(comparison.coneA)},
            {"test_a", toString(comparison.testA)},
            {"cone_b", toString(comparison.coneB)},
            {"test_b", toString(comparison.testB)},
            {"clusters_a", comparison.clustersA},
            {"clusters_b", comparison.clustersB},
            {"cluster_count_warning", warning.empty() ? nlohmann::json(nullptr) : nlohmann::json(warning)},
            {"back_facing_triangles", comparison.backFacingTriangles},
            {"triangles_culled_only_a", comparison.trianglesCulledOnlyA},
            {"triangles_culled_only_b", comparison.trianglesCulledOnlyB},
            {"triangles_culled_both", comparison.trianglesCulledBoth},
            {"efficiency_a", comparison.efficiencyA},
            {"efficiency_b", comparison.efficiencyB},
            {"views", std::move(views)}};
}

void writeComparisonJson(const RunStatistics& a, const RunStatistics& b, const Comparison& comparison,
                         const StatisticsDetail& detail, std::ostream& out) {
    std::string text;
    JsonWriter json(text);
    json.beginObject();
    json.key("a");
    writeStatistics(json, a, detail);
    json.key("b");
    writeStatistics(json, b, detail);
    json.key("diff");
    json.value(comparisonToJson(comparison));
    json.endObject();
    text += '\n';
    out << text;
}

void writeComparisonCsv(const Comparison& comparison, std::ostream& out) {
    out << "view,eye_x,eye_y,eye_z,back_facing_triangles,triangles_culled_only_a,triangles_culled_only_b,"
           "triangles_culled_both,efficiency_a,efficiency_b\n";
    for (const ViewComparison& view : comparison.views)
        out << view.view << ',' << csvNumber(view.eye.position.x) << ',' << csvNumber(view.eye.position.y) << ','
            << csvNumber(view.eye.position.z) << ',' << view.backFacingTriangles << ',' << view.trianglesCulledOnlyA << ','
            << view.trianglesCulledOnlyB << ',' << view.trianglesCulledBoth << ',' << csvNumber(view.efficiencyA) << ','
            << csvNumber(view.efficiencyB) << '\n';
}

void writeComparisonText(const RunStatistics& a, const RunStatistics& b, const Comparison& comparison, const Settings& base,
                         std::ostream& out) {
    const double back = double(std::max<size_t>(comparison.backFacingTriangles, 1));
    out << a.meshName << ": " << a.triangles << " triangles, " << counted(comparison.views.size(), "view") << '\n';
    out << "A: " << differences(a.settings, base) << "\n   " << counted(comparison.clustersA, "cluster") << ", "
        << toString(comparison.coneA) << " / " << toString(comparison.testA) << ", efficiency " << percent(comparison.efficiencyA) << '\n';
    out << "B: " << differences(b.settings, base) << "\n   " << counted(comparison.clustersB, "cluster") << ", "
        << toString(comparison.coneB) << " / " << toString(comparison.testB) << ", efficiency " << percent(comparison.efficiencyB) << '\n';
    out << "back-facing triangles culled by A only: " << comparison.trianglesCulledOnlyA << " ("
        << percent(double(comparison.trianglesCulledOnlyA) / back) << "), by B only: " << comparison.trianglesCulledOnlyB << " ("
        << percent(double(comparison.trianglesCulledOnlyB) / back) << "), by both: " << comparison.trianglesCulledBoth << " ("
        << percent(double(comparison.trianglesCulledBoth) / back) << ")\n";
    const std::string warning = clusterCountWarning(comparison);
    if (!warning.empty()) out << "warning: " << warning << '\n';
}

}  // namespace conescope
