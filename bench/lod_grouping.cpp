// ConeScope's grouping of clusters for LOD hierarchies (groupAdjacentClusters: grown from the
// cluster with the fewest free neighbours by the most shared border) against METIS's k-way
// partition of the cluster graph (edges weighted by shared border), which Nanite groups with. Per
// mesh and grouping: levels, build time, the share of the clusters' border kept inside groups, each
// level's efficiency and the cut's at 1 pixel. scripts/bench-lod.sh --grouping runs it on every
// CGAL mesh into bench/results/lod-grouping.md.
#include <metis.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>

#include "BenchSupport.h"
#include "core/lod/LodCut.h"
#include "io/MeshReader.h"

namespace conescope::bench {
namespace {

// Shared border edges per pair of clusters.
std::map<std::pair<uint32_t, uint32_t>, idx_t> sharedBorders(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> clusterOfEdge;
    std::map<std::pair<uint32_t, uint32_t>, idx_t> shared;
    for (size_t t = 0; t < clusterOfTriangle.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
            const auto [at, added] = clusterOfEdge.emplace(std::minmax(a, b), clusterOfTriangle[t]);
            if (!added && at->second != clusterOfTriangle[t]) ++shared[std::minmax(at->second, clusterOfTriangle[t])];
        }
    return shared;
}

// METIS_PartGraphKway into ceil(clusters / groupSize) parts, numbered densely.
std::vector<uint32_t> metisGroups(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle, size_t clusterCount,
                                  size_t groupSize) {
    std::vector<uint32_t> groups(clusterCount, 0);
    idx_t parts = idx_t((clusterCount + groupSize - 1) / groupSize);
    if (parts <= 1) return groups;
    std::vector<std::vector<std::pair<idx_t, idx_t>>> neighbours(clusterCount);
    for (const auto& [pair, edges] : sharedBorders(triangles, clusterOfTriangle)) {
        neighbours[pair.first].push_back({idx_t(pair.second), edges});
        neighbours[pair.second].push_back({idx_t(pair.first), edges});
    }
    std::vector<idx_t> xadj{0}, adjncy, weights;
    for (const auto& row : neighbours) {
        for (const auto& [c, edges] : row) adjncy.push_back(c), weights.push_back(edges);
        xadj.push_back(idx_t(adjncy.size()));
    }
    idx_t vertices = idx_t(clusterCount), constraints = 1, cut = 0;
    std::vector<idx_t> part(clusterCount, 0);
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 1;
    if (METIS_PartGraphKway(&vertices, &constraints, xadj.data(), adjncy.data(), nullptr, nullptr, weights.data(), &parts, nullptr, nullptr,
                            options, &cut, part.data()) != METIS_OK)
        throw std::runtime_error("METIS_PartGraphKway failed");
    std::map<idx_t, uint32_t> dense;  // parts METIS left empty are dropped
    for (size_t c = 0; c < clusterCount; ++c) groups[c] = dense.emplace(part[c], uint32_t(dense.size())).first->second;
    return groups;
}

// Of the border between clusters, the share inside groups: what simplification may change.
double borderInsideGroups(const LodLevel& level) {
    std::vector<uint32_t> triangles, clusterOf;
    const Mesh& mesh = level.prepared.mesh();
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t i = 1; i + 1 < mesh.faceSize(f); ++i) {
            triangles.insert(triangles.end(), {mesh.faceBegin(f)[0], mesh.faceBegin(f)[i], mesh.faceBegin(f)[i + 1]});
            clusterOf.push_back(level.clusters.partition.clusterOfFace[f]);
        }
    double inside = 0.0, all = 0.0;
    for (const auto& [pair, edges] : sharedBorders(triangles, clusterOf)) {
        all += double(edges);
        if (level.place[pair.first].group == level.place[pair.second].group) inside += double(edges);
    }
    return all > 0.0 ? inside / all : 1.0;
}

struct Row {
    std::string mesh, grouping;
    size_t triangles = 0, levels = 0;
    double seconds = 0.0, inside = 0.0, cut = 0.0, cutTriangles = 0.0;
    std::vector<double> efficiency;  // levels 1 to 3
};

Row measure(const PreparedMesh& prepared, const std::string& name, const std::string& grouping, const Settings& settings) {
    LodBuildOptions options;
    if (grouping == "metis") options.grouping = metisGroups;
    const auto start = std::chrono::steady_clock::now();
    const ClusterHierarchy hierarchy = buildClusterHierarchy(prepared, settings, options);
    Row row;
    row.mesh = name, row.grouping = grouping, row.triangles = prepared.triangles, row.levels = hierarchy.levels.size();
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const LodStatistics statistics = measureHierarchy(hierarchy, settings, LodThreshold{});
    double inside = 0.0;
    size_t grouped = 0;
    for (const LodLevel& level : hierarchy.levels)
        if (level.groups > 0) inside += borderInsideGroups(level), ++grouped;
    row.inside = grouped ? inside / double(grouped) : 1.0;
    for (size_t l = 1; l <= 3; ++l) row.efficiency.push_back(l < statistics.levels.size() ? statistics.levels[l].culling.efficiency : NAN);
    row.cut = statistics.cut.efficiency;
    row.cutTriangles = statistics.cut.meanTriangles;
    return row;
}

double geometricMean(const std::vector<double>& ratios) {
    double sum = 0.0;
    size_t count = 0;
    for (double r : ratios)
        if (r > 0.0 && std::isfinite(r)) sum += std::log(r), ++count;
    return count ? std::exp(sum / double(count)) : NAN;
}

}  // namespace
}  // namespace conescope::bench

