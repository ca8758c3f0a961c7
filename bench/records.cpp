// conescope-bench-records: what each test's record costs in bytes and culls, on every mesh of a
// directory, for the default partition and for meshoptimizer's meshlets (cone weight 1) at the same
// limits: efficiency, bytes per cluster, culling per byte, false culls (engine records) and
// quantisation loss, and the 16-byte octagon's culling as a share of the float octagon's. Writes
// records.md and records.csv. Every number is a `conescope-cli stats` run's (runStatistics).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "BenchSupport.h"
#include "ReportRows.h"
#include "core/Pipeline.h"
#include "io/MeshReader.h"

using namespace conescope;

namespace {

struct Measured {
    std::string mesh, partition;
    size_t clusters = 0;
    CullTestStatistics result;  // views and clusters dropped
};

std::vector<Measured> measureMesh(const std::string& path, size_t views, double distance) {
    const Mesh mesh = readMesh(path);
    std::vector<Measured> rows;
    for (Builder builder : {Builder::Optimized, Builder::Meshopt}) {
        Settings settings;
        settings.builder = builder;
        settings.tests = allCullTests();
        settings.views = views;
        settings.distance = distance;
        RunStatistics run = runStatistics(mesh, settings, bench::meshName(path));
        for (CullTestStatistics& result : run.results) {
            result.views.clear();
            result.clusters.clear();
            rows.push_back({run.meshName, toString(builder), run.clusters, std::move(result)});
        }
    }
    return rows;
}

double perByte(const CullTestStatistics& r) { return r.bytesPerCluster ? r.efficiency / double(r.bytesPerCluster) : 0.0; }

double share(size_t part, size_t whole) { return whole ? double(part) / double(whole) : 0.0; }

void writeCsv(const std::vector<Measured>& rows, const std::string& path) {
    std::ofstream out(path);
    out << "mesh,partition,clusters,test,bytes_per_cluster,efficiency,efficiency_per_byte,false_culls,engine_record,"
           "quantisation_loss_share\n";
    for (const Measured& m : rows)
        out << m.mesh << ',' << m.partition << ',' << m.clusters << ',' << toString(m.result.test) << ',' << m.result.bytesPerCluster << ','
            << m.result.efficiency << ',' << perByte(m.result) << ',' << m.result.falseCulls << ',' << m.result.engineRecord << ','
            << share(m.result.quantisationLossTriangles, m.result.backFacingTriangles) << '\n';
}

// Per test and partition: means over the meshes.
void writeTestTable(const std::vector<Measured>& rows, size_t meshes, std::ostream& md) {
    md << "| test | bytes per cluster | efficiency, default partition | per byte | efficiency, meshoptimizer's meshlets | per byte | "
          "false culls | quantisation loss |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (CullTest test : allCullTests()) {
        std::map<std::string, double> efficiency;
        size_t falseCulls = 0, bytes = 0;
        double quantisation = 0.0;
        for (const Measured& m : rows) {
            if (m.result.test != test) continue;
            efficiency[m.partition] += m.result.efficiency / double(meshes);
            falseCulls += m.result.falseCulls;
            bytes = m.result.bytesPerCluster;
            quantisation += share(m.result.quantisationLossTriangles, m.result.backFacingTriangles) / double(2 * meshes);
        }
        auto per = [&](double value) { return bytes ? report::formatNumber(100.0 * value / double(bytes), 2) + "%" : std::string("-"); };
        // The vertices test's bytes grow with the cluster's vertices: the cone's 16 and 12 per vertex.
        const std::string byteText = test == CullTest::Vertices ? "16 + 12 a vertex" : std::to_string(bytes);
        md << "| `" << toString(test) << "` | " << byteText << " | " << report::formatNumber(efficiency["optimized"], 3) << " | "
           << per(efficiency["optimized"]) << " | " << report::formatNumber(efficiency["meshopt"], 3) << " | " << per(efficiency["meshopt"])
           << " | " << falseCulls << " | " << report::formatNumber(quantisation, 4) << " |\n";
    }
}

