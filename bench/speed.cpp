// conescope-bench-speed: Google Benchmark timings of one cull pass over all clusters, per test: the
// core's scalar double cullClusters, the batched float tests at each SIMD level, and meshoptimizer's
// own float loop over meshopt_Bounds, on a real mesh and on it subdivided 1->4 to >= 1M triangles.
// After the usual output it prints ns per cluster for every cull benchmark. (Preparation times are
// conescope-bench-prepare's.)
//
//   conescope-bench-speed [--mesh=path.off] [--min-triangles=N] [google benchmark flags]
#include <benchmark/benchmark.h>

#include <cstring>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>

#include "BenchSupport.h"
#include "core/BatchCulling.h"
#include "core/ClusterBounds.h"
#include "core/Culling.h"
#include "core/MultiCones.h"
#include "core/Pipeline.h"
#include "core/Settings.h"
#include "core/Statistics.h"
#include "io/MeshReader.h"

using namespace conescope;

namespace {

std::string meshPath = bench::sourceDirectory() + "/datasets/cgal/armadillo.off";
size_t minTriangles = 1000000;
const MeshletLimits kLimits{64, 124};

// A mesh with its clusters (meshlet builder, minimal cone), their float batch, meshoptimizer's
// clusters for the same budget, and 128 orbit eyes at distance 3 to cycle through.
struct Scene {
    Mesh mesh;
    std::vector<glm::vec3> world;
    FaceGeometry faces;
    ClusterBounds bounds;
    ClusterBatch batch;
    bench::MeshoptClusters meshopt;
    std::vector<Eye> eyes;
};

std::unique_ptr<Scene> makeScene(Mesh mesh) {
    auto scene = std::make_unique<Scene>();
    scene->mesh = std::move(mesh);
    scene->world = worldPositions(scene->mesh);
    scene->faces = computeFaceGeometry(scene->mesh);
    const Partition partition = buildMeshlets(scene->mesh, scene->faces, kLimits);
    scene->bounds = computeClusterBounds(scene->mesh, scene->world, scene->faces, partition, ConeMethod::Minimal);
    scene->batch = makeClusterBatch(scene->bounds);
    scene->meshopt = bench::buildMeshoptClusters(fanTriangles(scene->mesh), scene->world, kLimits, 0.25f);
    scene->eyes = orbitViews(computeAabb(scene->world), 128, 3.0);
    return scene;
}

const Mesh& baseMesh() {
    static const Mesh mesh = readMesh(meshPath);
    return mesh;
}

const Mesh& largeMesh() {
    static const Mesh mesh = bench::subdivideToAtLeast(baseMesh(), minTriangles);
    return mesh;
}

// Scenes are built on first use, so filtering benchmarks also skips the preparation they need.
const Scene& scene(bool large) {
    static std::map<bool, std::unique_ptr<Scene>> scenes;
    auto& slot = scenes[large];
    if (!slot) slot = makeScene(large ? largeMesh() : baseMesh());
    return *slot;
}

void countClusters(benchmark::State& state, size_t clusters) {
    state.counters["clusters"] = double(clusters);
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(clusters));
}

void cullScalarCore(benchmark::State& state, bool large, CullTest test) {
    const Scene& s = scene(large);
    const CullingInput input{s.mesh, s.world, s.faces, s.bounds};
    size_t view = 0, culled = 0;
    for (auto _ : state) {
        const std::vector<uint8_t> result = cullClustersExact(input, s.eyes[view++ % s.eyes.size()], test);
        culled += result[0];
        benchmark::DoNotOptimize(result.data());
    }
    benchmark::DoNotOptimize(culled);
    countClusters(state, s.bounds.count());
}

void cullBatched(benchmark::State& state, bool large, CullTest test, SimdLevel level) {
    const Scene& s = scene(large);
    std::vector<uint8_t> culled(s.batch.count);
    size_t view = 0;
    for (auto _ : state) {
        cullBatch(s.batch, s.eyes[view++ % s.eyes.size()].position, test, culled.data(), level);
        benchmark::DoNotOptimize(culled.data());
        benchmark::ClobberMemory();
    }
    countClusters(state, s.batch.count);
}

