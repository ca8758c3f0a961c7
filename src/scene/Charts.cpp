#include "Charts.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <vtkAxis.h>
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

}  // namespace conescope
