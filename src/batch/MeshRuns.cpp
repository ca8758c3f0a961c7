#include "batch/MeshRuns.h"

#include <memory>

#include "core/MeshChecks.h"
#include "io/StatisticsIO.h"

namespace conescope::cli {

std::vector<std::string> runWarnings(const RunStatistics& run, const std::string& which) {
    std::vector<std::string> warnings;
    const std::string winding = windingWarning(run.meshReport);
    if (!winding.empty() && !run.settings.fixWinding) warnings.push_back(which + winding + "; repair with --fix-winding");
    const std::string sides = doubleSidedWarning(run.meshReport);
    if (!sides.empty()) warnings.push_back(which + sides);
    const std::string budget = budgetMissed(run.settings, run.clusters, run.fewestClusters);
    if (!budget.empty()) warnings.push_back(which + budget);
    return warnings;
}

Settings clusterTableSettings(Settings settings) {
    settings.cones.resize(1);
    settings.tests.resize(1);
    return settings;
}

nlohmann::json clusterTableJson(const RunStatistics& run, ClusterSortKey key, size_t top) {
    const CullTestStatistics& result = run.results.front();
    const nlohmann::json mesh = {
        {"name", run.meshName}, {"vertices", run.vertices}, {"faces", run.faces}, {"triangles", run.triangles}};
    return {{"mesh", mesh},
            {"settings", settingsToJson(run.settings)},
            {"clusters", run.clusters},
            {"view_count", run.viewCount},
            {"cone", toString(result.cone)},
            {"test", toString(result.test)},
            {"sort", toString(key)},
            {"rows", clusterRowsToJson(result, rankClusters(result, key, top))}};
}

ComparedRuns compareMesh(const Mesh& mesh, const std::string& path, const Settings& a, const Settings& b,
                         const Settings& shared, const ProgressCallback& progress,
                         const std::function<void(char side)>& building) {
    const PreparedMesh prepared = prepareMesh(std::make_shared<Mesh>(mesh), path, shared.fixWinding, progress);
    return runComparison(prepared, a, b, shared, progress, building);
}

}  // namespace conescope::cli
