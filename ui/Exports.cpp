#include "Exports.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include "io/ClusterIdFile.h"
#include "io/ComparisonIO.h"
#include "io/GranularityIO.h"
#include "io/LodIO.h"
#include "io/MeshWriter.h"
#include "io/StatisticsIO.h"

namespace conescope {

StatisticsFormat statisticsFormatOf(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return extension == ".csv" ? StatisticsFormat::Csv : StatisticsFormat::Json;
}

namespace {

void writeFile(const std::string& file, const std::function<void(std::ostream&)>& content) {
    std::ofstream out(file, std::ios::binary);
    if (!out) throw std::runtime_error(file + ": cannot open for writing");
    content(out);
    out.close();
    if (!out) throw std::runtime_error(file + ": write failed");
}

}  // namespace

RunStatistics exportStatistics(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                               const std::string& path, StatisticsFormat format, const ProgressCallback& progress) {
    // A run whose settings make the clusters stale builds them again, reading a cluster file anew.
    RunStatistics run = measureRun(prepared, clusters, withClusterIds(settings), progress);
    if (format == StatisticsFormat::Csv) {
        for (const auto& [table, file] : csvTableFiles(path))
            writeFile(file, [&run, table = table](std::ostream& out) { writeStatisticsCsv(run, out, table); });
    } else {
        writeFile(path, [&run](std::ostream& out) { writeStatisticsJson(run, out); });
    }
    return run;
}

void exportLodStatistics(const LodStatistics& statistics, const Settings& settings, const std::string& path, StatisticsFormat format) {
    writeFile(path, [&](std::ostream& out) {
        if (format == StatisticsFormat::Csv) writeLodCsv(statistics, out);
        else out << lodStatisticsToJson(statistics, settings).dump(2) << "\n";
    });
}

void exportGranularity(const GranularityReport& report, const std::string& path, StatisticsFormat format) {
    writeFile(path, [&](std::ostream& out) {
        if (format == StatisticsFormat::Csv) writeGranularityCsv(report, out);
        else out << granularityToJson(report).dump(2) << "\n";
    });
}

Comparison exportComparison(const PreparedMesh& prepared, const ClusterConfiguration& a, const ClusterConfiguration& b,
                            const std::string& path, StatisticsFormat format, const ProgressCallback& progress) {
    // Each side as `stats` with its settings would write it, then the diff: what runCompare writes.
    const RunStatistics runA = measureRun(prepared, a.clusters, a.settings, progressWithin(progress, 0.0, 0.4));
    const RunStatistics runB = measureRun(prepared, b.clusters, b.settings, progressWithin(progress, 0.4, 0.8));
    const Comparison comparison =
        compareClusterSets(prepared, a, b, viewsFor(b.settings, prepared.box), progressWithin(progress, 0.8, 1.0));
    writeFile(path, [&](std::ostream& out) {
        if (format == StatisticsFormat::Csv)
            writeComparisonCsv(comparison, out);
        else
            writeComparisonJson(runA, runB, comparison, StatisticsDetail{}, out);
    });
    return comparison;
}

void exportPartition(const PreparedMesh& prepared, const ClusterSet& clusters, CullTest test, const EyeMeasurement* eye,
                     const std::string& path) {
    std::map<std::string, std::vector<double>> arrays = partitionFaceArrays(prepared, clusters, test);
    if (eye) arrays.merge(eyeFaceArrays(prepared, clusters, *eye));
    writePolyData(prepared.mesh(), path, arrays);
}

void saveRenderWindowPng(vtkRenderWindow* window, const std::string& path) {
    vtkNew<vtkWindowToImageFilter> capture;
    capture->SetInput(window);
    capture->SetInputBufferTypeToRGB();
    capture->ReadFrontBufferOff();
    capture->Update();
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputConnection(capture->GetOutputPort());
    writer->Write();
    if (writer->GetErrorCode() != 0 || !std::filesystem::exists(path) || std::filesystem::file_size(path) == 0)
        throw std::runtime_error(path + ": cannot write the PNG");
}

}  // namespace conescope
