// conescope-bench-report: cull efficiency of every builder, cone and test on a set of meshes, next
// to meshoptimizer's own pipeline run in the same process. Writes report.csv (every row),
// report.md (the summary) and summary.csv (per mesh, for the plot) into the output directory.
//
// Work is shared as far as it can be: face geometry once per mesh, a partition once per
// (builder, budget), bounds once per (partition, cone), and views once per distance.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "BenchSupport.h"
#include "ReportRows.h"
#include "core/ClusterBounds.h"
#include "core/Culling.h"
#include "core/ExpectedCull.h"
#include "core/Pipeline.h"
#include "core/Settings.h"
#include "core/Statistics.h"
#include "io/MeshReader.h"

using namespace conescope;
using namespace conescope::report;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Progress lines on stderr, whole lines at a time (meshes may be measured on several threads).
void progress(const std::string& line) {
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    std::cerr << line << std::endl;
}

struct Options {
    std::string meshes;
    std::string output;
    bool quick = false;
    size_t views = 128;
    size_t jobs = 1;
};

// A mesh as the pipeline's first stage holds it (core/Pipeline.h), with the orbits measured on it.
struct MeshData {
    std::string name;
    PreparedMesh prepared;
    std::map<double, std::vector<Eye>> views;  // by distance
    const Mesh& mesh() const { return prepared.mesh(); }
};

// Largest cluster, in distinct vertices and fan triangles.
void recordClusterSizes(const ClusterBounds& bounds, Row& row) {
    for (size_t c = 0; c < bounds.count(); ++c) {
        row.largestVertices = std::max<size_t>(row.largestVertices, bounds.vertexStarts[c + 1] - bounds.vertexStarts[c]);
        row.largestTriangles = std::max<size_t>(row.largestTriangles, bounds.triangles[c]);
    }
}

// Every ConeScope builder (all but File) at one budget: partition, bounds per cone, every test and distance.
// Builders that take a cluster count are compared at `comparedCount`, the count meshoptimizer's
// builder reached at the same limits (cone weight 1): smaller clusters cull more for free, so
// partitions are only compared at equal counts. k-means is asked for it; the optimized builder runs
// at its default budget, which is that count (asked explicitly it would search longer, as
// `--clusters` does, and this report measures the default). The others choose their own count.
void measureConeScope(const MeshData& data, const MeshletLimits& limits, size_t comparedCount, std::vector<Row>& rows) {
    Settings settings;
    settings.limits = limits;
    for (Builder builder : allBuilders()) {
        if (builder == Builder::File) continue;
        settings.builder = builder;
        settings.clusterCount = builder == Builder::KMeans ? comparedCount : 0;
        const std::string what = "  " + data.name + " " + std::to_string(limits.maxVertices) + "/" +
                                 std::to_string(limits.maxTriangles) + " " + toString(builder) + ": ";
        Partition partition;
        const auto partitionStart = Clock::now();
        try {
            partition = buildPartition(data.mesh(), data.prepared.faces, settings);
        } catch (const std::exception& error) {
            progress(what + "skipped (" + error.what() + ")");
            continue;
        }
        const double partitionSeconds = secondsSince(partitionStart);
        const auto measureStart = Clock::now();
        bool oracleDone = false;
        for (ConeMethod cone : allConeMethods()) {
            const auto boundsStart = Clock::now();
            const ClusterBounds bounds =
                computeClusterBounds(data.mesh(), data.prepared.world, data.prepared.faces, partition, cone, settings.sphere);
            const double boundsSeconds = secondsSince(boundsStart);
            const CullingInput input{data.mesh(), data.prepared.world, data.prepared.faces, bounds};
            Row base;
            base.mesh = data.name;
            base.triangles = data.prepared.triangles;
            base.builder = toString(builder);
            if (builder == Builder::Meshopt) base.coneWeight = formatWeight(settings.meshoptConeWeight);
            base.maxVertices = limits.maxVertices;
            base.maxTriangles = limits.maxTriangles;
            base.clusters = partition.clusterCount;
            base.partitionSeconds = partitionSeconds;
            base.boundsSeconds = boundsSeconds;
            recordClusterSizes(bounds, base);
            for (CullTest test : allCullTests()) {
                // The oracle reads faces only: the same for every cone, so it is measured once.
                if (test == CullTest::Oracle && oracleDone) continue;
                for (const auto& [distance, views] : data.views) {
                    const CullTestStatistics statistics = measureCulling(input, views, test);
                    Row row = base;
                    row.cone = test == CullTest::Oracle ? "-" : toString(cone);
                    row.test = toString(test);
                    row.distance = distance;
                    row.efficiency = statistics.efficiency;
                    row.expectedEfficiency = test == CullTest::Oracle ? 0.0 : statistics.expectedEfficiency;
                    row.falseCulls = statistics.falseCulls;
                    row.nanosecondsPerCluster = statistics.nanosecondsPerCluster;
                    rows.push_back(row);
                }
                oracleDone |= test == CullTest::Oracle;
            }
        }
        progress(what + std::to_string(partition.clusterCount) + " clusters in " + formatNumber(partitionSeconds, 2) +
                 " s, every cone, test and distance in " + formatNumber(secondsSince(measureStart), 1) + " s");
    }
}

