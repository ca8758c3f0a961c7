// The subcommands, each taking what its options parsed. They throw on failure; main turns
// the exception into a message and an exit code.
#pragma once

#include <string>

#include "cli/SettingsOptions.h"
#include "core/lod/LodCut.h"
#include "io/StatisticsIO.h"

namespace conescope::cli {

struct StatsOptions {
    std::string mesh;
    SettingsOptions run;
    std::string format;                // "json", "csv", "text" or empty: from the output's extension, else text
                                       // on a terminal and json otherwise
    std::string output;                // empty = stdout
    StatisticsDetail detail;
    std::string table;                 // CSV: "totals", "views" or "clusters"; empty: totals on stdout, every
                                       // table into -o FILE.csv and its FILE.views.csv / FILE.clusters.csv
    bool quiet = false;
};

struct ClustersOptions {
    std::string mesh;
    SettingsOptions run;
    std::string sort = "test-loss";    // a ClusterSortKey name
    size_t top = 20;                   // 0 = every cluster
    std::string format;                // "text", "json" or "csv"; empty: from the output's extension, else text
    std::string output;                // empty = stdout
    bool quiet = false;
};

struct CompareOptions {
    std::string mesh;
    SettingsOptions run;               // the options both sides share (and start from)
    std::string a, b;                  // "K=V,K=V": what each side sets on top of them
    std::string format;                // "json", "csv", "text" or empty: as for stats
    std::string output;                // empty = stdout
    StatisticsDetail detail;           // of the `a` and `b` objects
    bool quiet = false;
};

struct CheckOptions {
    std::string mesh;
    bool fixWinding = false;
    std::string output;                // the repaired mesh; needs fixWinding
};

struct PartitionOptions {
    std::string mesh;
    SettingsOptions run;
    std::string output;                // .vtp or .vtk: the formats that keep the cluster_id array
    bool quiet = false;
};

struct LodCommandOptions {
    std::string mesh;
    SettingsOptions run;
    LodThreshold threshold;
    size_t groupSize = 8;
    uint32_t cones = 0;                // K cones per cluster measured beside the one cone (0: --cones-per-cluster's, if above 1)
    std::string hierarchy;             // a hierarchy file to read instead of building one
    std::string writeHierarchy;        // where to write the hierarchy measured
    std::string writeLevels;           // a folder for each level and the cut as meshes with cluster_id
    std::string writeLesson;           // where to write the lesson on why coarse clusters cull less (Markdown)
    long lessonLevel = -1;             // the level it compares with level 0 (-1: lodLessonCoarseLevel)
    bool perView = true;
    std::string format;                // "json", "csv", "text" or empty: as for stats
    std::string output;                // empty = stdout
    bool quiet = false;
};

struct GranularityOptions {
    std::string mesh;
    SettingsOptions run;
    std::string format;                // "json", "csv", "text" or empty: as for stats
    std::string output;                // empty = stdout
    std::string writeLesson;           // where to write the lesson on why more cones cull more (Markdown)
    bool quiet = false;
};

// Culling statistics for every requested (cone, test) as JSON, CSV or a short text summary.
void runStats(const StatsOptions& options);

// The worst clusters of the displayed (first) cone and test, ranked by options.sort.
void runClusters(const ClustersOptions& options);

// A against B on the same mesh and views: each side as `stats` writes it, and what only each culls.
void runCompare(const CompareOptions& options);

// Mesh problems as JSON on stdout; with fixWinding also the repaired mesh.
void runCheck(const CheckOptions& options);

// A cluster LOD hierarchy of the mesh: each level's culling and the cut's from every view.
void runLod(const LodCommandOptions& options);

// Every record granularity's culling and cost on the mesh's partition (core/Granularity.h).
void runGranularity(const GranularityOptions& options);
CLI::App* addGranularityCommand(CLI::App& app, GranularityOptions& options, const std::string& meshFileHelp);

// The mesh with a per-face "cluster_id" array, readable by the file builder.
void runPartition(const PartitionOptions& options);

}  // namespace conescope::cli
