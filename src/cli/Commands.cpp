#include "cli/Commands.h"

#include <filesystem>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "cli/CommandSupport.h"
#include "batch/MeshRuns.h"
#include "batch/OutputFiles.h"
#include "core/ClusterRanking.h"
#include "core/MeshChecks.h"
#include "core/Pipeline.h"
#include "io/ClusterFiles.h"
#include "io/ClusterIdFile.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"
#include "io/StatisticsText.h"

namespace conescope::cli {

namespace {

// One tidy table per file: the one asked for (--table) or the totals on stdout; into -o FILE.csv every
// table the detail keeps, the others beside it (csvTableFiles).
void writeCsvTables(const RunStatistics& run, const StatsOptions& options) {
    std::vector<std::pair<CsvTable, std::string>> files;
    if (!options.table.empty() || options.output.empty())
        files = {{options.table.empty() ? CsvTable::Totals : parseCsvTable(options.table), options.output}};
    else
        files = csvTableFiles(options.output, options.detail);
    for (const auto& [table, path] : files) {
        std::ostringstream text;
        writeStatisticsCsv(run, text, table);
        writeText(path, text.str());
        if (!path.empty()) note(options.quiet, "wrote " + path + " (" + toString(table) + ")");
    }
}

nlohmann::json meshSummary(const std::string& path, const Mesh& mesh) {
    return {{"name", fileName(path)},
            {"vertices", mesh.positions.size()},
            {"faces", mesh.faceCount()},
            {"triangles", triangleCount(mesh)}};
}

}  // namespace

void runStats(const StatsOptions& options) {
    const Settings settings = withClusterIds(options.run.toSettings());
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet, {settings});
    const RunStatistics run = runStatistics(mesh, settings, fileName(options.mesh), stderrProgress(options.quiet));
    warnAboutMesh(run, options.quiet);
    warnAboutBudget(run);
    const std::string format = outputFormat(options.format, options.output, "json");
    if (format != "csv" && !options.table.empty()) throw std::invalid_argument("--table applies to CSV output only");
    if (format == "csv") {
        writeCsvTables(run, options);
        return;
    }
    // The whole text is made before anything is written, so stdout never gets half a document.
    std::string text;
    if (format == "text") {
        std::ostringstream out;
        writeStatisticsText(run, out);
        text = out.str();
    } else {
        text = statisticsJsonText(run, options.detail);
    }
    writeText(options.output, text);
    if (!options.output.empty()) note(options.quiet, "wrote " + options.output);
}

void runClusters(const ClustersOptions& options) {
    const Settings settings = clusterTableSettings(withClusterIds(options.run.toSettings()));
    const ClusterSortKey key = parseClusterSortKey(options.sort);
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet, {settings});
    const RunStatistics run = runStatistics(mesh, settings, fileName(options.mesh), stderrProgress(options.quiet));
    warnAboutMesh(run, options.quiet);
    warnAboutBudget(run);
    const CullTestStatistics& result = run.results.front();
    std::ostringstream text;
    const std::string format = outputFormat(options.format, options.output, "text");
    if (format == "csv") {
        writeClusterRowsCsv(result, rankClusters(result, key, options.top), text);
    } else if (format == "json") {
        text << clusterTableJson(run, key, options.top).dump(2) << '\n';
    } else {
        writeStatisticsText(run, text, 0);
        text << "\nclusters by " << toString(key) << " (alpha* = never cullable):\n";
        writeClusterTableText(result, rankClusters(result, key, options.top), text);
    }
    writeText(options.output, text.str());
    if (!options.output.empty()) note(options.quiet, "wrote " + options.output);
}

void runCheck(const CheckOptions& options) {
    Mesh mesh = readMeshNoting(options.mesh, true);
    nlohmann::json result = {{"mesh", meshSummary(options.mesh, mesh)},
                             {"report", meshReportToJson(checkMesh(mesh, computeFaceGeometry(mesh)))}};
    if (options.fixWinding) {
        result["winding_fixed_faces"] = fixWinding(mesh);
        result["report_after_fix"] = meshReportToJson(checkMesh(mesh, computeFaceGeometry(mesh)));
        if (!options.output.empty())
            replaceFileAtomically(options.output, [&](const std::string& temporary) { writePolyData(mesh, temporary); });
    }
    result["output"] = options.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(options.output);
    std::cout << result.dump(2) << std::endl;
}

void runPartition(const PartitionOptions& options) {
    const Settings settings = withClusterIds(options.run.toSettings());
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet, {settings});
    note(options.quiet, "building clusters (" + toString(settings.builder) + ")");
    const Partition partition = buildPartition(mesh, computeFaceGeometry(mesh), settings, stderrProgress(options.quiet));
    // By the output's extension: a mesh with cluster_id, meshlet arrays, OBJ groups, glTF primitives or ids.
    replaceFileAtomically(options.output, [&](const std::string& temporary) { writePartitionFile(mesh, partition, temporary); });
    note(options.quiet, "wrote " + options.output + ": " + std::to_string(mesh.faceCount()) + " faces in " +
                            std::to_string(partition.clusterCount) + " clusters");
}

}  // namespace conescope::cli
