// The efficiency report's rows and what is written from them: report.csv (every row), report.md
// (the summary tables) and summary.csv (per mesh, for the plot). Measuring is in report.cpp.
#pragma once

#include <string>
#include <vector>

#include "core/Partition.h"

namespace conescope::report {

// The name of meshoptimizer's own pipeline in the rows (builder and cone columns).
inline const std::string kMeshoptLoop = "meshoptimizer";

struct Row {
    std::string mesh;
    size_t triangles = 0;
    std::string builder;
    std::string coneWeight;  // meshoptimizer's cone_weight where a meshoptimizer builder made the clusters
    size_t maxVertices = 0, maxTriangles = 0;
    size_t clusters = 0;
    size_t largestVertices = 0, largestTriangles = 0;
    std::string cone, test;
    double distance = 0.0;
    double efficiency = 0.0, expectedEfficiency = 0.0;
    size_t falseCulls = 0;
    double nanosecondsPerCluster = 0.0;
    double partitionSeconds = 0.0, boundsSeconds = 0.0;

    bool withinLimits() const { return largestVertices <= maxVertices && largestTriangles <= maxTriangles; }
    std::string configuration() const { return builder + (coneWeight.empty() ? "" : " (cw " + coneWeight + ")") + " / " + cone + " / " + test; }
};

std::string formatNumber(double value, int digits);
std::string formatWeight(float weight);

struct SummaryInputs {
    std::vector<Row> rows;
    std::vector<std::string> meshes;
    std::vector<MeshletLimits> budgets;
    std::vector<double> distances;
    std::vector<std::string> weights;  // meshoptimizer cone weights measured
    size_t views = 0;
    size_t jobs = 1;
    double seconds = 0.0;
    std::string command;
};

// Every row as CSV.
void writeCsv(const std::vector<Row>& rows, const std::string& path);

// The summary: headline table at the first budget and distance 3, per-mesh tables, the plot's CSV.
void writeSummary(const SummaryInputs& in, const std::string& markdownPath, const std::string& plotCsvPath);

}  // namespace conescope::report
