// conescope-bench-prepare: time and peak memory of preparing clusters + bounds for a large mesh,
// for every ConeScope builder (minimal cone) and for meshoptimizer's builder + bounds. Each
// configuration runs in its own forked child, so one's peak memory cannot hide another's: the child
// reads its peak resident size (getrusage ru_maxrss) when it starts, holding only the input mesh,
// and again at the end; the difference is what the preparation itself added at its peak. The last
// column is expectedCullRate (sum T_c (1 - sin alpha_c) / T over minimal cones), the view-independent
// quality guide, so a faster preparation can be judged by what it costs in culling.
//
//   conescope-bench-prepare [--mesh path.off] [--min-triangles N] [--only NAME...]
#include <CLI/CLI.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "BenchSupport.h"
#include "core/ClusterBounds.h"
#include "core/ClusterOptimizer.h"
#include "core/Settings.h"
#include "core/Statistics.h"
#include "io/MeshReader.h"

using namespace conescope;

namespace {

using Clock = std::chrono::steady_clock;
const MeshletLimits kLimits{64, 124};

struct Measurement {
    size_t clusters = 0;
    double seconds = 0.0;     // wall clock
    double cpuSeconds = 0.0;  // this process only: robust when other processes share the cores
    double peakMiB = 0.0;       // peak resident size when the preparation ended
    double expectedRate = 0.0;  // the view-independent guide, computed after the clock and peak were read
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

double cpuSecondsSince(std::clock_t start) { return double(std::clock() - start) / CLOCKS_PER_SEC; }

Measurement prepareConeScope(const Mesh& mesh, Builder builder) {
    Settings settings;
    settings.builder = builder;
    settings.limits = kLimits;
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition partition = buildPartition(mesh, faces, settings);
    const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
    Measurement m{bounds.count(), std::chrono::duration<double>(Clock::now() - start).count(), cpuSecondsSince(cpuStart)};
    m.peakMiB = bench::peakResidentMiB();
    m.expectedRate = expectedCullRate(mesh, faces, partition);
    return m;
}

Measurement prepareMeshopt(const Mesh& mesh, float coneWeight) {
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const bench::MeshoptClusters clusters = bench::buildMeshoptClusters(bench::fanTriangles(mesh), world, kLimits, coneWeight);
    Measurement m{clusters.count(), std::chrono::duration<double>(Clock::now() - start).count(), cpuSecondsSince(cpuStart)};
    m.peakMiB = bench::peakResidentMiB();
    const bench::MeshletTriangles triangles = bench::meshletTriangleMesh(clusters, world);
    m.expectedRate = expectedCullRate(triangles.mesh, computeFaceGeometry(triangles.mesh), meshletPartition(triangles));
    return m;
}

// Runs `work` in a child process; the child prints one table row.
template <typename Work>
bool inChild(const std::string& name, Work work) {
    std::cout << std::flush;
    const pid_t child = fork();
    if (child < 0) {
        std::perror("fork");
        return false;
    }
    if (child == 0) {
        int status = 0;
        try {
            const double before = bench::peakResidentMiB();
            const Measurement m = work();
            const double after = m.peakMiB;
            std::ostringstream row;
            row << std::fixed << std::setprecision(0) << "| " << name << " | " << m.clusters << " | " << std::setprecision(2)
                << m.seconds << " | " << m.cpuSeconds << " | " << std::setprecision(0) << before << " | " << after << " | " << after - before
                << " | " << std::setprecision(4) << m.expectedRate << " |\n";
            std::cout << row.str() << std::flush;
        } catch (const std::exception& error) {
            std::cerr << name << ": " << error.what() << "\n";
            status = 1;
        }
        _exit(status);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::string meshPath = bench::sourceDirectory() + "/datasets/cgal/armadillo.off";
    size_t minTriangles = 1000000;
    CLI::App app{"Time and peak memory of cluster + bounds preparation, one child process per builder"};
    app.add_option("--mesh", meshPath, "mesh to subdivide")->capture_default_str();
    app.add_option("--min-triangles", minTriangles, "subdivide 1->4 until at least this many triangles")->capture_default_str();
    std::vector<std::string> only;
    app.add_option("--only", only, "run only these rows: builder names and/or 'meshoptimizer' (for profiling one)");
    CLI11_PARSE(app, argc, argv);
    try {
        const Mesh mesh = bench::subdivideToAtLeast(readMesh(meshPath), minTriangles);
        std::cout << "mesh: " << meshPath << " subdivided to " << triangleCount(mesh) << " triangles, "
                  << mesh.positions.size() << " vertices; budget " << kLimits.maxVertices << "/" << kLimits.maxTriangles
                  << "; parent peak RSS " << std::fixed << std::setprecision(0) << bench::peakResidentMiB() << " MiB\n\n";
        std::cout << "| preparation | clusters | wall s | CPU s | peak RSS at start (MiB) | peak RSS at end (MiB) | added by preparation (MiB) | expected cull rate |\n"
                  << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
        auto wanted = [&](const std::string& name) { return only.empty() || std::find(only.begin(), only.end(), name) != only.end(); };
        bool ok = true;
        for (Builder builder : allBuilders())
            if (builder != Builder::File && wanted(toString(builder)))
                ok &= inChild("ConeScope " + toString(builder) + " + minimal cone + bounds",
                              [&] { return prepareConeScope(mesh, builder); });
        for (float weight : {0.25f, Settings{}.meshoptConeWeight}) {
            if (!wanted("meshoptimizer")) break;
            std::ostringstream name;
            name << "meshopt_buildMeshlets (cone_weight " << weight << ") + meshopt_computeMeshletBounds";
            ok &= inChild(name.str(), [&] { return prepareMeshopt(mesh, weight); });
        }
        return ok ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "conescope-bench-prepare: " << error.what() << "\n";
        return 1;
    }
}
