// conescope-bench-prepare: time and peak memory of preparing clusters + bounds, for the optimized
// builder at each effort level (and optionally the other builders), against meshoptimizer's
// builder + bounds measured in the same run; and the whole run of `conescope-cli stats MESH
// --views 1` against reading the same file and running meshoptimizer's builder, bounds and one view.
//
// Every configuration runs `--repeat` times, each in a process of its own (this program again,
// reading the measured mesh from a temporary binary .vtk file, which readMesh gives back exactly),
// so that one's peak memory cannot hide another's and every run starts as a CLI run does: the
// child resets its peak resident size once it holds only the input mesh (bench::resetPeakResident)
// and reads it again at the end. A row gives the median and the least wall time, the median CPU
// time (all threads of the child), the largest memory added, and the median wall time as a
// multiple of meshoptimizer's median (cone weight 1) from the same run. The last column is expectedCullRate (sum T_c
// (1 - sin alpha_c) / T over minimal cones), the view-independent guide to what the time buys.
//
//   conescope-bench-prepare [--mesh FILE] [--min-triangles N] [--repeat N] [--only NAME...] [--whole-run] [--fork-only]
#include <CLI/CLI.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "BenchSupport.h"
#include "core/ClusterBounds.h"
#include "core/ClusterOptimizer.h"
#include "core/LargeArrays.h"
#include "core/Pipeline.h"
#include "core/Settings.h"
#include "core/SettingsSchema.h"
#include "core/Statistics.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"
#include "io/StatisticsIO.h"

using namespace conescope;

