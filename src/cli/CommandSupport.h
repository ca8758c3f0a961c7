// What every subcommand shares: progress and notes on stderr, reading a mesh with its reader's notes,
// the winding warning, the output format and writing the result whole.
#pragma once

#include <string>
#include <vector>

#include "core/Pipeline.h"
#include "core/Progress.h"

namespace conescope::cli {

// Stage names on stderr, so a long run shows it is alive while stdout stays clean for the data.
ProgressCallback stderrProgress(bool quiet);
void note(bool quiet, const std::string& message);
// Warnings are for every run, --quiet or not: they say the numbers on stdout may be wrong.
void warn(const std::string& message);
std::string fileName(const std::string& path);
// The mesh, with what its reader noticed on stderr even when quiet, and the cluster files of the
// file builder in `clusterFilesOf` read onto it (io/ClusterFiles.h).
Mesh readMeshNoting(const std::string& path, bool quiet, const std::vector<Settings>& clusterFilesOf = {});
// Inconsistent or inside-out winding makes every number after it wrong without looking wrong.
void warnAboutMesh(const RunStatistics& run, bool quiet);
// Warns, even when quiet, when a cluster budget was asked for and another count made; `which`
// (say "A: ") goes before the warning.
void warnAboutBudget(const RunStatistics& run, const std::string& which = "");
// The format asked for, else the output file's (.csv, .json, .txt), else text for a person at a
// terminal and `otherwise` for a pipe or file.
std::string outputFormat(const std::string& format, const std::string& output, const std::string& otherwise);
// To stdout (output empty) or replacing the file whole.
void writeText(const std::string& output, const std::string& text);

}  // namespace conescope::cli