int main(int argc, char** argv) {
    using namespace conescope;
    CLI::App app{"LOD hierarchies grouped by ConeScope's greedy grouping and by METIS"};
    std::string meshes = bench::sourceDirectory() + "/datasets/cgal-all", output;
    Settings settings;
    settings.views = 64;
    app.add_option("--meshes", meshes, "A folder of .off meshes or one file");
    app.add_option("--views", settings.views, "Orbit views");
    app.add_option("--output", output, "Markdown table (default: stdout)");
    CLI11_PARSE(app, argc, argv);
    std::vector<bench::Row> rows;
    std::vector<double> cutRatios, levelRatios, timeRatios, insideGreedy, insideMetis;
    for (const std::string& path : bench::meshFiles(meshes)) {
        try {
            const PreparedMesh prepared = prepareMesh(std::make_shared<const Mesh>(readMesh(path)), path, false);
            if (prepared.triangles < 1000) continue;  // a few clusters: nothing to group
            const bench::Row greedy = bench::measure(prepared, bench::meshName(path), "greedy", settings);
            const bench::Row metis = bench::measure(prepared, bench::meshName(path), "metis", settings);
            cutRatios.push_back(metis.cut / greedy.cut);
            levelRatios.push_back(metis.efficiency[0] / greedy.efficiency[0]);
            timeRatios.push_back(metis.seconds / greedy.seconds);
            insideGreedy.push_back(greedy.inside), insideMetis.push_back(metis.inside);
            rows.push_back(greedy), rows.push_back(metis);
        } catch (const std::exception& error) {
            std::cerr << path << ": " << error.what() << "\n";
        }
    }
    std::ostringstream text;
    text << std::fixed << std::setprecision(3);
    const auto mean = [](const std::vector<double>& values) { double s = 0.0; for (double v : values) s += v; return values.empty() ? NAN : s / double(values.size()); };
    text << rows.size() / 2 << " meshes of 1,000 triangles or more, " << settings.views << " views at distance 3, the cut at 1 pixel.\n\n"
         << "METIS over greedy, geometric mean: level 1 efficiency " << bench::geometricMean(levelRatios) << "x, the cut's "
         << bench::geometricMean(cutRatios) << "x, build time " << bench::geometricMean(timeRatios) << "x; border kept inside groups "
         << mean(insideGreedy) << " (greedy) and " << mean(insideMetis) << " (METIS) on average.\n\n"
         << "| mesh | triangles | grouping | levels | build s | border inside groups | level 1 | level 2 | level 3 | cut triangles | cut |\n"
         << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const bench::Row& row : rows)
        text << "| " << row.mesh << " | " << row.triangles << " | " << row.grouping << " | " << row.levels << " | " << row.seconds << " | "
             << row.inside << " | " << row.efficiency[0] << " | " << row.efficiency[1] << " | " << row.efficiency[2] << " | "
             << std::setprecision(0) << row.cutTriangles << std::setprecision(3) << " | " << row.cut << " |\n";
    if (output.empty()) std::cout << text.str();
    else std::ofstream(output) << text.str();
    return 0;
}
