#include "Charts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include <vtkAxis.h>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkObjectFactory.h>
#include <vtkStringArray.h>
#include <vtkTransform2D.h>
#include <vtkVariant.h>
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
    // A short title: in the dock's small chart a longer one runs over both axes' titles, which
    // already say which axis is which.
    chart->SetTitle(levels > 0 ? "Culling by LOD level" : "No hierarchy built");
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
    chart->GetAxis(vtkAxis::RIGHT)->SetTitle("half-angle (\u00b0)");  // short: the dock's chart is low
    fixRange(chart->GetAxis(vtkAxis::LEFT), 0.0, 1.0);
    fixRange(chart->GetAxis(vtkAxis::RIGHT), 0.0, 90.0);
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    fixRange(bottom, -0.5, std::max(0.5, double(levels) - 0.5));
    // One tick per level, at the whole numbers.
    vtkNew<vtkDoubleArray> ticks;
    for (size_t level = 0; level < levels; ++level) ticks->InsertNextValue(double(level));
    bottom->SetCustomTickPositions(levels > 0 ? ticks.GetPointer() : nullptr);
    chart->SetBarWidthFraction(0.6f);
    // No legend: in the dock's small chart any corner of it covers a high bar, and above the plot it
    // takes all the height; the caption under the chart says which colour is which.
    chart->SetShowLegend(false);
    chart->Modified();
}

}  // namespace conescope

namespace conescope {

namespace {

// A K-cone record ("cones-4", "cones-4-compact"), of the compact kind or the float one.
bool isConesRecord(const std::string& record, bool compact) {
    return record.rfind("cones-", 0) == 0 && (record.find("-compact") != std::string::npos) == compact;
}

// Writes each row's "record" beside its point where placeRecordLabels puts it: vtkChartXY draws no
// labels of its own.
class PointLabels : public vtkPlot {
public:
    static PointLabels* New();
    vtkTypeMacro(PointLabels, vtkPlot);

    bool Paint(vtkContext2D* painter) override {
        vtkTable* table = GetInput();
        auto* names = table ? vtkStringArray::SafeDownCast(table->GetColumnByName("record")) : nullptr;
        if (!names || !GetScene() || !GetXAxis() || !GetYAxis()) return false;
        const bool logX = GetXAxis()->GetLogScaleActive();
        std::vector<glm::dvec2> screen;
        for (vtkIdType row = 0; row < table->GetNumberOfRows(); ++row) {
            const double x = table->GetValueByName(row, "bytes per cluster").ToDouble();
            float point[2] = {float(logX ? std::log10(x) : x), float(table->GetValueByName(row, "culled share").ToDouble())};
            painter->GetTransform()->TransformPoints(point, point, 1);
            screen.emplace_back(point[0], point[1]);
        }
        // The plot area's corners on screen: labels stay inside it.
        float area[4] = {float(GetXAxis()->GetMinimum()), float(GetYAxis()->GetMinimum()), float(GetXAxis()->GetMaximum()),
                         float(GetYAxis()->GetMaximum())};
        painter->GetTransform()->TransformPoints(area, area, 2);
        painter->PushMatrix();
        vtkNew<vtkTransform2D> identity;
        painter->SetTransform(identity);
        painter->GetTextProp()->SetFontSize(10);
        painter->GetTextProp()->SetColor(0.1, 0.1, 0.1);
        painter->GetTextProp()->SetJustificationToLeft();
        painter->GetTextProp()->SetVerticalJustificationToCentered();
        painter->GetPen()->SetColor(140, 140, 140);
        painter->GetPen()->SetWidth(1.0f);
        std::vector<std::string> records;
        std::vector<glm::dvec2> sizes;
        for (vtkIdType row = 0; row < table->GetNumberOfRows(); ++row) {
            records.push_back(names->GetValue(row));
            float bounds[4];
            painter->ComputeStringBounds(records.back(), bounds);
            sizes.emplace_back(bounds[2] + 2.0, std::max(12.0f, bounds[3]));
        }
        const PixelBox plotArea{area[0], area[1], area[2], area[3]};
        for (const RecordLabel& placed :
             placeRecordLabels(screen, records, sizes, plotArea, GetScene()->GetSceneWidth(), GetScene()->GetSceneHeight())) {
            const LabelSpot& spot = placed.spot;
            if (spot.leader) painter->DrawLine(float(spot.leaderFrom.x), float(spot.leaderFrom.y), float(spot.leaderTo.x), float(spot.leaderTo.y));
            painter->DrawString(float(spot.box.x0 + 1.0), float(0.5 * (spot.box.y0 + spot.box.y1)), records[placed.row]);
        }
        painter->PopMatrix();
        return true;
    }
};
vtkStandardNewMacro(PointLabels);

// The rows of `report` whose record passes `keep`, as a table for one plot.
vtkSmartPointer<vtkTable> rowsWhere(const GranularityReport& report, const std::function<bool(const std::string&)>& keep) {
    GranularityReport kept;
    for (const GranularityRow& row : report.rows)
        if (keep(row.record)) kept.rows.push_back(row);
    return granularityTable(kept);
}

vtkPlot* addSeries(vtkChartXY* chart, int type, vtkTable* table, const char* label, const unsigned char (&colour)[3]) {
    vtkPlot* plot = chart->AddPlot(type);
    plot->SetInputData(table, "bytes per cluster", "culled share");
    plot->SetColor(colour[0], colour[1], colour[2], 255);
    plot->SetWidth(2.0);
    plot->SetLabel(label);
    plot->SetIndexedLabels(vtkStringArray::SafeDownCast(table->GetColumnByName("record")));
    plot->SetTooltipLabelFormat("%i: %x bytes per cluster, culled share %y");
    if (auto* points = vtkPlotPoints::SafeDownCast(plot)) {
        points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
        points->SetMarkerSize(8.0);
    }
    return plot;
}

}  // namespace

std::vector<RecordLabel> placeRecordLabels(const std::vector<glm::dvec2>& points, const std::vector<std::string>& records,
                                           const std::vector<glm::dvec2>& sizes, const PixelBox& area, int width, int height) {
    LabelPlacer placer(width, height, area, 1.0, 9.0);
    for (const glm::dvec2& point : points) placer.blockBox({point.x - 5.0, point.y - 5.0, point.x + 5.0, point.y + 5.0});
    for (const bool compact : {false, true}) {
        std::vector<glm::dvec2> line;  // the K-cone records of one kind, in the report's order as the line runs
        for (size_t row = 0; row < points.size(); ++row)
            if (isConesRecord(records[row], compact)) line.push_back(points[row]);
        if (line.size() >= 2) placer.blockLine(line, 2.0);
    }
    // The per-triangle row first, off its own ceiling line (blocked before it is placed); then the
    // finer records (K cones), so that on a small chart they keep theirs.
    std::vector<size_t> order(points.size());
    for (size_t row = 0; row < order.size(); ++row) order[row] = row;
    std::stable_partition(order.begin(), order.end(), [&](size_t row) { return records[row].rfind("cones-", 0) == 0; });
    std::stable_partition(order.begin(), order.end(), [&](size_t row) { return records[row] == "triangle"; });
    std::vector<RecordLabel> placed;
    for (size_t row : order) {
        if (records[row] == "triangle") placer.blockLine({{area.x0, points[row].y}, {area.x1, points[row].y}}, 2.0);
        const std::optional<LabelSpot> spot = placer.place(points[row], {1.0, 0.0}, sizes[row], 30.0);
        if (spot) placed.push_back({row, *spot});
    }
    return placed;
}

vtkSmartPointer<vtkTable> granularityTable(const GranularityReport& report) {
    auto table = vtkSmartPointer<vtkTable>::New();
    for (const char* name : {"bytes per cluster", "culled share"}) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(name);
        table->AddColumn(column);
    }
    vtkNew<vtkStringArray> records;
    records->SetName("record");
    table->AddColumn(records);
    table->SetNumberOfRows(vtkIdType(report.rows.size()));
    for (size_t row = 0; row < report.rows.size(); ++row) {
        table->SetValue(vtkIdType(row), 0, double(report.rows[row].bytesPerCluster));
        table->SetValue(vtkIdType(row), 1, report.rows[row].culledShare);
        table->SetValue(vtkIdType(row), 2, vtkVariant(report.rows[row].record));
    }
    return table;
}

