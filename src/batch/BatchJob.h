// One mesh of a batch, computed where it is called: in a batch worker process (BatchWorker.cpp) or in
// a Dask worker through the Python module. The mesh is read and run as `stats` runs it (and, when
// asked, compared as `compare` does); its JSON files are written whole; any failure becomes an error
// row, so one bad mesh never stops the others.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "batch/BatchInputs.h"
#include "io/BatchTable.h"

namespace conescope::cli {

struct BatchConfig {
    Settings settings;          // each row's own totals: what `stats` with the batch's options computes
    std::string compare;        // "K=V,...": A of a comparison against the settings (B), or empty
    StatisticsDetail detail;    // the tables the statistics JSON keeps
    bool granularity = false;   // also the granularity report's finer records (without a comparison)
    bool lod = false;           // also a cluster LOD hierarchy's levels and cut (at 1 pixel)
};

// The columns a batch adds on request, for its settings hash: "granularity", "lod", both or "".
std::string extraColumns(const BatchConfig& config);

// The configuration the option text makes: parseConfiguration checks `compare` before any mesh is
// read. Throws std::invalid_argument.
BatchConfig batchConfig(const Settings& settings, const std::string& compare, const StatisticsDetail& detail,
                        bool granularity = false, bool lod = false);

// Where a mesh's files go: absolute paths, empty = not written.
struct BatchJob {
    std::string path;
    std::string json;           // what `stats` writes
    std::string compareJson;    // what `compare --a COMPARE` writes (with a comparison only)
};

// The cells a worker computes: status, error and error_kind (`read`, `settings`, `memory` or `run`),
// seconds, and for an ok row the run's, the comparison's and the warnings. `testFault` (the worker's
// test hook, BatchWorker.cpp) runs after the mesh is read, where the run would, so what it does takes
// the run's way out.
BatchRow runBatchJob(const BatchConfig& config, const BatchJob& job, const std::function<void()>& testFault = {});

// The cells that say which mesh and settings a row is about: file, json, compare_json, content_hash,
// settings_hash, setting_KEY and a_options (the comparison asked for). The content hash is taken now.
BatchRow batchRowStart(const BatchMesh& mesh, const BatchConfig& config);

// For tests only: CONESCOPE_BATCH_TEST_FAULT=KIND:NAME makes the process computing a batch's rows
// (a batch worker, or a Dask worker through the Python module) misbehave on the mesh whose file is
// named NAME, after reading it, where its run would be: `crash` (SIGSEGV), `allocate` (64 MiB
// blocks, each written, until the allocator refuses), `hang` (sleeps until stopped). The action for
// `path`, or empty; only runBatchJob's callers read it, so no other command changes with it.
std::function<void()> testFaultFor(const std::string& path);

// Whether a row from the last run in `folder` can be kept for the mesh whose row starts as `start`:
// the same mesh bytes and settings, its files still there, and an outcome another try would repeat
// (an ok row, or a file that cannot be read or run; not a crash, a timeout or memory, which depend
// on the machine and the limits). The batch and the Dask batch resume by it.
bool reusableRow(const BatchRow& previous, const BatchRow& start, const std::filesystem::path& folder);

// An error row's own cells.
BatchRow errorCells(const std::string& kind, const std::string& message);

}  // namespace conescope::cli
