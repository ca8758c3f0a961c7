// conescope-cli batch: every mesh under some paths into one folder DIR: DIR/meshes/*.json (what
// `stats` writes), DIR/results.csv (a row per mesh, io/BatchTable.h) and DIR/report.html. Meshes run in
// worker processes (WorkerPool.h); rows are appended whole as they finish, and DIR/results.csv is
// rewritten in sorted order at the end, so DIR is consistent whenever the batch stops. A mesh whose
// row is there with the same content and settings hashes is skipped, so a batch run again resumes.
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <regex>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/Batch.h"
#include "batch/BatchJob.h"
#include "cli/BatchProgress.h"
#include "batch/OutputFiles.h"
#include "cli/WorkerPool.h"
#include "core/SettingsSchema.h"
#include "io/BatchReport.h"
#include "io/MeshReader.h"

namespace conescope::cli {

namespace fs = std::filesystem;

const char* const kMeshoptPipeline = "builder=meshopt,cone=meshopt,test=apex";

namespace {

volatile std::sig_atomic_t stopRequested = 0;
void requestStop(int) { stopRequested = 1; }

// SIGINT and SIGTERM set a flag the batch checks between results (no SA_RESTART: a wait returns at
// once); the previous handlers come back when the batch ends.
class StopSignals {
public:
    StopSignals() {
        stopRequested = 0;
        struct sigaction action {};
        action.sa_handler = requestStop;
        sigemptyset(&action.sa_mask);
        ::sigaction(SIGINT, &action, &previousInt_);
        ::sigaction(SIGTERM, &action, &previousTerm_);
    }
    ~StopSignals() {
        ::sigaction(SIGINT, &previousInt_, nullptr);
        ::sigaction(SIGTERM, &previousTerm_, nullptr);
    }

private:
    struct sigaction previousInt_ {}, previousTerm_ {};
};

void note(bool quiet, const std::string& message) {
    if (!quiet) std::cerr << "conescope-cli: " << message << std::endl;
}

// DIR and DIR/meshes made when missing, or why not in the batch's words (std::filesystem's own text
// names its call, not the folder's problem).
void makeOutputFolder(const fs::path& folder) {
    std::error_code error;
    for (const fs::path& path : {folder, folder / "meshes"}) {
        // The nearest part of the path that exists must be a folder.
        fs::path existing = path;
        while (!existing.empty() && !fs::exists(fs::symlink_status(existing, error)) && existing.has_parent_path() &&
               existing.parent_path() != existing)
            existing = existing.parent_path();
        const fs::file_status status = fs::status(existing, error);
        if (fs::exists(fs::symlink_status(existing, error)) && !fs::is_directory(status))
            throw std::runtime_error(folder.string() + ": cannot be the output folder: " + existing.string() +
                                     (fs::exists(status) ? " is a file, not a folder" : " is a link to nothing"));
        fs::create_directories(path, error);
        if (error) throw std::runtime_error(folder.string() + ": cannot make the output folder (" + error.message() + ")");
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw std::runtime_error(folder.string() + ": cannot write into the output folder (" + std::strerror(errno) + ")");
}

// One batch per folder at a time: a second would interleave rows. The lock goes with the process.
int lockFolder(const fs::path& folder) {
    const std::string path = (folder / ".batch.lock").string();
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error(path + ": cannot open (" + std::strerror(errno) + ")");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
        throw std::runtime_error(folder.string() + " is in use by another batch (" + path + " is locked)");
    return fd;
}

// Files a killed worker or batch was writing (OutputFiles.h names them ".NAME.partial-PID.EXT").
void removePartialFiles(const fs::path& folder) {
    static const std::regex partial(R"(\..*\.partial-[0-9]+\.(json|csv|html))");
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
        if (std::regex_match(entry.path().filename().string(), partial)) fs::remove(entry.path(), error);
}

std::string workerExecutable() {
    std::error_code error;
    const fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (error) throw std::runtime_error("cannot find the conescope-cli executable for the batch workers");
    return self.string();
}

std::vector<std::string> workerCommand(const BatchConfig& config, long memoryLimitMiB) {
    std::vector<std::string> command = {workerExecutable(), "batch-worker"};
    for (const std::string& argument : settingArguments(config.settings)) command.push_back(argument);
    if (!config.compare.empty()) command.insert(command.end(), {"--compare", config.compare});
    if (config.granularity) command.push_back("--granularity");
    if (config.lod) command.push_back("--lod");
    if (!config.detail.views) command.push_back("--no-per-view");
    if (!config.detail.clusters) command.push_back("--no-per-cluster");
    command.insert(command.end(), {"--memory-limit", std::to_string(memoryLimitMiB)});
    return command;
}

// Physical memory shared by the workers, so together they cannot push the machine into swap.
long defaultMemoryLimitMiB(size_t workers) {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return 0;
    return long(double(pages) * double(pageSize) / double(workers) / double(1 << 20));
}

bool sanitizerBuild() {
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#endif
#endif
    return false;
}

// The job's request to a worker: three NUL-terminated fields (BatchWorker.cpp).
std::string workerRequest(const BatchMesh& mesh, const BatchRow& start, const fs::path& folder) {
    const auto fileIn = [&](const char* key) {
        const auto found = start.find(key);
        return found == start.end() || found->second.empty() ? std::string() : (folder / found->second).string();
    };
    return mesh.path + '\0' + fileIn("json") + '\0' + fileIn("compare_json") + '\0';
}

// The worker's cells over the row's start; a reply that is no JSON object is the worker's failure.
BatchRow finishedRow(BatchRow row, const WorkerPool::Result& result) {
    BatchRow cells;
    if (result.replied) {
        const nlohmann::json reply = nlohmann::json::parse(result.reply, nullptr, false);
        if (reply.is_object())
            for (const auto& [key, value] : reply.items()) cells[key] = value.is_string() ? value.get<std::string>() : value.dump();
        else
            cells = errorCells("crash", row["file"] + ": the worker's reply was not understood");
    } else {
        cells = errorCells(result.failureKind, row["file"] + ": " + result.failure);
    }
    for (auto& [key, value] : cells) row[key] = value;
    return row;
}

void appendLine(int fd, const std::string& line, const std::string& path) {
    // One write per row: a row is in the file whole or not at all, whenever the batch is stopped.
    if (::write(fd, line.data(), line.size()) != ssize_t(line.size()))
        throw std::runtime_error(path + ": cannot append a row (" + std::strerror(errno) + ")");
}

struct BatchPlan {
    std::vector<BatchMesh> meshes;
    std::vector<BatchRow> rows;          // per mesh: the kept row, or the start of its new one
    std::vector<bool> done;              // per mesh: its row is final
    size_t skipped = 0;
};

BatchPlan planBatch(const BatchOptions& options, const BatchConfig& config, const fs::path& folder) {
    BatchPlan plan;
    plan.meshes = findBatchMeshes(options.paths);
    if (!options.shard.empty()) plan.meshes = meshesOfShard(plan.meshes, parseShard(options.shard));
    const BatchTable previous = readBatchCsv((folder / "results.csv").string());
    if (!previous.sameColumns) note(options.quiet, "results.csv is another version's: every mesh is run again");
    if (previous.unreadableRows > 0)
        note(options.quiet, "results.csv: " + std::to_string(previous.unreadableRows) + " lines were no row and are dropped");
    std::map<std::string, const BatchRow*> byJson;
    for (const BatchRow& row : previous.rows)
        if (row.count("json")) byJson[row.at("json")] = &row;
    for (const BatchMesh& mesh : plan.meshes) {
        BatchRow start = batchRowStart(mesh, config);
        if (!mesh.problem.empty()) {
            // Its row now, and looked at again by every run: a path problem is fixed outside the batch.
            start["content_hash"] = "";
            for (const auto& [key, value] : errorCells("read", mesh.problem)) start[key] = value;
            note(options.quiet, "error: " + mesh.problem);
            plan.rows.push_back(start);
            plan.done.push_back(true);
            continue;
        }
        const auto found = byJson.find(mesh.json);
        const bool keep = found != byJson.end() && reusableRow(*found->second, start, folder);
        plan.rows.push_back(keep ? *found->second : start);
        plan.done.push_back(keep);
        plan.skipped += keep ? 1 : 0;
    }
    return plan;
}

std::vector<BatchRow> finalRows(const BatchPlan& plan) {
    std::vector<BatchRow> rows;
    for (size_t k = 0; k < plan.rows.size(); ++k)
        if (plan.done[k]) rows.push_back(plan.rows[k]);
    return rows;
}

// results.csv in sorted order and report.html, both replaced whole.
void writeResults(const BatchPlan& plan, const fs::path& folder, const BatchConfig& config) {
    const std::vector<BatchRow> rows = finalRows(plan);
    writeTextFileAtomically((folder / "results.csv").string(), batchCsvText(rows));
    const BatchReportInfo info{fs::absolute(folder).lexically_normal().filename().string(), plan.meshes.size(), config.compare};
    writeTextFileAtomically((folder / "report.html").string(), batchReportHtml(rows, info));
}

struct BatchCounts {
    size_t ok = 0, errors = 0;
};

BatchCounts countRows(const BatchPlan& plan) {
    BatchCounts counts;
    for (size_t k = 0; k < plan.rows.size(); ++k)
        if (plan.done[k]) (plan.rows[k].at("status") == "ok" ? counts.ok : counts.errors) += 1;
    return counts;
}

// Hands the meshes still to do to the workers and records each row as it comes; stops early when
// asked to (the rows so far stay).
void runMeshes(BatchPlan& plan, const BatchOptions& options, const BatchConfig& config, const fs::path& folder) {
    std::vector<size_t> todo;
    uintmax_t bytes = 0;
    for (size_t k = 0; k < plan.meshes.size(); ++k)
        if (!plan.done[k]) todo.push_back(k), bytes += plan.meshes[k].bytes;
    if (todo.empty()) return;
    const size_t workers = std::min(todo.size(), options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency()));
    long memoryMiB = options.memoryLimitMiB < 0 ? defaultMemoryLimitMiB(workers) : options.memoryLimitMiB;
    // AddressSanitizer reserves terabytes of address space up front: no data limit can hold it.
    if (sanitizerBuild()) memoryMiB = 0;
    WorkerPool pool(workerCommand(config, memoryMiB), workers,
                    {size_t(memoryMiB) << 20, options.timeoutSeconds});
    const std::string csv = (folder / "results.csv").string();
    const int out = ::open(csv.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (out < 0) throw std::runtime_error(csv + ": cannot append (" + std::strerror(errno) + ")");
    BatchProgress progress(todo.size(), plan.skipped, bytes, options.quiet);
    size_t next = 0;
    while (!stopRequested && (next < todo.size() || pool.running() > 0)) {
        for (; next < todo.size() && pool.canTake(); ++next)
            pool.submit(todo[next], workerRequest(plan.meshes[todo[next]], plan.rows[todo[next]], folder));
        for (const WorkerPool::Result& result : pool.wait(250)) {
            BatchRow& row = plan.rows[result.job];
            row = finishedRow(row, result);
            appendLine(out, batchCsvLine(row), csv);
            plan.done[result.job] = true;
            const bool ok = row["status"] == "ok";
            progress.finished(plan.meshes[result.job].bytes, ok, fs::path(row["file"]).filename().string());
            if (!ok) {
                progress.clear();
                note(options.quiet, "error: " + row["error"]);
            }
        }
        progress.draw();
    }
    progress.draw(true);
    ::close(out);
}

}  // namespace

BatchCommands addBatchCommands(CLI::App& app, BatchOptions& batch, BatchWorkerOptions& worker) {
    BatchCommands commands;
    CLI::App* command = app.add_subcommand(
        "batch", "Statistics for every mesh under some paths: DIR/meshes/*.json, DIR/results.csv and DIR/report.html");
    commands.batch = command;
    command->add_option("paths", batch.paths, "Mesh files and folders (searched recursively for every format a reader takes)")
        ->required();
    command->add_option("-o,--output", batch.output, "The folder for the results (made when missing)")->required();
    command->add_option("-j,--jobs", batch.jobs, "Worker processes (default: one per core)")->check(CLI::PositiveNumber);
    command->add_option("--shard", batch.shard, "I/N: only every N-th mesh of the sorted list, from the I-th (job arrays)")
        ->check([](const std::string& text) -> std::string {
            try {
                parseShard(text);
                return {};
            } catch (const std::invalid_argument& error) {
                return error.what();
            }
        });
    addBuilderOptions(*command, batch.run);
    addCullingOptions(*command, batch.run);
    CLI::Option* compare = command->add_option(
        "--compare", batch.compare, "Also compare each mesh with A = these options (K=V[,K=V...] as compare's --a) on top of the others");
    command->add_flag("--compare-meshopt", batch.compareMeshopt,
                      std::string("Also compare each mesh with meshoptimizer's pipeline (") + kMeshoptPipeline + ")")
        ->excludes(compare);
    command->add_flag("--granularity", batch.granularity,
                      "Also each mesh's 2, 4 and 8 cones per cluster and per-triangle culling (granularity's rows) as columns, and their plot in the report");
    command->add_flag("--lod", batch.lod,
                      "Also each mesh's cluster LOD hierarchy (lod's levels and its cut at 1 pixel) as columns, and efficiency by level in the report");
    command->add_flag_callback("--no-per-view", [&batch] { batch.detail.views = false; }, "Leave the per-view tables out of the JSON");
    command->add_flag_callback("--no-per-cluster", [&batch] { batch.detail.clusters = false; },
                               "Leave the per-cluster tables out of the JSON");
    command->add_option("--timeout", batch.timeoutSeconds, "Seconds a mesh may take before its worker is stopped (0 = no limit)")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--memory-limit", batch.memoryLimitMiB,
                        "MiB of data each worker may allocate (0 = no limit; default: physical memory / workers)")
        ->check(CLI::NonNegativeNumber);
    command->add_flag("-q,--quiet", batch.quiet, "No progress, notes or per-mesh errors on stderr");

