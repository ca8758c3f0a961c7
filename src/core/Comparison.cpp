#include "Comparison.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "BatchCulling.h"
#include "SettingsSchema.h"

namespace conescope {

namespace {

// Both sides see the same mesh from the same eyes: these are given once, for both.
bool sharedOption(const std::string& flag) {
    return flag == "views" || flag == "distance" || flag == "eye" || flag == "ortho" || flag == "fix-winding";
}

const SettingField* configurationField(const std::string& key) {
    for (const SettingField& field : settingFields())
        if (field.flag == key && !sharedOption(key)) return &field;
    return nullptr;
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
    return text;
}

struct ConfigurationPair {
    std::string key;
    std::optional<std::string> value;  // none: "K" alone
};

// "K=V" pieces split at commas; a piece without "=" that is not an option continues the value before
// it (lists, paths with commas), while any piece with "=" is a pair of its own, so a mistyped key is
// named as unknown rather than read as part of the value before it.
std::vector<ConfigurationPair> configurationPairs(const std::string& text) {
    std::vector<ConfigurationPair> pairs;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string piece = text.substr(start, comma - start);
        const size_t equals = piece.find('=');
        const std::string key = piece.substr(0, equals);
        if (pairs.empty() || equals != std::string::npos || sharedOption(key) || configurationField(key)) {
            pairs.push_back({key, equals == std::string::npos ? std::nullopt : std::optional(piece.substr(equals + 1))});
        } else {
            std::optional<std::string>& value = pairs.back().value;
            value = (value ? *value : std::string()) + "," + piece;
        }
        start = comma + 1;
    }
    return pairs;
}

// An empty comparison of A and B: what both sides are, and per-face counts at zero.
Comparison emptyComparison(const PreparedMesh& prepared, const ClusterConfiguration& a, const ClusterConfiguration& b) {
    const size_t faceCount = prepared.mesh().faceCount();
    if (a.clusters.partition.clusterOfFace.size() != faceCount || b.clusters.partition.clusterOfFace.size() != faceCount)
        throw std::invalid_argument("compareClusterSets: A and B must partition the prepared mesh");
    Comparison comparison;
    comparison.testA = displayedTest(a.settings), comparison.testB = displayedTest(b.settings);
    comparison.coneA = a.clusters.bounds.coneMethod, comparison.coneB = b.clusters.bounds.coneMethod;
    comparison.clustersA = a.clusters.bounds.count(), comparison.clustersB = b.clusters.bounds.count();
    comparison.viewsCulledOnlyA.assign(faceCount, 0);
    comparison.viewsCulledOnlyB.assign(faceCount, 0);
    return comparison;
}

// One view's faces into the comparison: back-facing triangles only, as triangles_culled counts them.
void addView(Comparison& comparison, const Mesh& mesh, const Eye& eye, const std::vector<Facing>& facing,
             const std::vector<FaceDiff>& diff) {
    ViewComparison view;
    view.view = comparison.views.size();
    view.eye = eye;
    for (size_t f = 0; f < diff.size(); ++f) {
        if (facing[f] != Facing::Back) continue;
        const size_t triangles = mesh.faceSize(f) - 2;
        view.backFacingTriangles += triangles;
        switch (diff[f]) {
            case FaceDiff::OnlyA: view.trianglesCulledOnlyA += triangles, ++comparison.viewsCulledOnlyA[f]; break;
            case FaceDiff::OnlyB: view.trianglesCulledOnlyB += triangles, ++comparison.viewsCulledOnlyB[f]; break;
            case FaceDiff::Both: view.trianglesCulledBoth += triangles; break;
            case FaceDiff::Neither: break;
        }
    }
    view.efficiencyA = cullEfficiency(view.trianglesCulledOnlyA + view.trianglesCulledBoth, view.backFacingTriangles);
    view.efficiencyB = cullEfficiency(view.trianglesCulledOnlyB + view.trianglesCulledBoth, view.backFacingTriangles);
    comparison.trianglesCulledOnlyA += view.trianglesCulledOnlyA;
    comparison.trianglesCulledOnlyB += view.trianglesCulledOnlyB;
    comparison.trianglesCulledBoth += view.trianglesCulledBoth;
    comparison.backFacingTriangles += view.backFacingTriangles;
    comparison.efficiencyA = cullEfficiency(comparison.trianglesCulledOnlyA + comparison.trianglesCulledBoth, comparison.backFacingTriangles);
    comparison.efficiencyB = cullEfficiency(comparison.trianglesCulledOnlyB + comparison.trianglesCulledBoth, comparison.backFacingTriangles);
    comparison.views.push_back(view);
}

}  // namespace

std::vector<std::string> configurationKeys() {
    std::vector<std::string> keys;
    for (const SettingField& field : settingFields())
        if (!sharedOption(field.flag)) keys.push_back(field.flag);
    return keys;
}

