#include "Charts.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

namespace conescope {

namespace {

// A table of two named double columns, the form every vtkPlot reads.
vtkSmartPointer<vtkTable> twoColumnTable(const char* xName, const std::vector<double>& x, const char* yName,
                                         const std::vector<double>& y) {
    auto table = vtkSmartPointer<vtkTable>::New();
    vtkNew<vtkDoubleArray> xColumn;
    xColumn->SetName(xName);
    vtkNew<vtkDoubleArray> yColumn;
    yColumn->SetName(yName);
    table->AddColumn(xColumn);
    table->AddColumn(yColumn);
    table->SetNumberOfRows(vtkIdType(x.size()));
    for (size_t row = 0; row < x.size(); ++row) {
        table->SetValue(vtkIdType(row), 0, x[row]);
        table->SetValue(vtkIdType(row), 1, y[row]);
    }
    return table;
}

void setAxes(vtkChartXY* chart, const char* xTitle, const char* yTitle) {
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
}

// Fixed axis range, so a chart does not rescale as the values change.
void fixRange(vtkAxis* axis, double minimum, double maximum) {
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetRange(minimum, maximum);
}

}  // namespace

HalfAngleHistogram halfAngleHistogram(const std::vector<ClusterStatistics>& clusters, double binDegrees) {
    HalfAngleHistogram histogram;
    histogram.binDegrees = binDegrees > 0.0 ? binDegrees : 5.0;
    const size_t binCount = size_t(std::ceil(90.0 / histogram.binDegrees));
    histogram.counts.assign(binCount, 0);
    for (const ClusterStatistics& cluster : clusters) {
        if (!cluster.cullable) {
            ++histogram.uncullable;
            continue;
        }
        const size_t bin = size_t(std::max(0.0, cluster.halfAngleDegrees) / histogram.binDegrees);
        ++histogram.counts[std::min(bin, binCount - 1)];
    }
    return histogram;
}

void plotEfficiencyPerView(vtkChartXY* chart, const std::vector<ViewStatistics>& views, long currentView,
                           const std::vector<double>* pinned) {
    chart->ClearPlots();
    std::vector<double> index, efficiency;
    for (const ViewStatistics& view : views) {
        index.push_back(double(view.view));
        efficiency.push_back(view.efficiency);
    }
    // A line needs two points; an orbit not measured yet shows empty axes.
    if (views.size() >= 2) {
        vtkPlot* line = chart->AddPlot(vtkChart::LINE);
        line->SetInputData(twoColumnTable("view", index, "efficiency", efficiency), 0, 1);
        line->SetColor(40, 110, 220, 255);
        line->SetWidth(2.0);
        line->SetLabel(pinned ? "B (current)" : "efficiency");
    }
    const bool comparing = pinned && pinned->size() == views.size() && views.size() >= 2;
    if (comparing) {
        vtkPlot* line = chart->AddPlot(vtkChart::LINE);
        line->SetInputData(twoColumnTable("view", index, "A (pinned)", *pinned), 0, 1);
        line->SetColor(245, 130, 15, 255);
        line->SetWidth(2.0);
        line->SetLabel("A (pinned)");
    }
    if (currentView >= 0 && size_t(currentView) < views.size()) {
        vtkPlot* marker = chart->AddPlot(vtkChart::POINTS);
        marker->SetInputData(
            twoColumnTable("view", {index[size_t(currentView)]}, "current view", {efficiency[size_t(currentView)]}), 0, 1);
        marker->SetColor(230, 30, 200, 255);
        marker->SetWidth(8.0);
        marker->SetLabel("current view");
        if (auto* points = vtkPlotPoints::SafeDownCast(marker)) points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    }
    setAxes(chart, "orbit view", "efficiency");
    fixRange(chart->GetAxis(vtkAxis::LEFT), 0.0, 1.0);
    fixRange(chart->GetAxis(vtkAxis::BOTTOM), 0.0, std::max(1.0, double(views.size()) - 1.0));
    chart->SetShowLegend(comparing);
    chart->Modified();
}

void plotHalfAngleHistogram(vtkChartXY* chart, const std::vector<ClusterStatistics>& clusters, double binDegrees) {
    chart->ClearPlots();
    const HalfAngleHistogram histogram = halfAngleHistogram(clusters, binDegrees);
    std::vector<double> centres, counts;
    double largest = double(histogram.uncullable);
    for (size_t bin = 0; bin < histogram.counts.size(); ++bin) {
        centres.push_back((double(bin) + 0.5) * histogram.binDegrees);
        counts.push_back(double(histogram.counts[bin]));
        largest = std::max(largest, counts.back());
    }
    vtkPlot* bars = chart->AddPlot(vtkChart::BAR);
    bars->SetInputData(twoColumnTable("half-angle", centres, "cullable clusters", counts), 0, 1);
    bars->SetColor(40, 110, 220, 255);
    const double uncullableAt = 90.0 + 0.5 * histogram.binDegrees;
    vtkPlot* uncullable = chart->AddPlot(vtkChart::BAR);
    uncullable->SetInputData(
        twoColumnTable("half-angle", {uncullableAt}, "uncullable clusters", {double(histogram.uncullable)}), 0, 1);
    uncullable->SetColor(220, 90, 30, 255);
    chart->SetBarWidthFraction(0.9f);
    setAxes(chart, "cone half-angle (degrees)", "clusters");
    fixRange(chart->GetAxis(vtkAxis::BOTTOM), 0.0, 90.0 + histogram.binDegrees);
    fixRange(chart->GetAxis(vtkAxis::LEFT), 0.0, std::max(1.0, largest * 1.05));
    chart->SetShowLegend(true);
    chart->Modified();
}

vtkSmartPointer<vtkTable> levelTable(const LodStatistics& statistics) {
    auto table = vtkSmartPointer<vtkTable>::New();
    for (const char* name : {"level", "efficiency", "expected efficiency", "mean half-angle", "without a cone"}) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(name);
        table->AddColumn(column);
    }
    table->SetNumberOfRows(vtkIdType(statistics.levels.size()));
    for (size_t row = 0; row < statistics.levels.size(); ++row) {
        const LodLevelStatistics& level = statistics.levels[row];
        // A level whose clusters all lack a cone has no half-angle to show (its mean reads 0).
        const bool anyCone = level.culling.uncullableClusters < level.clusters;
        const double values[] = {double(level.level), level.culling.efficiency, level.culling.expectedEfficiency,
                                 anyCone ? level.meanHalfAngleDegrees : std::nan(""),
                                 uncullableShare(level.culling.uncullableClusters, level.clusters)};
        for (vtkIdType column = 0; column < 5; ++column) table->SetValue(vtkIdType(row), column, values[column]);
    }
    return table;
}