void cullMeshoptLoop(benchmark::State& state, bool large, bool apex) {
    const Scene& s = scene(large);
    std::vector<uint8_t> culled(s.meshopt.count());
    size_t view = 0;
    for (auto _ : state) {
        const glm::vec3 eye(s.eyes[view++ % s.eyes.size()].position);
        for (size_t m = 0; m < culled.size(); ++m)
            culled[m] = (apex ? bench::meshoptApexCulls(s.meshopt.bounds[m], eye) : bench::meshoptSphereCulls(s.meshopt.bounds[m], eye)) ? 1 : 0;
        benchmark::DoNotOptimize(culled.data());
        benchmark::ClobberMemory();
    }
    countClusters(state, culled.size());
}

// One pass of the K-cone record's sub-group tests (float record, apex test per sub-group): the
// exact double test, and the batched float kernel at each SIMD level.
void cullMultiCones(benchmark::State& state, bool large, uint32_t k) {
    const Scene& s = scene(large);
    const MultiCones multi = computeMultiCones(s.mesh, s.faces, s.bounds, k);
    size_t view = 0;
    for (auto _ : state) {
        const std::vector<uint8_t> culled = cullSubGroups(s.bounds, multi, s.eyes[view++ % s.eyes.size()]);
        benchmark::DoNotOptimize(culled.data());
    }
    countClusters(state, s.bounds.count());
}

void cullMultiConesBatched(benchmark::State& state, bool large, uint32_t k, SimdLevel level) {
    const Scene& s = scene(large);
    const MultiCones multi = computeMultiCones(s.mesh, s.faces, s.bounds, k);
    const ClusterBatch batch = subGroupBatch(multi.cones, multi.apexes);
    std::vector<uint8_t> culled(batch.count);
    size_t view = 0;
    for (auto _ : state) {
        cullApexBatch(batch, s.eyes[view++ % s.eyes.size()].position, culled.data(), level);
        benchmark::DoNotOptimize(culled.data());
        benchmark::ClobberMemory();
    }
    countClusters(state, s.bounds.count());
}

// What the K-cone records add to a build: each cluster's faces split into K sub-groups with their
// cones, against the default partition's own build (buildClusters with the default settings).
void splitForKCones(benchmark::State& state, uint32_t k) {
    const Scene& s = scene(false);
    MultiCones multi;
    for (auto _ : state) benchmark::DoNotOptimize((multi = computeMultiCones(s.mesh, s.faces, s.bounds, k, s.world)).cones.data());
    state.counters["clusters_split"] = double(s.bounds.count());
    // What the split aims at: the share of triangles its cones cull over view directions.
    double expected = 0.0, triangles = 0.0;
    for (size_t g = 0; g < multi.groupCount(); ++g)
        expected += expectedCulledTriangles(multi.cones[g], multi.groupTriangles[g]), triangles += multi.groupTriangles[g];
    state.counters["expected_share"] = expected / triangles;
}

void defaultBuild(benchmark::State& state) {
    const Scene& s = scene(false);
    const PreparedMesh prepared = prepareMesh(std::make_shared<const Mesh>(s.mesh), "mesh", false);
    for (auto _ : state) benchmark::DoNotOptimize(buildClusters(prepared, Settings{}).partition.clusterCount);
}