Settings withSharedOptions(Settings side, const Settings& shared) {
    for (const SettingField& field : settingFields())
        if (sharedOption(field.flag)) field.assign(side, field.value(shared));
    return side;
}

Settings parseConfiguration(const std::string& text, const Settings& base) {
    Settings settings = base;
    if (text.empty()) return settings;
    for (const auto& [key, value] : configurationPairs(text)) {
        if (sharedOption(key))
            throw std::invalid_argument("'" + key + "' is shared by both sides: give it as --" + key + " outside --a and --b");
        const SettingField* field = configurationField(key);
        if (!field)
            throw std::invalid_argument("unknown option '" + key + "' in a configuration (expected K=V with K one of: " +
                                        joined(configurationKeys()) + ")");
        // An on/off option alone is on; the schema reads K=on/off (and every other kind) as the CLI does.
        if (!value && field->kind != SettingKind::Flag)
            throw std::invalid_argument("'" + key + "' needs a value: " + key + "=" + field->valueName);
        parseSetting(*field, value.value_or(""), settings);
    }
    return settings;
}

bool Comparison::clusterCountsDiffer() const {
    const size_t smaller = std::min(clustersA, clustersB), larger = std::max(clustersA, clustersB);
    return double(larger) > 1.05 * double(smaller);
}

std::string clusterCountWarning(const Comparison& comparison) {
    if (!comparison.clusterCountsDiffer()) return {};
    return "A has " + std::to_string(comparison.clustersA) + " clusters and B " + std::to_string(comparison.clustersB) +
           ", more than 5% apart: smaller clusters cull more for free, so compare at equal counts (--clusters K)";
}

std::vector<FaceDiff> faceDiff(const ClusterSet& a, const std::vector<uint8_t>& culledA, const ClusterSet& b,
                               const std::vector<uint8_t>& culledB) {
    const std::vector<uint32_t>& clusterA = a.partition.clusterOfFace;
    const std::vector<uint32_t>& clusterB = b.partition.clusterOfFace;
    if (clusterA.size() != clusterB.size()) throw std::invalid_argument("faceDiff: A and B partition different meshes");
    std::vector<FaceDiff> diff(clusterA.size());
    for (size_t f = 0; f < diff.size(); ++f)
        diff[f] = FaceDiff((culledA[clusterA[f]] ? 1 : 0) | (culledB[clusterB[f]] ? 2 : 0));
    return diff;
}

Comparison compareClusterSets(const PreparedMesh& prepared, const ClusterConfiguration& a, const ClusterConfiguration& b,
                              const std::vector<Eye>& views, const ProgressCallback& progress) {
    Comparison comparison = emptyComparison(prepared, a, b);
    const Mesh& mesh = prepared.mesh();
    // Each side's float batch once, as measureCulling makes it for its views.
    const ClusterBatch batchA = makeClusterBatch(a.clusters.bounds), batchB = makeClusterBatch(b.clusters.bounds);
    const CullingInput inputA{mesh, prepared.world, prepared.faces, a.clusters.bounds, &batchA};
    const CullingInput inputB{mesh, prepared.world, prepared.faces, b.clusters.bounds, &batchB};
    for (size_t v = 0; v < views.size(); ++v) {
        if (progress && v % 16 == 0 && !progress(double(v) / double(views.size()), "views")) throw OperationCancelled();
        const Eye& eye = views[v];
        addView(comparison, mesh, eye, classifyFaces(mesh, prepared.world, prepared.faces, eye),
                faceDiff(a.clusters, cullClusters(inputA, eye, comparison.testA), b.clusters, cullClusters(inputB, eye, comparison.testB)));
    }
    return comparison;
}

Comparison compareAtEye(const PreparedMesh& prepared, const ClusterConfiguration& a, const std::vector<uint8_t>& culledA,
                        const ClusterConfiguration& b, const std::vector<uint8_t>& culledB, const Eye& eye,
                        std::vector<FaceDiff>& diff) {
    Comparison comparison = emptyComparison(prepared, a, b);
    diff = faceDiff(a.clusters, culledA, b.clusters, culledB);
    addView(comparison, prepared.mesh(), eye, classifyFaces(prepared.mesh(), prepared.world, prepared.faces, eye), diff);
    return comparison;
}

ComparedRuns runComparison(const PreparedMesh& prepared, const Settings& a, const Settings& b, const Settings& shared,
                           const ProgressCallback& progress, const std::function<void(char side)>& building) {
    if (building) building('A');
    const ClusterSet clustersA = buildClusters(prepared, a, nullptr, progress);
    if (building) building('B');
    const ClusterSet clustersB = buildClusters(prepared, b, nullptr, progress);
    ComparedRuns runs{measureRun(prepared, clustersA, a, progress), measureRun(prepared, clustersB, b, progress), {}};
    runs.comparison = compareClusterSets(prepared, {clustersA, a}, {clustersB, b}, viewsFor(shared, prepared.box), progress);
    return runs;
}

}  // namespace conescope
