// conescope-cli batch: statistics for every mesh under some paths, into one folder (BatchCommand.cpp),
// computed by worker processes (the hidden `batch-worker` command, BatchWorker.cpp) that a crash, a
// runaway allocation or a hang cannot take the batch down with.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/SettingsOptions.h"
#include "io/StatisticsIO.h"

namespace conescope::cli {

// Exit codes of `batch` besides main's 0 (every mesh ok), 1 (the batch failed) and 2 (bad arguments).
constexpr int kExitSomeMeshesFailed = 3;  // the batch finished; some rows are errors
constexpr int kExitInterrupted = 130;     // Ctrl-C or SIGTERM: DIR holds what was done; run again to resume

struct BatchOptions {
    std::vector<std::string> paths;
    std::string output;                  // the folder
    size_t jobs = 0;                     // 0 = one worker per core
    std::string shard;                   // "I/N" or empty
    SettingsOptions run;
    std::string compare;                 // "K=V,...": A against the batch's settings, as `compare --a`
    bool compareMeshopt = false;         // compare = meshoptimizer's own pipeline
    bool granularity = false;            // also the finer records' columns (granularity's rows)
    bool lod = false;                    // also a LOD hierarchy's per-level columns (lod's levels and cut)
    StatisticsDetail detail;
    double timeoutSeconds = 0;           // per mesh; 0 = none
    long memoryLimitMiB = -1;            // per worker; -1 = physical memory / workers, 0 = none
    bool quiet = false;
};

struct BatchWorkerOptions {
    SettingsOptions run;
    std::string compare;
    bool granularity = false, lod = false;
    StatisticsDetail detail;
    long memoryLimitMiB = 0;             // only to say it in an out-of-memory row
};

// meshoptimizer's pipeline at cone weight 1: what --compare-meshopt compares against.
extern const char* const kMeshoptPipeline;

// The two subcommands on `app`; the worker's is hidden from --help.
struct BatchCommands {
    CLI::App* batch = nullptr;
    CLI::App* worker = nullptr;
};
BatchCommands addBatchCommands(CLI::App& app, BatchOptions& batch, BatchWorkerOptions& worker);

// Returns the exit code. Throws for what stops the batch before it starts (bad options, a path that
// does not exist, DIR unwritable or in use by another batch).
int runBatch(const BatchOptions& options);

// Reads jobs from stdin until it closes, replies one line each (BatchWorker.cpp says the format).
int runBatchWorker(const BatchWorkerOptions& options);

}  // namespace conescope::cli
