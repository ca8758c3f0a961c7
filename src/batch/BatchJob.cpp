#include "batch/BatchJob.h"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <thread>
#include <new>
#include <sstream>

#include "batch/MeshRuns.h"
#include "batch/OutputFiles.h"
#include "core/Comparison.h"
#include "core/Granularity.h"
#include "io/ClusterIdFile.h"
#include "io/ComparisonIO.h"
#include "io/ClusterFiles.h"
#include "io/MeshReader.h"
#include "io/StatisticsIO.h"

namespace conescope::cli {

namespace {

std::string fileNameOf(const std::string& path) { return std::filesystem::path(path).filename().string(); }

void writeStatisticsFile(const std::string& path, const RunStatistics& run, const StatisticsDetail& detail) {
    if (!path.empty()) writeTextFileAtomically(path, statisticsJsonText(run, detail));
}

// The mesh as `stats` runs it: its totals, its warnings and its JSON.
void runStatsJob(const BatchConfig& config, const BatchJob& job, const Mesh& mesh, BatchRow& row) {
    if (config.granularity) {
        // The same run as `stats`, with the finer records on its partition and views.
        const GranularityReport report = runGranularity(mesh, withClusterIds(config.settings), fileNameOf(job.path));
        writeStatisticsFile(job.json, report.run, config.detail);
        addRunCells(row, report.run, runWarnings(report.run));
        addGranularityCells(row, report);
    } else {
        const RunStatistics run = runStatistics(mesh, withClusterIds(config.settings), fileNameOf(job.path));
        writeStatisticsFile(job.json, run, config.detail);
        addRunCells(row, run, runWarnings(run));
    }
    // The hierarchy over the same partition as its level 0, at 1 pixel (1080 pixels high, 60 degrees).
    if (config.lod) addLodCells(row, lodOfMesh(mesh, fileNameOf(job.path), withClusterIds(config.settings), LodThreshold{}));
}

// The mesh as `compare --a COMPARE` runs it: B is the batch's settings, so its side is the row's
// totals and its JSON what `stats` writes.
void runCompareJob(const BatchConfig& config, const BatchJob& job, const Mesh& mesh, BatchRow& row) {
    const Settings a = withClusterIds(parseConfiguration(config.compare, config.settings));
    const ComparedRuns runs = compareMesh(mesh, job.path, a, withClusterIds(config.settings), config.settings);
    writeStatisticsFile(job.json, runs.b, config.detail);
    if (!job.compareJson.empty()) {
        std::ostringstream text;
        writeComparisonJson(runs.a, runs.b, runs.comparison, config.detail, text);
        writeTextFileAtomically(job.compareJson, text.str());
    }
    std::vector<std::string> warnings = runWarnings(runs.b);
    const std::string budgetA = budgetMissed(runs.a.settings, runs.a.clusters, runs.a.fewestClusters);
    if (!budgetA.empty()) warnings.push_back("A: " + budgetA);
    addRunCells(row, runs.b, warnings);
    addComparisonCells(row, runs);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

BatchConfig batchConfig(const Settings& settings, const std::string& compare, const StatisticsDetail& detail, bool granularity,
                        bool lod) {
    parseConfiguration(compare, settings);
    if (granularity && !compare.empty()) throw std::invalid_argument("--granularity runs without a comparison (--compare, --compare-meshopt)");
    if (lod && !compare.empty()) throw std::invalid_argument("--lod runs without a comparison (--compare, --compare-meshopt)");
    return {settings, compare, detail, granularity, lod};
}

std::string extraColumns(const BatchConfig& config) {
    std::string extras = config.granularity ? "granularity" : "";
    if (config.lod) extras += extras.empty() ? "lod" : " lod";
    return extras;
}

BatchRow runBatchJob(const BatchConfig& config, const BatchJob& job, const std::function<void()>& testFault) {
    const auto start = std::chrono::steady_clock::now();
    BatchRow row;
    try {
        MeshFile file = readMeshFile(job.path);
        // The file builder's cluster files, on this mesh (a meshlet file may cut its polygons).
        readClusterFileOf(file.mesh, config.settings, file.notes);
        if (!config.compare.empty()) readClusterFileOf(file.mesh, parseConfiguration(config.compare, config.settings), file.notes);
        if (testFault) testFault();
        if (config.compare.empty())
            runStatsJob(config, job, file.mesh, row);
        else
            runCompareJob(config, job, file.mesh, row);
        row["status"] = "ok";
    } catch (const MeshReadError& error) {
        // The reader says "out of memory" when a file's counts ask for more than there is.
        const bool memory = std::string(error.what()).find("out of memory") != std::string::npos;
        row = errorCells(memory ? "memory" : "read", error.what());
    } catch (const std::bad_alloc&) {
        row = errorCells("memory", job.path + ": out of memory");
    } catch (const std::invalid_argument& error) {
        row = errorCells("settings", job.path + ": " + error.what());
    } catch (const std::exception& error) {
        row = errorCells("run", job.path + ": " + error.what());
    }
    row["seconds"] = csvNumber(secondsSince(start));
    return row;
}

BatchRow batchRowStart(const BatchMesh& mesh, const BatchConfig& config) {
    BatchRow row;
    row["file"] = mesh.path;
    row["json"] = mesh.json;
    if (!config.compare.empty()) row["compare_json"] = batchJsonName(mesh.canonical, ".compare");
    row["content_hash"] = contentHash(mesh.path);
    row["settings_hash"] = settingsHash(config.settings, config.compare, config.detail, extraColumns(config));
    addSettingCells(row, config.settings);
    row["a_options"] = config.compare;
    return row;
}

std::function<void()> testFaultFor(const std::string& path) {
    const char* text = std::getenv("CONESCOPE_BATCH_TEST_FAULT");
    const std::string value = text ? text : "";
    const size_t colon = value.find(':');
    if (colon == std::string::npos || std::filesystem::path(path).filename() != value.substr(colon + 1)) return {};
    const std::string kind = value.substr(0, colon);
    return [kind] {
        if (kind == "crash") std::raise(SIGSEGV);
        if (kind == "hang")
            for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
        if (kind == "allocate") {
            constexpr size_t block = size_t(64) << 20;
            std::vector<std::unique_ptr<char[]>> blocks;
            for (;;) {
                blocks.emplace_back(new char[block]);
                std::memset(blocks.back().get(), 1, block);
            }
        }
    };
}

bool reusableRow(const BatchRow& previous, const BatchRow& start, const std::filesystem::path& folder) {
    const auto cell = [&](const BatchRow& row, const std::string& key) {
        const auto found = row.find(key);
        return found == row.end() ? std::string() : found->second;
    };
    if (cell(previous, "content_hash").empty() || cell(previous, "content_hash") != cell(start, "content_hash") ||
        cell(previous, "settings_hash") != cell(start, "settings_hash"))
        return false;
    if (cell(previous, "status") == "ok") {
        for (const std::string& file : {cell(start, "json"), cell(start, "compare_json")})
            if (!file.empty() && !std::filesystem::exists(folder / file)) return false;
        return true;
    }
    const std::string kind = cell(previous, "error_kind");
    return kind == "read" || kind == "settings" || kind == "run";
}

BatchRow errorCells(const std::string& kind, const std::string& message) {
    return {{"status", "error"}, {"error_kind", kind}, {"error", message}};
}

}  // namespace conescope::cli