    CLI::App* hidden = app.add_subcommand("batch-worker", "");
    hidden->group("");  // the batch's own worker: not for people
    commands.worker = hidden;
    addBuilderOptions(*hidden, worker.run);
    addCullingOptions(*hidden, worker.run);
    hidden->add_option("--compare", worker.compare);
    hidden->add_flag("--granularity", worker.granularity);
    hidden->add_flag("--lod", worker.lod);
    hidden->add_flag_callback("--no-per-view", [&worker] { worker.detail.views = false; });
    hidden->add_flag_callback("--no-per-cluster", [&worker] { worker.detail.clusters = false; });
    hidden->add_option("--memory-limit", worker.memoryLimitMiB);
    return commands;
}

int runBatch(const BatchOptions& options) {
    if (options.run.toSettings().conesPerCluster != 1)
        throw std::invalid_argument("--cones-per-cluster: a batch measures one cone per cluster; --granularity adds its rows with 2, 4 and 8 cones");
    const BatchConfig config =
        batchConfig(options.run.toSettings(), options.compareMeshopt ? kMeshoptPipeline : options.compare, options.detail,
                    options.granularity, options.lod);
    const fs::path folder = options.output;
    makeOutputFolder(folder);
    const int lock = lockFolder(folder);
    removePartialFiles(folder);
    removePartialFiles(folder / "meshes");
    BatchPlan plan = planBatch(options, config, folder);
    // The kept rows alone first: from here on the file holds one row per mesh, whenever it stops.
    writeTextFileAtomically((folder / "results.csv").string(), batchCsvText(finalRows(plan)));
    note(options.quiet, std::to_string(plan.meshes.size()) + " meshes, " + std::to_string(plan.skipped) +
                            " skipped (done before with the same content and settings)");
    {
        // Held while the results are written too: a second Ctrl-C cannot cut them short.
        StopSignals signals;
        runMeshes(plan, options, config, folder);
        removePartialFiles(folder / "meshes");
        writeResults(plan, folder, config);
    }
    ::close(lock);
    const BatchCounts counts = countRows(plan);
    const size_t left = plan.meshes.size() - counts.ok - counts.errors;
    note(options.quiet, std::to_string(plan.meshes.size()) + " meshes: " + std::to_string(counts.ok) + " ok, " +
                            std::to_string(counts.errors) + (counts.errors == 1 ? " error, " : " errors, ") +
                            std::to_string(plan.skipped) + " skipped (already done)" +
                            (left ? ", " + std::to_string(left) + " not run" : "") + "; " + (folder / "results.csv").string() +
                            ", " + (folder / "report.html").string());
    if (left > 0) {
        std::cerr << "conescope-cli: interrupted; the same command resumes where this one stopped" << std::endl;
        return kExitInterrupted;
    }
    return counts.errors > 0 ? kExitSomeMeshesFailed : 0;
}

}  // namespace conescope::cli
