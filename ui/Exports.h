// What the window writes to files: cull statistics in the CLI's format (runStatistics with the
// window's settings, then StatisticsIO), the partition as a mesh with per-face arrays, and PNG
// screenshots of a render window.
#pragma once

#include <string>

#include "core/Comparison.h"
#include "core/Granularity.h"
#include "core/Pipeline.h"
#include "core/lod/LodCut.h"

class vtkRenderWindow;

namespace conescope {

enum class StatisticsFormat { Json, Csv };

// ".csv" (any case) is CSV, everything else JSON, like `conescope-cli stats -o`.
StatisticsFormat statisticsFormatOf(const std::string& path);

// The run's statistics from the window's stages (measureRun) with `settings` (their eye set for one
// eye, unset for the orbit), written as `format` (CSV: the totals at `path`, the views and clusters
// beside it, csvTableFiles): what runStatistics on the mesh as read would give.
// Throws std::runtime_error naming the path when it cannot be written, OperationCancelled when
// `progress` cancels.
RunStatistics exportStatistics(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                               const std::string& path, StatisticsFormat format, const ProgressCallback& progress = {});

// A (pinned) against B as `conescope-cli compare` writes it: JSON with `a` and `b` as measureRun
// gives each (`a.settings` with B's views) and the `diff` of compareClusterSets over B's views; CSV
// its per-view table. Returns the comparison. Throws as exportStatistics.
Comparison exportComparison(const PreparedMesh& prepared, const ClusterConfiguration& a, const ClusterConfiguration& b,
                            const std::string& path, StatisticsFormat format, const ProgressCallback& progress = {});

// A LOD hierarchy's statistics (measureHierarchy with `settings`) as `conescope-cli lod` writes them
// with the same settings (io/LodIO.h): JSON with `levels` and `cut`, or its CSV. Throws as exportStatistics.
void exportLodStatistics(const LodStatistics& statistics, const Settings& settings, const std::string& path, StatisticsFormat format);

// A granularity report as `conescope-cli granularity` writes it (io/GranularityIO.h): JSON with its
// `rows`, or one CSV row per record. Throws as exportStatistics.
void exportGranularity(const GranularityReport& report, const std::string& path, StatisticsFormat format);

// The culled mesh with cluster_id and the per-cluster cone and bound arrays per face
// (partitionFaceArrays, cull_fraction for `test`), through writePolyData: .vtp or .vtk keep the
// arrays, and the `file` builder reads cluster_id back. Throws MeshWriteError.
// With an eye's measurement, also what happened to each face from that eye (eyeFaceArrays: culled,
// back_facing, loss), for ParaView and the like.
void exportPartition(const PreparedMesh& prepared, const ClusterSet& clusters, CullTest test, const EyeMeasurement* eye,
                     const std::string& path);

// The window's current picture as PNG (vtkWindowToImageFilter, back buffer re-rendered).
// Throws std::runtime_error naming the path when it cannot be written.
void saveRenderWindowPng(vtkRenderWindow* window, const std::string& path);

}  // namespace conescope