// Console output as usual, then one line per cull benchmark in plain nanoseconds per cluster.
class PerClusterReporter : public benchmark::ConsoleReporter {
public:
    // Tabular without colour codes: the output usually goes to a file (speed.txt).
    PerClusterReporter() : ConsoleReporter(OO_Tabular) {}

    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            auto clusters = run.counters.find("clusters");
            if (run.error_occurred || clusters == run.counters.end()) continue;
            const double unit = benchmark::GetTimeUnitMultiplier(run.time_unit);
            lines_.push_back({run.benchmark_name(), run.GetAdjustedRealTime() / unit * 1e9 / clusters->second,
                              run.GetAdjustedCPUTime() / unit * 1e9 / clusters->second});
        }
    }
    void Finalize() override {
        ConsoleReporter::Finalize();
        std::ostream& out = GetOutputStream();
        out << "\nns per cluster, one cull pass over all clusters (real and CPU time / clusters; they differ when\n"
               "other processes share the cores):\n";
        out << "  " << std::left << std::setw(50) << "benchmark" << std::right << std::setw(10) << "real" << std::setw(10)
            << "cpu" << "\n";
        for (const Line& line : lines_)
            out << "  " << std::left << std::setw(50) << line.name << std::right << std::fixed << std::setprecision(3)
                << std::setw(10) << line.real << std::setw(10) << line.cpu << "\n";
    }

private:
    struct Line {
        std::string name;
        double real, cpu;
    };
    std::vector<Line> lines_;
};

// Takes --mesh=... and --min-triangles=... out of argv before Google Benchmark reads it.
void takeOwnFlags(int& argc, char** argv) {
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--mesh=", 7) == 0) meshPath = argv[i] + 7;
        else if (std::strncmp(argv[i], "--min-triangles=", 16) == 0) minTriangles = std::stoul(argv[i] + 16);
        else argv[kept++] = argv[i];
    }
    argc = kept;
}

void registerBenchmarks() {
    for (bool large : {false, true}) {
        const std::string size = large ? "large" : "mesh";
        for (CullTest test : allCullTests())
            benchmark::RegisterBenchmark(("cull/core-scalar/" + toString(test) + "/" + size).c_str(), cullScalarCore, large, test);
        for (CullTest test : allCullTests()) {
            if (!batchSupports(test)) continue;
            for (SimdLevel level : {SimdLevel::Scalar, SimdLevel::Sse2, SimdLevel::Avx2})
                if (level <= bestSimdLevel())
                    benchmark::RegisterBenchmark(("cull/batch-" + std::string(toString(level)) + "/" + toString(test) + "/" + size).c_str(),
                                                 cullBatched, large, test, level);
        }
        benchmark::RegisterBenchmark(("cull/meshoptimizer-loop/apex/" + size).c_str(), cullMeshoptLoop, large, true);
        benchmark::RegisterBenchmark(("cull/meshoptimizer-loop/meshopt-sphere/" + size).c_str(), cullMeshoptLoop, large, false);
        for (uint32_t k : {2u, 4u, 8u}) {
            benchmark::RegisterBenchmark(("cull/core-scalar/cones-" + std::to_string(k) + "/" + size).c_str(), cullMultiCones, large, k);
            for (SimdLevel level : {SimdLevel::Scalar, SimdLevel::Sse2, SimdLevel::Avx2})
                if (level <= bestSimdLevel())
                    benchmark::RegisterBenchmark(("cull/batch-" + std::string(toString(level)) + "/cones-" + std::to_string(k) + "/" + size).c_str(),
                                                 cullMultiConesBatched, large, k, level);
        }
    }
    for (uint32_t k : {2u, 4u, 8u})
        benchmark::RegisterBenchmark(("build/cones-" + std::to_string(k) + "-split/mesh").c_str(), splitForKCones, k)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
    benchmark::RegisterBenchmark("build/default-partition/mesh", defaultBuild)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
}

}  // namespace

int main(int argc, char** argv) {
    takeOwnFlags(argc, argv);
    registerBenchmarks();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    try {
        PerClusterReporter reporter;
        std::cout << "mesh: " << meshPath << ", large mesh: at least " << minTriangles << " triangles, budget "
                  << kLimits.maxVertices << "/" << kLimits.maxTriangles << ", best SIMD level: " << toString(bestSimdLevel())
                  << "\n";
        benchmark::RunSpecifiedBenchmarks(&reporter);
    } catch (const std::exception& error) {
        std::cerr << "conescope-bench-speed: " << error.what() << "\n";
        return 1;
    }
    benchmark::Shutdown();
    return 0;
}