void plotLevels(vtkChartXY* chart, const LodStatistics* statistics) {
    chart->ClearPlots();
    const size_t levels = statistics ? statistics->levels.size() : 0;
    chart->SetTitle(levels > 0 ? "Culling by LOD level: efficiency (left axis), mean cone half-angle (right axis)"
                               : "No hierarchy built");
    if (levels > 0) {
        const vtkSmartPointer<vtkTable> table = levelTable(*statistics);
        vtkPlot* measured = chart->AddPlot(vtkChart::BAR);
        measured->SetInputData(table, 0, 1);
        measured->SetColor(40, 110, 220, 255);
        measured->SetLabel("efficiency, measured");
        vtkPlot* expected = chart->AddPlot(vtkChart::LINE);
        expected->SetInputData(table, 0, 2);
        expected->SetColor(20, 50, 120, 255);
        expected->SetWidth(2.0);
        expected->GetPen()->SetLineType(vtkPen::DASH_LINE);
        expected->SetLabel("efficiency, predicted by the cones");
        vtkPlot* coneless = chart->AddPlot(vtkChart::LINE);
        coneless->SetInputData(table, 0, 4);
        coneless->SetColor(90, 90, 90, 255);
        coneless->SetWidth(2.5);
        coneless->GetPen()->SetLineType(vtkPen::DASH_DOT_LINE);
        coneless->SetLabel("clusters without a cone (share)");
        vtkPlot* angle = chart->AddPlot(vtkChart::LINE);
        angle->SetInputData(table, 0, 3);
        angle->SetColor(230, 100, 20, 255);
        angle->SetWidth(3.0);
        angle->SetLabel("mean cone half-angle (right axis)");
        if (auto* points = vtkPlotPoints::SafeDownCast(angle)) points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
        // The angle on the right axis (bottom-right corner), in degrees.
        chart->SetPlotCorner(angle, 1);
    }
    setAxes(chart, "level (0 = finest)", "efficiency");
    chart->GetAxis(vtkAxis::RIGHT)->SetTitle("mean half-angle (degrees)");
    fixRange(chart->GetAxis(vtkAxis::LEFT), 0.0, 1.0);
    fixRange(chart->GetAxis(vtkAxis::RIGHT), 0.0, 90.0);
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    fixRange(bottom, -0.5, std::max(0.5, double(levels) - 0.5));
    // One tick per level, at the whole numbers.
    vtkNew<vtkDoubleArray> ticks;
    for (size_t level = 0; level < levels; ++level) ticks->InsertNextValue(double(level));
    bottom->SetCustomTickPositions(levels > 0 ? ticks.GetPointer() : nullptr);
    chart->SetBarWidthFraction(0.6f);
    chart->SetShowLegend(levels > 0);
    // Top left: the bars stay low there and the rising lines reach the top on the right.
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
    chart->Modified();
}

}  // namespace conescope
