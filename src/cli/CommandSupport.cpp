#include "cli/CommandSupport.h"

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include <unistd.h>

#include "batch/MeshRuns.h"
#include "batch/OutputFiles.h"
#include "io/ClusterFiles.h"
#include "io/MeshReader.h"

namespace conescope::cli {

// Stage names on stderr, so a long run shows it is alive while stdout stays clean for the data.
// A line only when the percentage or the stage changes: the builder reports every part it finishes.
ProgressCallback stderrProgress(bool quiet) {
    if (quiet) return {};
    return [lastPercent = -1, lastStage = std::string()](double fraction, const std::string& stage) mutable {
        const int percent = int(fraction * 100.0 + 0.5);
        if (percent == lastPercent && stage == lastStage) return true;
        lastPercent = percent, lastStage = stage;
        std::cerr << "conescope-cli: " << percent << "% " << stage << std::endl;
        return true;
    };
}

void note(bool quiet, const std::string& message) {
    if (!quiet) std::cerr << "conescope-cli: " << message << std::endl;
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// Warnings are for every run, --quiet or not: they say the numbers on stdout may be wrong.
void warn(const std::string& message) { std::cerr << "conescope-cli: warning: " << message << std::endl; }

// The mesh, with what its reader noticed (skipped points and lines, a converted encoding) on stderr
// even when quiet: it says what the numbers are about.
Mesh readMeshNoting(const std::string& path, bool quiet, const std::vector<Settings>& clusterFilesOf) {
    note(quiet, "reading " + path);
    MeshFile file = readMeshFile(path, stderrProgress(quiet));
    for (const Settings& settings : clusterFilesOf) {
        if (settings.builder == Builder::File && !settings.clusterFile.empty()) note(quiet, "reading " + settings.clusterFile);
        readClusterFileOf(file.mesh, settings, file.notes);
    }
    for (const std::string& readerNote : file.notes) note(false, fileName(path) + ": " + readerNote);
    return std::move(file.mesh);
}

// Inconsistent or inside-out winding makes every number after it wrong without looking wrong, and
// double-sided faces make culling nothing look like a failure of the clusters.
void warnAboutMesh(const RunStatistics& run, bool quiet) {
    const std::string warning = windingWarning(run.meshReport);
    if (!warning.empty() && run.settings.fixWinding)
        note(quiet, "--fix-winding flipped " + std::to_string(run.windingFixedFaces) + " faces (" + warning + ")");
    else if (!warning.empty())
        warn(runWarnings(run).front());
    const std::string sides = doubleSidedWarning(run.meshReport);
    if (!sides.empty()) warn(sides);
}

// A count other than the one asked for makes every comparison at that count unfair.
void warnAboutBudget(const RunStatistics& run, const std::string& which) {
    const std::string warning = budgetMissed(run.settings, run.clusters, run.fewestClusters);
    if (!warning.empty()) warn(which + warning);
}

// The format asked for, else the output file's (.csv, .json, .txt), else text for a person at a
// terminal and `otherwise` for a pipe or file.
std::string outputFormat(const std::string& format, const std::string& output, const std::string& otherwise) {
    if (!format.empty()) return format;
    if (hasExtension(output, {".csv"})) return "csv";
    if (hasExtension(output, {".json"})) return "json";
    if (hasExtension(output, {".txt"})) return "text";
    return output.empty() && isatty(fileno(stdout)) ? "text" : otherwise;
}

void writeText(const std::string& output, const std::string& text) {
    if (output.empty()) {
        std::cout << text << std::flush;
        if (!std::cout) throw std::runtime_error("cannot write to standard output");
    } else {
        writeTextFileAtomically(output, text);
    }
}

}  // namespace conescope::cli
