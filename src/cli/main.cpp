// conescope-cli: culling statistics, mesh checks and partitions from the command line.
// Exit codes: 0 success, 1 a file could not be read or written (or the run failed), 2 bad arguments.
#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/Batch.h"
#include "cli/Commands.h"
#include "batch/OutputFiles.h"
#include "core/ClusterRanking.h"
#include "core/Comparison.h"
#include "core/LargeArrays.h"
#include "io/ClusterFiles.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"

namespace {

constexpr int kExitFileError = 1;
constexpr int kExitUsageError = 2;

void printError(const std::string& message) { std::cerr << "conescope-cli: error: " << message << std::endl; }

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : " ") + item;
    return text;
}

// -o of a mesh-writing command: the extension decides the format, so check it while parsing.
CLI::Validator meshOutputValidator(const std::vector<std::string>& extensions) {
    return CLI::Validator(
        [extensions](std::string& path) -> std::string {
            if (conescope::cli::hasExtension(path, extensions)) return {};
            return "'" + path + "' must end in one of: " + joined(extensions);
        },
        "FILE");
}

// What `partition -o` writes: the partition files and the meshes that keep cluster_id.
std::vector<std::string> partitionOutputExtensions() {
    std::vector<std::string> extensions = conescope::partitionFileExtensions();
    extensions.insert(extensions.end(), {".vtp", ".vtk"});
    return extensions;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace conescope::cli;
    conescope::keepFreedMemory();

    CLI::App app{"ConeScope: back-face culling of mesh clusters with normal cones.", "conescope-cli"};
    app.require_subcommand(1);
    app.set_version_flag("--version", conescope::conescopeVersion());
    app.failure_message([](const CLI::App*, const CLI::Error& error) {
        return "conescope-cli: error: " + std::string(error.what()) + "\nRun with --help for more information.\n";
    });

    // The formats readMesh takes, from the reader's own table.
    std::string meshFileHelp = "Mesh file (";
    for (const std::string& extension : conescope::supportedMeshExtensions()) meshFileHelp += extension + (extension == conescope::supportedMeshExtensions().back() ? ")" : " ");

    StatsOptions stats;
    CLI::App* statsCommand = app.add_subcommand("stats", "Culling statistics over a set of views, as JSON or CSV");
    statsCommand->add_option("mesh", stats.mesh, meshFileHelp)->required();
    addBuilderOptions(*statsCommand, stats.run);
    addCullingOptions(*statsCommand, stats.run);
    statsCommand->add_option("--format", stats.format,
                             "Output format (default: from the output's extension; on a terminal text, else json)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    statsCommand->add_option("-o,--output", stats.output, "Output file, replaced only when the run succeeds (default: stdout)");
    statsCommand->add_flag_callback("--no-per-view", [&stats] { stats.detail.views = false; }, "Leave out the per-view table");
    statsCommand->add_flag_callback("--no-per-cluster", [&stats] { stats.detail.clusters = false; },
                                    "Leave out the per-cluster table");
    statsCommand->add_option("--table", stats.table,
                             "CSV: the one table to write (default: totals on stdout; with -o FILE.csv every table, the "
                             "views and clusters in FILE.views.csv and FILE.clusters.csv)")
        ->check(CLI::IsMember({"totals", "views", "clusters"}));
    statsCommand->add_flag("-q,--quiet", stats.quiet, "No progress messages on stderr");

    ClustersOptions clusters;
    CLI::App* clustersCommand = app.add_subcommand(
        "clusters", "The clusters that cost the most: a table of the displayed cone and test, worst first");
    clustersCommand->add_option("mesh", clusters.mesh, meshFileHelp)->required();
    addBuilderOptions(*clustersCommand, clusters.run);
    addCullingOptions(*clustersCommand, clusters.run);
    std::string sortKeys;
    for (conescope::ClusterSortKey key : conescope::allClusterSortKeys()) sortKeys += (sortKeys.empty() ? "" : ",") + conescope::toString(key);
    clustersCommand->add_option("--sort", clusters.sort, "Rank by: " + sortKeys + " (losses and sizes largest first, fractions and culled smallest first)")
        ->check([](const std::string& text) -> std::string {
            try {
                conescope::parseClusterSortKey(text);
                return {};
            } catch (const std::invalid_argument& error) {
                return error.what();
            }
        })
        ->capture_default_str();
    clustersCommand->add_option("--top", clusters.top, "How many clusters (0 = all)")->capture_default_str();
    clustersCommand->add_option("--format", clusters.format, "text, json or csv (default: from the output's extension, else text)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    clustersCommand->add_option("-o,--output", clusters.output, "Output file, replaced only when the run succeeds (default: stdout)");
    clustersCommand->add_flag("-q,--quiet", clusters.quiet, "No progress messages on stderr");

    CompareOptions compare;
    CLI::App* compareCommand = app.add_subcommand(
        "compare", "Two configurations A and B of one mesh over the same views: what each culls that the other does not");
    compareCommand->add_option("mesh", compare.mesh, meshFileHelp)->required();
    std::string keys;
    for (const std::string& key : conescope::configurationKeys()) keys += (keys.empty() ? "" : ", ") + key;
    compareCommand->add_option("--a", compare.a, "A's options on top of the common ones, as K=V[,K=V...] with K one of: " + keys)
        ->required();
    compareCommand->add_option("--b", compare.b, "B's options, as for --a (default: none, so B is the common options)");
    addBuilderOptions(*compareCommand, compare.run);
    addCullingOptions(*compareCommand, compare.run);
    compareCommand->add_option("--format", compare.format,
                               "Output format (default: from the output's extension; on a terminal text, else json)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    compareCommand->add_option("-o,--output", compare.output, "Output file, replaced only when the run succeeds (default: stdout)");
    compareCommand->add_flag_callback("--no-per-view", [&compare] { compare.detail.views = false; },
                                      "Leave the per-view tables out of `a` and `b`");
    compareCommand->add_flag_callback("--no-per-cluster", [&compare] { compare.detail.clusters = false; },
                                      "Leave the per-cluster tables out of `a` and `b`");
    compareCommand->add_flag("-q,--quiet", compare.quiet, "No progress messages on stderr");

    CheckOptions check;
    CLI::App* checkCommand = app.add_subcommand("check", "Mesh problems that make culling wrong, as JSON");
    checkCommand->add_option("mesh", check.mesh, meshFileHelp)->required();
    CLI::Option* fixWinding =
        checkCommand->add_flag("--fix-winding", check.fixWinding, "Make face winding consistent and inside-out closed parts face outward (reports the faces flipped)");
    checkCommand->add_option("-o,--output", check.output, "Write the repaired mesh here (.vtp .vtk .ply .off)")
        ->check(meshOutputValidator(conescope::writableMeshExtensions()))
        ->needs(fixWinding);

    PartitionOptions partition;
    CLI::App* partitionCommand =
        app.add_subcommand("partition", "Write the partition: a mesh with cluster_id, meshoptimizer's meshlet arrays, OBJ groups, glTF primitives or ids (read back by --builder file)");
    partitionCommand->add_option("mesh", partition.mesh, meshFileHelp)->required();
    addBuilderOptions(*partitionCommand, partition.run);
    partitionCommand->add_option("-o,--output", partition.output, "Output by extension: .json or .meshlets (meshoptimizer's meshlet arrays and bounds), .obj (an object per cluster), .gltf (a primitive per cluster), .txt (ids), .vtp or .vtk (the mesh with cluster_id)")
        ->required()
        ->check(meshOutputValidator(partitionOutputExtensions()));
    partitionCommand->add_flag("-q,--quiet", partition.quiet, "No progress messages on stderr");

    LodCommandOptions lod;
    CLI::App* lodCommand = app.add_subcommand(
        "lod", "A cluster LOD hierarchy built from the mesh (groups simplified to half, split again): cone culling per level and of the cut an eye draws");
    lodCommand->add_option("mesh", lod.mesh, meshFileHelp)->required();
    addBuilderOptions(*lodCommand, lod.run);
    addCullingOptions(*lodCommand, lod.run);
    lodCommand->add_option("--threshold", lod.threshold.value, "Largest error the cut draws, in pixels (or world units with --world)")
        ->capture_default_str();
    lodCommand->add_flag("--world", lod.threshold.worldUnits, "The threshold in world units, the same from every eye");
    lodCommand->add_option("--screen-height", lod.threshold.screenHeight, "Pixels of the screen's height, for a threshold in pixels")
        ->capture_default_str();
    lodCommand->add_option("--fov", lod.threshold.fovDegrees, "Vertical field of view in degrees, for a threshold in pixels")
        ->capture_default_str();
    lodCommand->add_option("--group-size", lod.groupSize, "Most clusters simplified together")->capture_default_str();
    lodCommand->add_option("--hierarchy", lod.hierarchy, "Read the hierarchy from this file (conescope-cluster-lod JSON, made for MESH) instead of building one");
    lodCommand->add_option("--write-levels", lod.writeLevels, "Write each level (level-NN.vtp) and the cut from the first view (cut.vtp) to this folder, with cluster_id and level per face");
    lodCommand->add_option("--write-hierarchy", lod.writeHierarchy, "Write the hierarchy measured to this file (conescope-cluster-lod JSON: meshoptimizer's meshlet arrays of every level, clusters and groups)");
    lodCommand->add_flag_callback("--no-per-view", [&lod] { lod.perView = false; }, "Leave the cut of each view out of the JSON");
    lodCommand->add_option("--format", lod.format, "Output format (default: from the output's extension; on a terminal text, else json)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    lodCommand->add_option("-o,--output", lod.output, "Output file, replaced only when the run succeeds (default: stdout)");
    lodCommand->add_flag("-q,--quiet", lod.quiet, "No progress messages on stderr");

    GranularityOptions granularity;
    CLI::App* granularityCommand = addGranularityCommand(app, granularity, meshFileHelp);

    BatchOptions batch;
    BatchWorkerOptions batchWorker;
    const BatchCommands batchCommands = addBatchCommands(app, batch, batchWorker);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);  // prints help, the version or the failure message
        return code == 0 ? 0 : kExitUsageError;
    }

    try {
        if (statsCommand->parsed()) runStats(stats);
        if (clustersCommand->parsed()) runClusters(clusters);
        if (compareCommand->parsed()) runCompare(compare);
        if (checkCommand->parsed()) runCheck(check);
        if (partitionCommand->parsed()) runPartition(partition);
        if (lodCommand->parsed()) runLod(lod);
        if (granularityCommand->parsed()) runGranularity(granularity);
        if (batchCommands.batch->parsed()) return runBatch(batch);
        if (batchCommands.worker->parsed()) return runBatchWorker(batchWorker);
    } catch (const std::invalid_argument& error) {
        // Settings the core refused (e.g. meshoptimizer's limits): still a usage problem.
        printError(error.what());
        return kExitUsageError;
    } catch (const std::exception& error) {
        printError(error.what());
        return kExitFileError;
    }
    return 0;
}
