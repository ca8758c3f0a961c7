// What `stats`, `clusters` and `compare` compute for one mesh, apart from where it is printed: the
// CLI's commands, the batch's workers and the Python module call these, so each gives the same
// document and the same warnings for the same mesh and settings.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/ClusterRanking.h"
#include "core/Comparison.h"
#include "core/Pipeline.h"

namespace conescope::cli {

// The sentences a run warns of, whatever the output: inside-out or inconsistent winding left as it is
// (every number after it is wrong without looking wrong) and a cluster budget the builder missed.
// `which` (say "A: ") goes before each.
std::vector<std::string> runWarnings(const RunStatistics& run, const std::string& which = "");

// The `clusters` command's run settings: its table is about the displayed (first) cone and test only.
Settings clusterTableSettings(Settings settings);

// The `clusters` command's JSON: mesh, settings, clusters, view_count, cone, test, sort and the `top`
// worst rows (0 = all) of the displayed result by `key`.
nlohmann::json clusterTableJson(const RunStatistics& run, ClusterSortKey key, size_t top);

// prepareMesh + runComparison: what `compare` computes for a mesh read from `path` (its name is the
// statistics' mesh name). `building` hears 'A' or 'B' before each side's clusters.
ComparedRuns compareMesh(const Mesh& mesh, const std::string& path, const Settings& a, const Settings& b,
                         const Settings& shared, const ProgressCallback& progress = {},
                         const std::function<void(char side)>& building = {});

}  // namespace conescope::cli