// The compact octagon's triangles culled over the float octagon's: over all the meshes, per mesh
// (every row for a short list, else those below the goal) and the median.
void writeCompactShare(const std::vector<Measured>& rows, std::ostream& md) {
    std::map<std::pair<std::string, std::string>, std::pair<size_t, size_t>> culled;  // (mesh, partition) -> (compact, float)
    for (const Measured& m : rows) {
        if (m.result.test == CullTest::OctagonCompact) culled[{m.mesh, m.partition}].first = m.result.trianglesCulled;
        if (m.result.test == CullTest::Octagon) culled[{m.mesh, m.partition}].second = m.result.trianglesCulled;
    }
    const bool everyRow = culled.size() <= 20;
    md << (everyRow ? "" : "Below the goal of 0.97:\n\n")
       << "| mesh | partition | octagon (112 bytes) culls | octagon-compact (16 bytes) culls | share |\n|---|---|---:|---:|---:|\n";
    size_t compactTotal = 0, floatTotal = 0;
    std::vector<double> ratios;
    for (const auto& [key, pair] : culled) {
        const double ratio = pair.second ? double(pair.first) / double(pair.second) : 1.0;
        if (everyRow || ratio < 0.97)
            md << "| " << key.first << " | " << key.second << " | " << pair.second << " | " << pair.first << " | "
               << report::formatNumber(ratio, 4) << " |\n";
        compactTotal += pair.first, floatTotal += pair.second, ratios.push_back(ratio);
    }
    std::sort(ratios.begin(), ratios.end());
    md << "\nOf all the back faces the float octagon culls over these meshes, the compact one culls **"
       << report::formatNumber(share(compactTotal, floatTotal), 4) << "** (goal: 0.97 or more); per mesh and partition the median is "
       << report::formatNumber(ratios.empty() ? 1.0 : ratios[ratios.size() / 2], 4) << " and the lowest "
       << report::formatNumber(ratios.empty() ? 1.0 : ratios.front(), 4) << ".\n";
}

}  // namespace

int main(int argc, char** argv) {
    std::string meshes = bench::sourceDirectory() + "/datasets/cgal", output = bench::sourceDirectory() + "/bench/results";
    size_t views = 64;
    double distance = 3.0;
    CLI::App app{"Bytes per cluster and culling per byte of every test's record"};
    app.add_option("--meshes", meshes, "directory of .off meshes, or one mesh file")->capture_default_str();
    app.add_option("--output", output, "directory for records.md and records.csv")->capture_default_str();
    app.add_option("--views", views, "orbit views")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--distance", distance, "orbit distance in half-diagonals")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try {
        std::vector<Measured> rows;
        const std::vector<std::string> files = bench::meshFiles(meshes);
        std::vector<std::string> skipped;  // files no reader takes (CGAL's demo set has a few on purpose)
        for (size_t i = 0; i < files.size(); ++i) {
            std::cerr << "[" << i + 1 << "/" << files.size() << "] " << bench::meshName(files[i]) << std::endl;
            try {
                for (Measured& row : measureMesh(files[i], views, distance)) rows.push_back(std::move(row));
            } catch (const MeshReadError& error) {
                skipped.push_back(bench::meshName(files[i]));
                std::cerr << "  skipped: " << error.what() << std::endl;
            }
        }
        const size_t measured = files.size() - skipped.size();
        std::filesystem::create_directories(output);
        writeCsv(rows, output + "/records.csv");
        std::ofstream md(output + "/records.md");
        std::string command;
        for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(i ? argv[i] : "conescope-bench-records");
        md << "# Culling per byte of record\n\n`" << command << "`: " << measured << " meshes, " << views << " orbit views at distance "
           << distance << ", limits 64/124, the default (chosen) cone; the default partition (optimized, balanced, at meshoptimizer's count) and "
           << "meshoptimizer's own meshlets (cone weight 1). Efficiency: back faces culled / back faces, the mean over the meshes; per "
           << "byte: that over the record's bytes per cluster. False culls: summed over meshes, views and both partitions.\n\n";
        if (!skipped.empty()) {
            md << "Not read (refused by the readers): ";
            for (size_t i = 0; i < skipped.size(); ++i) md << (i ? ", " : "") << skipped[i];
            md << ".\n\n";
        }
        writeTestTable(rows, measured, md);
        md << "\n## The 16-byte octagon against the float one\n\n";
        writeCompactShare(rows, md);
        std::cerr << "wrote " << output << "/records.md and records.csv\n";
    } catch (const std::exception& error) {
        std::cerr << "conescope-bench-records: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
