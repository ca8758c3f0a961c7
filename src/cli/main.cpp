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

using namespace conescope::cli;

// The stats command: culling statistics over the orbit's views.
CLI::App* addStatsCommand(CLI::App& app, StatsOptions& stats, const std::string& meshFileHelp) {
    CLI::App* command = app.add_subcommand("stats", "Culling statistics over a set of views, as JSON or CSV");
    command->add_option("mesh", stats.mesh, meshFileHelp)->required();
    addBuilderOptions(*command, stats.run);
    addCullingOptions(*command, stats.run);
    command->add_option("--format", stats.format,
                             "Output format (default: from the output's extension; on a terminal text, else json)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    command->add_option("-o,--output", stats.output, "Output file, replaced only when the run succeeds (default: stdout)");
    command->add_flag_callback("--no-per-view", [&stats] { stats.detail.views = false; }, "Leave out the per-view table");
    command->add_flag_callback("--no-per-cluster", [&stats] { stats.detail.clusters = false; },
                                    "Leave out the per-cluster table");
    command->add_option("--table", stats.table,
                             "CSV: the one table to write (default: totals on stdout; with -o FILE.csv every table, the "
                             "views and clusters in FILE.views.csv and FILE.clusters.csv)")
        ->check(CLI::IsMember({"totals", "views", "clusters"}));
    command->add_flag("-q,--quiet", stats.quiet, "No progress messages on stderr");
    return command;
}

// The clusters command: the costliest clusters, worst first.
CLI::App* addClustersCommand(CLI::App& app, ClustersOptions& clusters, const std::string& meshFileHelp) {
    CLI::App* command = app.add_subcommand(
        "clusters", "The clusters that cost the most: a table of the displayed cone and test, worst first");
    command->add_option("mesh", clusters.mesh, meshFileHelp)->required();
    addBuilderOptions(*command, clusters.run);
    addCullingOptions(*command, clusters.run);
    std::string sortKeys;
    for (conescope::ClusterSortKey key : conescope::allClusterSortKeys()) sortKeys += (sortKeys.empty() ? "" : ",") + conescope::toString(key);
    command->add_option("--sort", clusters.sort, "Rank by: " + sortKeys + " (losses and sizes largest first, fractions and culled smallest first)")
        ->check([](const std::string& text) -> std::string {
            try {
                conescope::parseClusterSortKey(text);
                return {};
            } catch (const std::invalid_argument& error) {
                return error.what();
            }
        })
        ->capture_default_str();
    command->add_option("--top", clusters.top, "How many clusters (0 = all)")->capture_default_str();
    command->add_option("--format", clusters.format, "text, json or csv (default: from the output's extension, else text)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    command->add_option("-o,--output", clusters.output, "Output file, replaced only when the run succeeds (default: stdout)");
    command->add_flag("-q,--quiet", clusters.quiet, "No progress messages on stderr");
    return command;
}

// The compare command: two configurations of one mesh over the same views.
CLI::App* addCompareCommand(CLI::App& app, CompareOptions& compare, const std::string& meshFileHelp) {
    CLI::App* command = app.add_subcommand(
        "compare", "Two configurations A and B of one mesh over the same views: what each culls that the other does not");
    command->add_option("mesh", compare.mesh, meshFileHelp)->required();
    std::string keys;
    for (const std::string& key : conescope::configurationKeys()) keys += (keys.empty() ? "" : ", ") + key;
    command->add_option("--a", compare.a, "A's options on top of the common ones, as K=V[,K=V...] with K one of: " + keys)
        ->required();
    command->add_option("--b", compare.b, "B's options, as for --a (default: none, so B is the common options)");
    addBuilderOptions(*command, compare.run);
    addCullingOptions(*command, compare.run);
    command->add_option("--format", compare.format,
                               "Output format (default: from the output's extension; on a terminal text, else json)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    command->add_option("-o,--output", compare.output, "Output file, replaced only when the run succeeds (default: stdout)");
    command->add_flag_callback("--no-per-view", [&compare] { compare.detail.views = false; },
                                      "Leave the per-view tables out of `a` and `b`");
    command->add_flag_callback("--no-per-cluster", [&compare] { compare.detail.clusters = false; },
                                      "Leave the per-cluster tables out of `a` and `b`");
    command->add_flag("-q,--quiet", compare.quiet, "No progress messages on stderr");
    return command;
}

// The check command: mesh problems that make culling wrong, and the winding repair.
CLI::App* addCheckCommand(CLI::App& app, CheckOptions& check, const std::string& meshFileHelp) {
    CLI::App* command = app.add_subcommand("check", "Mesh problems that make culling wrong, as JSON");
    command->add_option("mesh", check.mesh, meshFileHelp)->required();
    CLI::Option* fixWinding =
        command->add_flag("--fix-winding", check.fixWinding, "Make face winding consistent and inside-out closed parts face outward (reports the faces flipped)");
    command->add_option("-o,--output", check.output, "Write the repaired mesh here (.vtp .vtk .ply .off)")
        ->check(meshOutputValidator(conescope::writableMeshExtensions()))
        ->needs(fixWinding);
    return command;
}

// The partition command: the clusters written to a file.
CLI::App* addPartitionCommand(CLI::App& app, PartitionOptions& partition, const std::string& meshFileHelp) {
    CLI::App* command =
        app.add_subcommand("partition", "Write the partition: a mesh with cluster_id, meshoptimizer's meshlet arrays, OBJ groups, glTF primitives or ids (read back by --builder file)");
    command->add_option("mesh", partition.mesh, meshFileHelp)->required();
    addBuilderOptions(*command, partition.run);
    command->add_option("-o,--output", partition.output, "Output by extension: .json or .meshlets (meshoptimizer's meshlet arrays and bounds), .obj (an object per cluster), .gltf (a primitive per cluster), .txt (ids), .vtp or .vtk (the mesh with cluster_id)")
        ->required()
        ->check(meshOutputValidator(partitionOutputExtensions()));
    command->add_flag("-q,--quiet", partition.quiet, "No progress messages on stderr");
    return command;
}

// The lod command: a cluster LOD hierarchy and cone culling level by level.
CLI::App* addLodCommand(CLI::App& app, LodCommandOptions& lod, const std::string& meshFileHelp) {
    CLI::App* command = app.add_subcommand(
        "lod", "A cluster LOD hierarchy built from the mesh (groups simplified to half, split again): cone culling per level and of the cut an eye draws");
    command->add_option("mesh", lod.mesh, meshFileHelp)->required();
    addBuilderOptions(*command, lod.run);
    addCullingOptions(*command, lod.run);
    command->add_option("--threshold", lod.threshold.value, "Largest error the cut draws, in pixels (or world units with --world)")
        ->capture_default_str();
    command->add_flag("--world", lod.threshold.worldUnits, "The threshold in world units, the same from every eye");
    command->add_option("--screen-height", lod.threshold.screenHeight, "Pixels of the screen's height, for a threshold in pixels")
        ->capture_default_str();
    command->add_option("--fov", lod.threshold.fovDegrees, "Vertical field of view in degrees, for a threshold in pixels")
        ->capture_default_str();
    command->add_option("--group-size", lod.groupSize, "Most clusters simplified together")->capture_default_str();
    command->add_option("--cones", lod.cones, "Also cull every level and the cut with K cones per cluster (2, 4 or 8; granularity's cones-K record; the same as --cones-per-cluster)")
        ->check(CLI::IsMember({2, 4, 8}));
    command->add_option("--hierarchy", lod.hierarchy, "Read the hierarchy from this file (conescope-cluster-lod JSON or its binary form, made for MESH) instead of building one");
    command->add_option("--write-levels", lod.writeLevels, "Write each level (level-NN.vtp) and the cut from the first view (cut.vtp) to this folder, with cluster_id and level per face");
    command->add_option("--write-lesson", lod.writeLesson,
                        "Write the lesson on why coarse clusters cull less, with this mesh's numbers, to this Markdown file");
    command->add_option("--lesson-level", lod.lessonLevel,
                        "The level the lesson compares with level 0 (default: the coarsest with at least 8 clusters)");
    command->add_option("--write-hierarchy", lod.writeHierarchy, "Write the hierarchy measured to this file (conescope-cluster-lod: meshoptimizer's meshlet arrays of every level, clusters and groups; binary for .lod or .bin, else JSON)");
    command->add_flag_callback("--no-per-view", [&lod] { lod.perView = false; }, "Leave the cut of each view out of the JSON");
    command->add_option("--format", lod.format, "Output format (default: from the output's extension; on a terminal text, else json)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    command->add_option("-o,--output", lod.output, "Output file, replaced only when the run succeeds (default: stdout)");
    command->add_flag("-q,--quiet", lod.quiet, "No progress messages on stderr");
    return command;
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
    CLI::App* statsCommand = addStatsCommand(app, stats, meshFileHelp);
    ClustersOptions clusters;
    CLI::App* clustersCommand = addClustersCommand(app, clusters, meshFileHelp);
    CompareOptions compare;
    CLI::App* compareCommand = addCompareCommand(app, compare, meshFileHelp);
    CheckOptions check;
    CLI::App* checkCommand = addCheckCommand(app, check, meshFileHelp);
    PartitionOptions partition;
    CLI::App* partitionCommand = addPartitionCommand(app, partition, meshFileHelp);
    LodCommandOptions lod;
    CLI::App* lodCommand = addLodCommand(app, lod, meshFileHelp);

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
