// Charts of cull statistics for a vtkChartXY (in a vtkContextView): efficiency per view along the
// orbit, the histogram of cone half-angles, and culling level by level of an LOD hierarchy. The
// numbers come from the core's statistics rows; the charts only bin and draw them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/Granularity.h"
#include "core/Statistics.h"
#include "core/lod/LodCut.h"
#include "scene/LabelPlacement.h"

class vtkChartXY;
class vtkTable;

namespace conescope {

// Counts of cullable clusters per half-angle bin [i*binDegrees, (i+1)*binDegrees) over [0, 90),
// and the uncullable clusters apart (their cone is a hemisphere or wider).
struct HalfAngleHistogram {
    double binDegrees = 5.0;
    std::vector<size_t> counts;      // ceil(90 / binDegrees) bins
    size_t uncullable = 0;
};
HalfAngleHistogram halfAngleHistogram(const std::vector<ClusterStatistics>& clusters, double binDegrees = 5.0);

// Replaces the chart's plots: efficiency (triangles culled / back-facing) per view as a line, and
// the current view as a marked point when currentView is a row index. Axes: view, efficiency [0, 1].
// With `pinned` (one efficiency per view of a pinned configuration A), A's curve too and a legend
// naming the two.
void plotEfficiencyPerView(vtkChartXY* chart, const std::vector<ViewStatistics>& views, long currentView = -1,
                           const std::vector<double>* pinned = nullptr);

// Replaces the chart's plots: bars of halfAngleHistogram at the bin centres, and one bar for the
// uncullable clusters past 90 degrees in another colour. Axes: half-angle (degrees), clusters.
void plotHalfAngleHistogram(vtkChartXY* chart, const std::vector<ClusterStatistics>& clusters, double binDegrees = 5.0);

// One row per level of `statistics`, in level order: "level", "efficiency" (measured over the views),
// "expected efficiency" (sum T (1 - sin alpha) / T), "mean half-angle" (degrees, triangle-weighted over
// the clusters with a cone; NaN when none has one) and "without a cone" (the share of clusters).
vtkSmartPointer<vtkTable> levelTable(const LodStatistics& statistics);

// Replaces the chart's plots: per level, the measured efficiency as bars, the expected one and the
// share of clusters without a cone as lines on the left axis [0, 1], the mean cone half-angle as a
// line on the right axis [0, 90] degrees. Null: no plots, and a title saying no hierarchy is built.
void plotLevels(vtkChartXY* chart, const LodStatistics* statistics);

// One row per granularity row, in the report's order: "bytes per cluster", "culled share" and the
// row's "record" name (a string column).
vtkSmartPointer<vtkTable> granularityTable(const GranularityReport& report);

// Where the granularity chart writes its records' names, in pixels: `points` on screen, each labelled
// with its record (`sizes`: the text's box) inside `area` of a `width` x `height` picture. A label
// covers no point, no line of the K-cone records, no other label and, but for the per-triangle
// row's own label that names it, not the ceiling at that row's height; the per-triangle and K-cone
// rows are placed first. A row with no free spot within 30 pixels is left out (its tooltip names it).
struct RecordLabel {
    size_t row = 0;
    LabelSpot spot;
};
std::vector<RecordLabel> placeRecordLabels(const std::vector<glm::dvec2>& points, const std::vector<std::string>& records,
                                           const std::vector<glm::dvec2>& sizes, const PixelBox& area, int width, int height);

// Replaces the chart's plots: culled share of all triangles (y) against bytes per cluster (x, log
// scale), one marked point per row, each labelled with its record: the one-cone records, the float
// and the compact K-cone records as two lines through 2, 4 and 8 cones, and the per-triangle row with
// a dashed line at its share, the ceiling. Null: no plots, and a title saying nothing is measured.
void plotGranularity(vtkChartXY* chart, const GranularityReport* report);

}  // namespace conescope