namespace {

using Clock = std::chrono::steady_clock;
const MeshletLimits kLimits{64, 124};

// One run, as the child measured it.
struct Measurement {
    size_t clusters = 0;
    double seconds = 0.0;       // wall clock
    double cpuSeconds = 0.0;    // this process, all its threads
    double peakMiB = 0.0;       // peak resident size when the work ended
    double expectedRate = 0.0;  // the view-independent guide, computed after the clock and peak were read
};

double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Times `work` (which returns the clusters' partition and mesh, for the guide) from here.
struct Stopwatch {
    Clock::time_point start = Clock::now();
    double cpuStart = cpuSeconds();
    Measurement stop(size_t clusters) const {
        Measurement m{clusters, std::chrono::duration<double>(Clock::now() - start).count(), cpuSeconds() - cpuStart};
        m.peakMiB = bench::peakResidentMiB();
        return m;
    }
};

// Partition of meshoptimizer's triangles by meshlet, for expectedCullRate.
Partition meshletPartition(const bench::MeshletTriangles& triangles) {
    Partition partition;
    partition.clusterCount = uint32_t(triangles.faceStarts.size() - 1);
    partition.clusterOfFace.resize(triangles.mesh.faceCount());
    for (uint32_t m = 0; m < partition.clusterCount; ++m)
        std::fill(partition.clusterOfFace.begin() + triangles.faceStarts[m], partition.clusterOfFace.begin() + triangles.faceStarts[m + 1], m);
    return partition;
}

// ConeScope's preparation as the product makes it: meshoptimizer's meshlets (where the builder
// starts there) started on another core before world positions and face geometry are computed,
// then buildClusters: the partition, refining parts as they come, and each part's bounds (chosen
// cone, its octagon, minimal sphere) and cull map as soon as the part is made. The mesh checks of
// prepareMesh are left out, as meshoptimizer makes none.
Measurement prepareConeScope(const Mesh& mesh, const Settings& settings) {
    const Stopwatch clock;
    const std::shared_ptr<const Mesh> borrowed(&mesh, [](const Mesh*) {});
    const std::shared_ptr<MeshletStream> meshlets = meshoptStartInBackground(borrowed, settings);
    PreparedMesh prepared;
    prepared.original = prepared.culled = borrowed;
    prepared.world = worldPositions(mesh);
    prepared.faces = computeFaceGeometry(mesh);
    prepared.box = computeAabb(prepared.world);
    const ClusterSet clusters = buildClusters(prepared, settings, nullptr, {}, meshlets.get());
    Measurement m = clock.stop(clusters.bounds.count());
    m.expectedRate = expectedCullRate(mesh, prepared.faces, clusters.partition);
    return m;
}

Measurement prepareMeshopt(const Mesh& mesh, float coneWeight) {
    const Stopwatch clock;
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const bench::MeshoptClusters clusters = bench::buildMeshoptClusters(fanTriangles(mesh), world, kLimits, coneWeight);
    Measurement m = clock.stop(clusters.count());
    const bench::MeshletTriangles triangles = bench::meshletTriangleMesh(clusters, world);
    m.expectedRate = expectedCullRate(triangles.mesh, computeFaceGeometry(triangles.mesh), meshletPartition(triangles));
    return m;
}

// `conescope-cli stats FILE --views 1` as the CLI runs it: read, check, prepare, one view, JSON.
// The CLI has made its options from the settings schema before it reads the mesh, as here.
Measurement wholeRunConeScope(const std::string& path) {
    settingFields();
    keepFreedMemory();  // as the CLI's main does
    const Stopwatch clock;
    const Mesh mesh = readMeshFile(path).mesh;
    Settings settings;
    settings.views = 1;
    const RunStatistics run = runStatistics(mesh, settings, path);
    const std::string json = statisticsJsonText(run);
    Measurement m = clock.stop(run.clusters);
    m.expectedRate = double(json.size());  // keeps the text; not printed
    return m;
}

// The same file read the same way, then meshoptimizer's builder (cone weight 1), bounds and its
// apex test from the same one view.
Measurement wholeRunMeshopt(const std::string& path) {
    const Stopwatch clock;
    const Mesh mesh = readMeshFile(path).mesh;
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const bench::MeshoptClusters clusters = bench::buildMeshoptClusters(fanTriangles(mesh), world, kLimits, 1.0f);
    const glm::vec3 eye(orbitViews(computeAabb(world), 1, 3.0).front().position);
    size_t culled = 0;
    for (const meshopt_Bounds& b : clusters.bounds) culled += bench::meshoptApexCulls(b, eye);
    Measurement m = clock.stop(clusters.count());
    m.expectedRate = double(culled);  // keeps the loop; not printed
    return m;
}

// One row of a table: what a child process runs, on the measured mesh or (the whole run) on the
// file written from it.
struct Configuration {
    std::string selector;  // the --only name that picks it
    std::string key;       // what the child is told to run (--run)
    std::string name;      // the row's name
    bool wholeRun;
    std::function<Measurement(const Mesh& mesh, const std::string& file)> run;
};

const std::string kReference = "meshoptimizer, cone weight 1";
const std::string kWholeReference = "read + meshoptimizer builder, bounds, one view";

std::vector<Configuration> configurations() {
    std::vector<Configuration> all;
    for (Effort effort : allEfforts()) {
        Settings settings;
        settings.limits = kLimits;
        settings.effort = effort;
        const std::string key = "optimized-" + toString(effort);
        all.push_back({key, key, "ConeScope optimized, effort " + toString(effort), false,
                       [settings](const Mesh& mesh, const std::string&) { return prepareConeScope(mesh, settings); }});
    }
    for (Builder builder : {Builder::Meshlet, Builder::KMeans, Builder::Meshopt}) {
        Settings settings;
        settings.builder = builder;
        settings.limits = kLimits;
        all.push_back({toString(builder), toString(builder), "ConeScope " + toString(builder) + " builder", false,
                       [settings](const Mesh& mesh, const std::string&) { return prepareConeScope(mesh, settings); }});
    }
    for (float coneWeight : {0.25f, 1.0f})
        all.push_back({"meshoptimizer", "meshoptimizer-" + std::to_string(coneWeight), coneWeight == 1.0f ? kReference : "meshoptimizer, cone weight 0.25",
                       false, [coneWeight](const Mesh& mesh, const std::string&) { return prepareMeshopt(mesh, coneWeight); }});
    all.push_back({"whole-run", "whole-conescope", "read + conescope-cli stats --views 1", true,
                   [](const Mesh&, const std::string& file) { return wholeRunConeScope(file); }});
    all.push_back({"whole-run", "whole-meshoptimizer", kWholeReference, true,
                   [](const Mesh&, const std::string& file) { return wholeRunMeshopt(file); }});
    return all;
}

// Runs a configuration and writes its measurement to `channel`; the exit status of the child.
int runAndReport(const Configuration& configuration, const Mesh& mesh, const std::string& file, int channel) {
    try {
        if (!bench::resetPeakResident())
            std::cerr << configuration.name << ": the peak resident size cannot be reset here; memory added counts from the "
                      << "child's start, reading its input included\n";
        const double before = bench::peakResidentMiB();
        Measurement m = configuration.run(mesh, file);
        m.peakMiB -= before;
        return write(channel, &m, sizeof m) == ssize_t(sizeof m) ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << configuration.name << ": " << error.what() << "\n";
        return 1;
    }
}

// What the children are given: the mesh as a binary .vtk file (for a new process to read), the same
// mesh as the OFF file the whole run reads, and the mesh itself when the children are only forked.
struct ChildInputs {
    std::string measured, file;
    const Mesh* mesh = nullptr;
    bool forkOnly = false;
};

// Runs a configuration in a child process, which writes its measurement into a pipe. The child is
// a new process (this program again, with --run), as a CLI run is: a forked copy of this one
// would find its memory shared with the parent, and each first write to a page the parent had used
// (freed heap, say) would be a copy-on-write fault, which with two threads running also
// interrupts the other core to flush its TLB. With forkOnly it is that forked copy (the method
// before), for comparison.
std::optional<Measurement> inChild(const Configuration& configuration, const ChildInputs& inputs) {
    int channel[2];
    if (pipe(channel) != 0) {
        std::perror("pipe");
        return std::nullopt;
    }
    std::cout << std::flush;
    const pid_t child = fork();
    if (child < 0) {
        std::perror("fork");
        return std::nullopt;
    }
    if (child == 0) {
        close(channel[0]);
        if (inputs.forkOnly) _exit(runAndReport(configuration, *inputs.mesh, inputs.file, channel[1]));
        const std::string fd = std::to_string(channel[1]);
        execl("/proc/self/exe", "conescope-bench-prepare", "--run", configuration.key.c_str(), "--measured", inputs.measured.c_str(),
              "--file", inputs.file.c_str(), "--result-fd", fd.c_str(), static_cast<char*>(nullptr));
        std::perror("exec");
        _exit(127);
    }
    close(channel[1]);
    Measurement m;
    const bool read = ::read(channel[0], &m, sizeof m) == ssize_t(sizeof m);
    close(channel[0]);
    int status = 0;
    waitpid(child, &status, 0);
    if (!read || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
    return m;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

struct Row {
    std::string name;
    std::vector<Measurement> runs;
    double medianWall() const {
        std::vector<double> walls;
        for (const Measurement& m : runs) walls.push_back(m.seconds);
        return median(walls);
    }
};

// `repeat` rounds, each running every configuration once in turn, so that the machine's drift (its
// speed moves by a few percent within minutes here) falls on all of them alike, not on whichever
// ran last. A configuration whose child fails is left out of the rows; false then.
bool measureInRounds(const std::vector<const Configuration*>& configurations, size_t repeat, const ChildInputs& inputs,
                     std::vector<Row>& rows, std::vector<Row>& whole) {
    std::vector<Row> measured;
    std::vector<bool> failed(configurations.size(), false);
    for (const Configuration* configuration : configurations) measured.push_back(Row{configuration->name, {}});
    for (size_t round = 0; round < repeat; ++round)
        for (size_t i = 0; i < configurations.size(); ++i) {
            if (failed[i]) continue;
            const std::optional<Measurement> m = inChild(*configurations[i], inputs);
            if (m) measured[i].runs.push_back(*m);
            else failed[i] = true;
        }
    for (size_t i = 0; i < configurations.size(); ++i)
        if (!failed[i]) (configurations[i]->wholeRun ? whole : rows).push_back(measured[i]);
    return std::find(failed.begin(), failed.end(), true) == failed.end();
}

// One markdown row per configuration; `reference` is the row the ratio is taken against.
void printRows(const std::vector<Row>& rows, const std::string& reference, bool guide) {
    double referenceWall = 0.0;
    for (const Row& row : rows)
        if (row.name == reference) referenceWall = row.medianWall();
    std::cout << "| " << (guide ? "preparation" : "whole run") << " | clusters | median wall s | least wall s | median CPU s | "
              << "memory added (MiB) | wall / " << reference << (guide ? " | expected cull rate |" : " |") << "\n"
              << "|---|---:|---:|---:|---:|---:|---:|" << (guide ? "---:|" : "") << "\n";
    for (const Row& row : rows) {
        std::vector<double> walls, cpus;
        double peak = 0.0;
        for (const Measurement& m : row.runs) walls.push_back(m.seconds), cpus.push_back(m.cpuSeconds), peak = std::max(peak, m.peakMiB);
        std::ostringstream line;
        line << std::fixed << "| " << row.name << " | " << row.runs.front().clusters << " | " << std::setprecision(3) << median(walls)
             << " | " << *std::min_element(walls.begin(), walls.end()) << " | " << median(cpus) << " | " << std::setprecision(0)
             << peak << " | ";
        // Without the reference row (--only left it out) there is no ratio: a dash, not 0.00x.
        if (referenceWall > 0.0) line << std::setprecision(2) << median(walls) / referenceWall << "x |";
        else line << "- |";
        if (guide) line << " " << std::setprecision(4) << row.runs.front().expectedRate << " |";
        std::cout << line.str() << "\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string meshPath = bench::sourceDirectory() + "/datasets/cgal/armadillo.off";
    size_t minTriangles = 0, repeat = 5;
    bool wholeRun = false, forkOnly = false;
    CLI::App app{"Median time and peak memory of cluster + bounds preparation against meshoptimizer's, one child process per run"};
    app.add_option("--mesh", meshPath, "mesh to measure")->capture_default_str();
    app.add_option("--min-triangles", minTriangles, "subdivide 1->4 until at least this many triangles (0: as it is)")->capture_default_str();
    app.add_option("--repeat", repeat, "runs per configuration (the median is reported)")->capture_default_str()->check(CLI::PositiveNumber);
    std::vector<std::string> only;
    app.add_option("--only", only,
                   "rows to run: optimized-fast, optimized-balanced, optimized-best, meshlet, kmeans, meshopt, meshoptimizer");
    app.add_flag("--whole-run", wholeRun, "also time stats --views 1 against read + meshoptimizer's builder, bounds and one view");
    app.add_flag("--fork-only", forkOnly,
                 "run each child as a forked copy of this process instead of a new process (the method before; for comparison)");
    // A child's side: what to run on which inputs, and where its measurement goes.
    std::string run, measured, file;
    int resultFd = -1;
    app.add_option("--run", run)->group("");
    app.add_option("--measured", measured)->group("");
    app.add_option("--file", file)->group("");
    app.add_option("--result-fd", resultFd)->group("");
    CLI11_PARSE(app, argc, argv);
    const std::vector<Configuration> all = configurations();
    if (!run.empty()) {
        for (const Configuration& configuration : all)
            if (configuration.key == run) {
                try {
                    return runAndReport(configuration, configuration.wholeRun ? Mesh() : readMesh(measured), file, resultFd);
                } catch (const std::exception& error) {
                    std::cerr << "conescope-bench-prepare: " << error.what() << "\n";
                    return 1;
                }
            }
        std::cerr << "conescope-bench-prepare: nothing called " << run << "\n";
        return 1;
    }
    ChildInputs inputs;
    inputs.forkOnly = forkOnly;
    const std::filesystem::path temporary = std::filesystem::temp_directory_path() / ("conescope-bench-" + std::to_string(getpid()));
    try {
        const Mesh mesh = minTriangles > 0 ? bench::subdivideToAtLeast(readMesh(meshPath), minTriangles) : readMesh(meshPath);
        inputs.mesh = &mesh;
        inputs.measured = temporary.string() + ".vtk";
        writePolyData(mesh, inputs.measured);
        std::cout << "mesh: " << meshPath;
        if (minTriangles > 0) std::cout << " subdivided";
        std::cout << ", " << triangleCount(mesh) << " triangles, " << mesh.positions.size() << " vertices; budget "
                  << kLimits.maxVertices << "/" << kLimits.maxTriangles << "; " << repeat << " runs each, in rounds of every configuration"
                  << (forkOnly ? ", forked children" : "") << "\n\n";
        auto wanted = [&](const Configuration& c) {
            if (c.wholeRun) return wholeRun;
            return only.empty() || std::find(only.begin(), only.end(), c.selector) != only.end();
        };
        if (wholeRun) {
            // Both read the file the CLI would: the mesh as measured, written as OFF text.
            inputs.file = temporary.string() + ".off";
            writeOff(mesh, inputs.file);
        }
        std::vector<const Configuration*> chosen;
        for (const Configuration& configuration : all)
            if (wanted(configuration)) chosen.push_back(&configuration);
        std::vector<Row> rows, whole;
        const bool ok = measureInRounds(chosen, repeat, inputs, rows, whole);
        std::filesystem::remove(inputs.measured);
        if (wholeRun) std::filesystem::remove(inputs.file);
        printRows(rows, kReference, true);
        if (wholeRun) {
            std::cout << "\n";
            printRows(whole, kWholeReference, false);
        }
        return ok ? 0 : 1;
    } catch (const std::exception& error) {
        std::error_code ignored;
        if (!inputs.measured.empty()) std::filesystem::remove(inputs.measured, ignored);
        if (!inputs.file.empty()) std::filesystem::remove(inputs.file, ignored);
        std::cerr << "conescope-bench-prepare: " << error.what() << "\n";
        return 1;
    }
}
