#include "cli/Commands.h"

#include <filesystem>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "cli/OutputFiles.h"
#include "core/ClusterRanking.h"
#include "core/MeshChecks.h"
#include "core/Pipeline.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"
#include "io/StatisticsText.h"

namespace conescope::cli {

namespace {

// Stage names on stderr, so a long run shows it is alive while stdout stays clean for the data.
// A line only when the percentage or the stage changes: the builder reports every part it finishes.
ProgressCallback stderrProgress(bool quiet) {
    if (quiet) return {};
    return [lastPercent = -1, lastStage = std::string()](double fraction, const std::string& stage) mutable {
        const int percent = int(fraction * 100.0 + 0.5);
        if (percent == lastPercent && stage == lastStage) return true;
        lastPercent = percent, lastStage = stage;
        std::cerr << "conescope-cli: " << percent << "% " << stage << std::endl;
        return true;
    };
}

void note(bool quiet, const std::string& message) {
    if (!quiet) std::cerr << "conescope-cli: " << message << std::endl;
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// Warnings are for every run, --quiet or not: they say the numbers on stdout may be wrong.
void warn(const std::string& message) { std::cerr << "conescope-cli: warning: " << message << std::endl; }

// The mesh, with what its reader noticed (skipped points and lines, a converted encoding) on stderr
// even when quiet: it says what the numbers are about.
Mesh readMeshNoting(const std::string& path, bool quiet) {
    note(quiet, "reading " + path);
    MeshFile file = readMeshFile(path, stderrProgress(quiet));
    for (const std::string& readerNote : file.notes) note(false, fileName(path) + ": " + readerNote);
    return std::move(file.mesh);
}

// Inconsistent or inside-out winding makes every number after it wrong without looking wrong.
void warnAboutWinding(const RunStatistics& run, bool quiet) {
    const std::string warning = windingWarning(run.meshReport);
    if (warning.empty()) return;
    if (run.settings.fixWinding)
        note(quiet, "--fix-winding flipped " + std::to_string(run.windingFixedFaces) + " faces (" + warning + ")");
    else
        warn(warning + "; repair with --fix-winding");
}

// The format asked for, else the output file's (.csv, .json, .txt), else text for a person at a
// terminal and `otherwise` for a pipe or file.
std::string outputFormat(const std::string& format, const std::string& output, const std::string& otherwise) {
    if (!format.empty()) return format;
    if (hasExtension(output, {".csv"})) return "csv";
    if (hasExtension(output, {".json"})) return "json";
    if (hasExtension(output, {".txt"})) return "text";
    return output.empty() && isatty(fileno(stdout)) ? "text" : otherwise;
}

void writeText(const std::string& output, const std::string& text) {
    if (output.empty()) {
        std::cout << text << std::flush;
        if (!std::cout) throw std::runtime_error("cannot write to standard output");
    } else {
        writeTextFileAtomically(output, text);
    }
}

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
    const Settings settings = options.run.toSettings();
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet);
    const RunStatistics run = runStatistics(mesh, settings, fileName(options.mesh), stderrProgress(options.quiet));
    warnAboutWinding(run, options.quiet);
    const std::string format = outputFormat(options.format, options.output, "json");
    if (format != "csv" && !options.table.empty()) throw std::invalid_argument("--table applies to CSV output only");
    if (format == "csv") {
        writeCsvTables(run, options);
        return;
    }
    // The whole text is made before anything is written, so stdout never gets half a document.
    std::ostringstream text;
    if (format == "text")
        writeStatisticsText(run, text);
    else
        writeStatisticsJson(run, text, options.detail);
    writeText(options.output, text.str());
    if (!options.output.empty()) note(options.quiet, "wrote " + options.output);
}

void runClusters(const ClustersOptions& options) {
    Settings settings = options.run.toSettings();
    // The table is about one (cone, test): the displayed ones.
    settings.cones.resize(1);
    settings.tests.resize(1);
    const ClusterSortKey key = parseClusterSortKey(options.sort);
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet);
    const RunStatistics run = runStatistics(mesh, settings, fileName(options.mesh), stderrProgress(options.quiet));
    warnAboutWinding(run, options.quiet);
    const TestStatistics& result = run.results.front();
    const std::vector<uint32_t> order = rankClusters(result, key, options.top);
    std::ostringstream text;
    const std::string format = outputFormat(options.format, options.output, "text");
    if (format == "csv") {
        writeClusterRowsCsv(result, order, text);
    } else if (format == "json") {
        text << nlohmann::json{{"mesh", meshSummary(options.mesh, mesh)},
                               {"settings", settingsToJson(settings)},
                               {"clusters", run.clusters},
                               {"view_count", run.viewCount},
                               {"cone", toString(result.cone)},
                               {"test", toString(result.test)},
                               {"sort", toString(key)},
                               {"rows", clusterRowsToJson(result, order)}}
                    .dump(2)
             << '\n';
    } else {
        writeStatisticsText(run, text, 0);
        text << "\nclusters by " << toString(key) << " (alpha* = never cullable):\n";
        writeClusterTableText(result, order, text);
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
    const Settings settings = options.run.toSettings();
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet);
    note(options.quiet, "building clusters (" + toString(settings.builder) + ")");
    const Partition partition = buildPartition(mesh, computeFaceGeometry(mesh), settings, stderrProgress(options.quiet));
    const std::vector<double> ids(partition.clusterOfFace.begin(), partition.clusterOfFace.end());
    replaceFileAtomically(options.output, [&](const std::string& temporary) {
        writePolyData(mesh, temporary, {{"cluster_id", ids}});
    });
    note(options.quiet, "wrote " + options.output + ": " + std::to_string(mesh.faceCount()) + " faces in " +
                            std::to_string(partition.clusterCount) + " clusters");
}

}  // namespace conescope::cli
