// conescope-bench-prepare: time and peak memory of preparing clusters + bounds, for the optimized
// builder at each effort level (and optionally the other builders), against meshoptimizer's
// builder + bounds measured in the same run; and the whole run of `conescope-cli stats MESH
// --views 1` against reading the same file and running meshoptimizer's builder, bounds and one view.
//
// Every configuration runs `--repeat` times, each in its own forked child, so that one's peak
// memory cannot hide another's and every run starts from the same state: the child reads its peak
// resident size (getrusage ru_maxrss) when it starts, holding only the input mesh, and again at the
// end. A row gives the median and the least wall time, the median CPU time (all threads of the
// child), the largest memory added, and the median wall time as a multiple of meshoptimizer's
// median (cone weight 1) from the same run. The last column is expectedCullRate (sum T_c
// (1 - sin alpha_c) / T over minimal cones), the view-independent guide to what the time buys.
//
//   conescope-bench-prepare [--mesh FILE] [--min-triangles N] [--repeat N] [--only NAME...] [--whole-run]
#include <CLI/CLI.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "BenchSupport.h"
#include "core/ClusterBounds.h"
#include "core/ClusterOptimizer.h"
#include "core/Pipeline.h"
#include "core/Settings.h"
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
// then buildClusters: the partition, refining parts as they come, and each part's bounds (minimal
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
Measurement wholeRunConeScope(const std::string& path) {
    const Stopwatch clock;
    const Mesh mesh = readMeshFile(path).mesh;
    Settings settings;
    settings.views = 1;
    const RunStatistics run = runStatistics(mesh, settings, path);
    std::ostringstream json;
    writeStatisticsJson(run, json, {});
    return clock.stop(run.clusters);
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

// Runs `work` in a child process; the child writes its measurement into a pipe.
template <typename Work>
std::optional<Measurement> inChild(const std::string& name, Work work) {
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
        int status = 0;
        try {
            const double before = bench::peakResidentMiB();
            Measurement m = work();
            m.peakMiB -= before;
            status = write(channel[1], &m, sizeof m) == ssize_t(sizeof m) ? 0 : 1;
        } catch (const std::exception& error) {
            std::cerr << name << ": " << error.what() << "\n";
            status = 1;
        }
        _exit(status);
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

template <typename Work>
bool measure(const std::string& name, size_t repeat, Work work, std::vector<Row>& rows) {
    Row row{name, {}};
    for (size_t i = 0; i < repeat; ++i) {
        const std::optional<Measurement> m = inChild(name, work);
        if (!m) return false;
        row.runs.push_back(*m);
    }
    rows.push_back(row);
    return true;
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
             << peak << " | " << std::setprecision(2) << (referenceWall > 0.0 ? median(walls) / referenceWall : 0.0) << "x |";
        if (guide) line << " " << std::setprecision(4) << row.runs.front().expectedRate << " |";
        std::cout << line.str() << "\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string meshPath = bench::sourceDirectory() + "/datasets/cgal/armadillo.off";
    size_t minTriangles = 0, repeat = 5;
    bool wholeRun = false;
    CLI::App app{"Median time and peak memory of cluster + bounds preparation against meshoptimizer's, one child process per run"};
    app.add_option("--mesh", meshPath, "mesh to measure")->capture_default_str();
    app.add_option("--min-triangles", minTriangles, "subdivide 1->4 until at least this many triangles (0: as it is)")->capture_default_str();
    app.add_option("--repeat", repeat, "runs per configuration (the median is reported)")->capture_default_str()->check(CLI::PositiveNumber);
    std::vector<std::string> only;
    app.add_option("--only", only,
                   "rows to run: optimized-fast, optimized-balanced, optimized-best, meshlet, kmeans, meshopt, meshoptimizer");
    app.add_flag("--whole-run", wholeRun, "also time stats --views 1 against read + meshoptimizer's builder, bounds and one view");
    CLI11_PARSE(app, argc, argv);
    try {
        const Mesh mesh = minTriangles > 0 ? bench::subdivideToAtLeast(readMesh(meshPath), minTriangles) : readMesh(meshPath);
        std::cout << "mesh: " << meshPath;
        if (minTriangles > 0) std::cout << " subdivided";
        std::cout << ", " << triangleCount(mesh) << " triangles, " << mesh.positions.size() << " vertices; budget "
                  << kLimits.maxVertices << "/" << kLimits.maxTriangles << "; " << repeat << " runs each\n\n";
        auto wanted = [&](const std::string& name) { return only.empty() || std::find(only.begin(), only.end(), name) != only.end(); };
        std::vector<Row> rows;
        bool ok = true;
        for (Effort effort : allEfforts()) {
            const std::string name = "optimized-" + toString(effort);
            if (!wanted(name)) continue;
            Settings settings;
            settings.limits = kLimits;
            settings.effort = effort;
            ok &= measure("ConeScope optimized, effort " + toString(effort), repeat, [&] { return prepareConeScope(mesh, settings); }, rows);
        }
        for (Builder builder : {Builder::Meshlet, Builder::KMeans, Builder::Meshopt}) {
            if (!wanted(toString(builder))) continue;
            Settings settings;
            settings.builder = builder;
            settings.limits = kLimits;
            ok &= measure("ConeScope " + toString(builder) + " builder", repeat, [&] { return prepareConeScope(mesh, settings); }, rows);
        }
        const std::string reference = "meshoptimizer, cone weight 1";
        if (wanted("meshoptimizer")) {
            ok &= measure("meshoptimizer, cone weight 0.25", repeat, [&] { return prepareMeshopt(mesh, 0.25f); }, rows);
            ok &= measure(reference, repeat, [&] { return prepareMeshopt(mesh, 1.0f); }, rows);
        }
        printRows(rows, reference, true);
        if (wholeRun) {
            // Both read the file the CLI would: the mesh as measured, written as OFF text.
            const std::string file = (std::filesystem::temp_directory_path() / ("conescope-bench-" + std::to_string(getpid()) + ".off")).string();
            writeOff(mesh, file);
            std::vector<Row> whole;
            const std::string meshoptRun = "read + meshoptimizer builder, bounds, one view";
            ok &= measure("read + conescope-cli stats --views 1", repeat, [&] { return wholeRunConeScope(file); }, whole);
            ok &= measure(meshoptRun, repeat, [&] { return wholeRunMeshopt(file); }, whole);
            std::filesystem::remove(file);
            std::cout << "\n";
            printRows(whole, meshoptRun, false);
        }
        return ok ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "conescope-bench-prepare: " << error.what() << "\n";
        return 1;
    }
}