void plotGranularity(vtkChartXY* chart, const GranularityReport* report) {
    chart->ClearPlots();
    const bool shown = report && !report->rows.empty();
    // The caption under the chart says what it shows and which colour is which: the labels need the room.
    chart->SetTitle(shown ? "" : "Granularity not measured");
    double lowest = 8.0, highest = 64.0, top = 0.5, ceiling = 0.0;
    if (shown) {
        addSeries(chart, vtkChart::POINTS, rowsWhere(*report, [&](const std::string& r) { return r != "triangle" && r.rfind("cones-", 0) != 0; }),
                  "one cone per cluster", {40, 110, 220});
        addSeries(chart, vtkChart::LINE, rowsWhere(*report, [&](const std::string& r) { return isConesRecord(r, false); }), "2, 4, 8 cones (float)",
                  {230, 100, 20});
        addSeries(chart, vtkChart::LINE, rowsWhere(*report, [&](const std::string& r) { return isConesRecord(r, true); }), "2, 4, 8 cones (compact)",
                  {30, 150, 70});
        addSeries(chart, vtkChart::POINTS, rowsWhere(*report, [](const std::string& r) { return r == "triangle"; }), "per triangle",
                  {120, 40, 160});
        lowest = highest = double(report->rows.front().bytesPerCluster);
        for (const GranularityRow& row : report->rows) {
            lowest = std::min(lowest, double(row.bytesPerCluster));
            highest = std::max(highest, double(row.bytesPerCluster));
            top = std::max(top, row.culledShare);
            if (row.record == "triangle") ceiling = row.culledShare;
        }
        lowest = std::max(1.0, lowest / 1.3), highest *= 1.8;
        GranularityReport line;
        line.rows = {GranularityRow{"", size_t(lowest), 0, 0, 0, 0, ceiling}, GranularityRow{"", size_t(highest), 0, 0, 0, 0, ceiling}};
        vtkPlot* limit = addSeries(chart, vtkChart::LINE, granularityTable(line), "the ceiling: every back face", {120, 40, 160});
        limit->GetPen()->SetLineType(vtkPen::DASH_LINE);
        if (auto* points = vtkPlotPoints::SafeDownCast(limit)) points->SetMarkerStyle(vtkPlotPoints::NONE);
        vtkNew<PointLabels> labels;
        labels->SetInputData(granularityTable(*report), "bytes per cluster", "culled share");
        labels->SetLegendVisibility(false);
        chart->AddPlot(labels);
    }
    setAxes(chart, "bytes per cluster (log scale)", "culled share");
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    bottom->SetLogScale(true);
    bottom->SetBehavior(vtkAxis::FIXED);
    bottom->SetUnscaledRange(lowest, highest);
    fixRange(chart->GetAxis(vtkAxis::LEFT), 0.0, std::min(1.0, top * 1.15));
    chart->SetShowLegend(false);
    chart->Modified();
}

}  // namespace conescope