// meshoptimizer's pipeline as its documentation shows it, judged by the same per-face oracle.
// Returns its cluster count.
size_t measureMeshopt(const MeshData& data, const MeshletLimits& limits, float coneWeight, std::vector<Row>& rows) {
    const std::vector<unsigned int> indices = fanTriangles(data.mesh());
    const auto start = Clock::now();
    const bench::MeshoptClusters clusters = bench::buildMeshoptClusters(indices, data.prepared.world, limits, coneWeight);
    const double seconds = secondsSince(start);
    const bench::MeshletTriangles triangles = bench::meshletTriangleMesh(clusters, data.prepared.world);
    const FaceGeometry faces = computeFaceGeometry(triangles.mesh);
    const size_t count = clusters.count();

    Row base;
    base.mesh = data.name;
    base.triangles = data.prepared.triangles;
    base.builder = kMeshoptLoop;
    base.coneWeight = formatWeight(coneWeight);
    base.maxVertices = limits.maxVertices;
    base.maxTriangles = limits.maxTriangles;
    base.clusters = count;
    base.partitionSeconds = seconds;  // meshopt_buildMeshlets + meshopt_computeMeshletBounds
    base.cone = kMeshoptLoop;
    double expected = 0.0;
    for (size_t m = 0; m < count; ++m) {
        const meshopt_Meshlet& meshlet = clusters.meshlets[m];
        base.largestVertices = std::max<size_t>(base.largestVertices, meshlet.vertex_count);
        base.largestTriangles = std::max<size_t>(base.largestTriangles, meshlet.triangle_count);
        if (clusters.bounds[m].cone_cutoff < 1.0f)  // its cutoff is sin(alpha)
            expected += expectedCulledTriangles(meshlet.triangle_count, clusters.bounds[m].cone_cutoff);
    }
    base.expectedEfficiency = triangles.mesh.faceCount() ? expected / double(triangles.mesh.faceCount()) : 0.0;
    progress("  " + data.name + " " + std::to_string(limits.maxVertices) + "/" + std::to_string(limits.maxTriangles) +
             " meshoptimizer cw " + formatWeight(coneWeight) + ": " + std::to_string(count) + " meshlets + bounds in " +
             formatNumber(seconds, 2) + " s");

    struct Totals {
        size_t culledBack = 0, back = 0, falseCulls = 0;
        double nanoseconds = 0.0;
    };
    std::vector<uint8_t> culled(count);
    for (const auto& [distance, views] : data.views) {
        Totals apex, sphere;
        for (const Eye& eye : views) {
            const std::vector<Facing> facing = classifyFaces(triangles.mesh, triangles.mesh.positions, faces, eye);
            std::vector<uint32_t> front(count, 0), back(count, 0);
            size_t backTotal = 0;
            for (size_t m = 0; m < count; ++m)
                for (uint32_t f = triangles.faceStarts[m]; f < triangles.faceStarts[m + 1]; ++f) {
                    front[m] += facing[f] == Facing::Front;
                    back[m] += facing[f] == Facing::Back;
                }
            for (size_t m = 0; m < count; ++m) backTotal += back[m];
            const glm::vec3 eyePosition(eye.position);
            auto run = [&](auto culls, Totals& totals) {
                const auto start = Clock::now();
                for (size_t m = 0; m < count; ++m) culled[m] = culls(clusters.bounds[m], eyePosition) ? 1 : 0;
                totals.nanoseconds += std::chrono::duration<double, std::nano>(Clock::now() - start).count();
                totals.back += backTotal;
                for (size_t m = 0; m < count; ++m) {
                    if (!culled[m]) continue;
                    totals.culledBack += back[m];
                    totals.falseCulls += front[m] > 0;
                }
            };
            run(bench::meshoptApexCulls, apex);
            run(bench::meshoptSphereCulls, sphere);
        }
        for (auto [test, totals] : {std::pair{toString(CullTest::Apex), apex}, std::pair{toString(CullTest::MeshoptSphere), sphere}}) {
            Row row = base;
            row.test = test;
            row.distance = distance;
            row.efficiency = totals.back ? double(totals.culledBack) / double(totals.back) : 1.0;
            row.falseCulls = totals.falseCulls;
            row.nanosecondsPerCluster = count && !views.empty() ? totals.nanoseconds / double(count * views.size()) : 0.0;
            rows.push_back(row);
        }
    }
    return count;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    options.meshes = bench::sourceDirectory() + "/datasets/cgal";
    options.output = bench::sourceDirectory() + "/bench/results";
    CLI::App app{"Cull efficiency of every ConeScope builder, cone and test against meshoptimizer's pipeline"};
    app.add_option("--meshes", options.meshes, "directory of .off meshes, or one mesh file")->capture_default_str();
    app.add_option("--output", options.output, "directory for report.csv, report.md and summary.csv")->capture_default_str();
    app.add_flag("--quick", options.quick, "one budget (64/124) and one distance (3): a short run for CI");
    app.add_option("--views", options.views, "orbit views per distance")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--jobs", options.jobs, "meshes measured at the same time, one thread each")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    CLI11_PARSE(app, argc, argv);

    const auto start = Clock::now();
    try {
        std::vector<MeshletLimits> budgets = {{64, 124}, {128, 256}, {32, 64}};
        std::vector<double> distances = {1.5, 3.0, 10.0};
        if (options.quick) budgets.resize(1), distances = {3.0};
        std::vector<float> weights = {0.25f};
        if (Settings{}.meshoptConeWeight != 0.25f) weights.push_back(Settings{}.meshoptConeWeight);

        SummaryInputs summary;
        summary.budgets = budgets;
        summary.distances = distances;
        summary.views = options.views;
        for (float w : weights) summary.weights.push_back(formatWeight(w));
        for (int i = 0; i < argc; ++i) summary.command += (i ? " " : "") + std::string(i ? argv[i] : "conescope-bench-report");

        const std::vector<std::string> files = bench::meshFiles(options.meshes);
        // Meshes are independent: `jobs` threads take them in turn; rows are merged in file order.
        std::vector<std::vector<Row>> rowsPerMesh(files.size());
        std::vector<std::exception_ptr> failures(files.size());
        std::atomic<size_t> next{0};
        auto work = [&] {
            for (size_t i; (i = next++) < files.size();) {
                try {
                    MeshData data;
                    data.name = bench::meshName(files[i]);
                    data.prepared = prepareMesh(std::make_shared<const Mesh>(readMesh(files[i])), files[i], false);
                    for (double d : distances) data.views[d] = orbitViews(data.prepared.box, options.views, d);
                    progress("[" + std::to_string(i + 1) + "/" + std::to_string(files.size()) + "] " + data.name + ": " +
                             std::to_string(data.prepared.triangles) + " triangles (" + formatNumber(secondsSince(start), 0) +
                             " s elapsed)");
                    for (const MeshletLimits& limits : budgets) {
                        // The last weight is the settings' default (1.0), the stronger baseline.
                        size_t meshoptCount = 0;
                        for (float w : weights) meshoptCount = measureMeshopt(data, limits, w, rowsPerMesh[i]);
                        measureConeScope(data, limits, meshoptCount, rowsPerMesh[i]);
                    }
                } catch (...) {
                    failures[i] = std::current_exception();
                }
            }
        };
        std::vector<std::thread> threads;
        for (size_t j = 1; j < options.jobs; ++j) threads.emplace_back(work);
        work();
        for (std::thread& thread : threads) thread.join();
        for (size_t i = 0; i < files.size(); ++i) {
            if (failures[i]) std::rethrow_exception(failures[i]);
            summary.meshes.push_back(bench::meshName(files[i]));
            summary.rows.insert(summary.rows.end(), rowsPerMesh[i].begin(), rowsPerMesh[i].end());
        }
        summary.seconds = secondsSince(start);
        summary.jobs = options.jobs;
        std::filesystem::create_directories(options.output);
        writeCsv(summary.rows, options.output + "/report.csv");
        writeSummary(summary, options.output + "/report.md", options.output + "/summary.csv");
        std::cerr << "wrote " << summary.rows.size() << " rows to " << options.output << "/report.csv, the summary to "
                  << options.output << "/report.md in " << formatNumber(summary.seconds, 1) << " s\n";
    } catch (const std::exception& error) {
        std::cerr << "conescope-bench-report: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
