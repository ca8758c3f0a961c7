// The per-level chart of an LOD hierarchy: its table holds the statistics' levels (count and values),
// no hierarchy gives an empty chart that says so, and the rendered picture says what the numbers say
// (each level's bar reaches its efficiency on the left axis). The picture is written to the build tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlot.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkVariant.h>
#include <vtkWindowToImageFilter.h>

#include "ElephantLod.h"
#include "scene/Charts.h"

namespace conescope {
namespace {

// The elephant's hierarchy over a small orbit: every level and the cut, as conescope-cli lod runs it.
const LodStatistics& elephantLevels() {
    static const LodStatistics statistics = testing::elephantLod(24);
    return statistics;
}

TEST(LevelChart, TableRowsAreTheLevels) {
    const LodStatistics& statistics = elephantLevels();
    ASSERT_GE(statistics.levels.size(), 3u);
    const vtkSmartPointer<vtkTable> table = levelTable(statistics);
    ASSERT_EQ(table->GetNumberOfRows(), vtkIdType(statistics.levels.size()));
    ASSERT_EQ(table->GetNumberOfColumns(), 5);
    for (size_t row = 0; row < statistics.levels.size(); ++row) {
        const LodLevelStatistics& level = statistics.levels[row];
        EXPECT_EQ(table->GetValueByName(vtkIdType(row), "level").ToDouble(), double(level.level));
        EXPECT_EQ(table->GetValueByName(vtkIdType(row), "efficiency").ToDouble(), level.culling.efficiency);
        EXPECT_EQ(table->GetValueByName(vtkIdType(row), "expected efficiency").ToDouble(), level.culling.expectedEfficiency);
        EXPECT_EQ(table->GetValueByName(vtkIdType(row), "without a cone").ToDouble(),
                  double(level.culling.uncullableClusters) / double(level.clusters));
        // Levels where no cluster has a cone have no half-angle (the statistics' mean reads 0 there).
        const double angle = table->GetValueByName(vtkIdType(row), "mean half-angle").ToDouble();
        if (level.culling.uncullableClusters == level.clusters) {
            EXPECT_TRUE(std::isnan(angle)) << "level " << row;
        } else {
            EXPECT_EQ(angle, level.meanHalfAngleDegrees);
        }
    }
    vtkNew<vtkChartXY> chart;
    plotLevels(chart, &statistics);
    EXPECT_EQ(chart->GetNumberOfPlots(), 4);
    EXPECT_EQ(chart->GetPlot(0)->GetInput()->GetNumberOfRows(), vtkIdType(statistics.levels.size()));
}

TEST(LevelChart, NoHierarchyEmptiesTheChartAndSaysSo) {
    vtkNew<vtkChartXY> chart;
    plotLevels(chart, &elephantLevels());
    plotLevels(chart, nullptr);
    EXPECT_EQ(chart->GetNumberOfPlots(), 0);
    EXPECT_EQ(std::string(chart->GetTitle()), "No hierarchy built");
    const LodStatistics empty;
    plotLevels(chart, &empty);
    EXPECT_EQ(chart->GetNumberOfPlots(), 0);
}

// Rendered, each level's bar reaches its efficiency on the left axis, within a few pixels.
TEST(LevelChart, BarsReachEachLevelsEfficiency) {
    const LodStatistics& statistics = elephantLevels();
    vtkNew<vtkContextView> view;
    view->GetRenderWindow()->SetSize(900, 500);
    view->GetRenderWindow()->SetMultiSamples(0);
    view->GetRenderWindow()->OffScreenRenderingOn();
    view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    vtkNew<vtkChartXY> chart;
    view->GetScene()->AddItem(chart);
    plotLevels(chart, &statistics);
    view->GetRenderWindow()->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view->GetRenderWindow());
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(CONESCOPE_RENDER_OUTPUT_DIR "/lod-levels-chart.png");
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();

    vtkImageData* image = grab->GetOutput();
    const int* size = image->GetDimensions();
    vtkAxis* left = chart->GetAxis(vtkAxis::LEFT);
    vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
    const double y0 = left->GetPoint1()[1], y1 = left->GetPoint2()[1];
    const double x0 = bottom->GetPoint1()[0], x1 = bottom->GetPoint2()[0];
    // The bar's blue (40, 110, 220), within a little shading.
    const auto isBar = [&](int x, int y) {
        const auto* pixel = static_cast<const unsigned char*>(image->GetScalarPointer(x, y, 0));
        return std::abs(pixel[0] - 40) < 12 && std::abs(pixel[1] - 110) < 12 && std::abs(pixel[2] - 220) < 12;
    };
    for (const LodLevelStatistics& level : statistics.levels) {
        const double centre = x0 + (double(level.level) - bottom->GetMinimum()) / (bottom->GetMaximum() - bottom->GetMinimum()) * (x1 - x0);
        // The highest bar pixel over a few columns of the bar (a line may cross one column at its top).
        int top = -1;
        for (int x = int(centre) - 6; x <= int(centre) + 6; ++x)
            for (int y = std::min(size[1] - 1, int(y1)); y >= int(y0); --y)
                if (x >= 0 && x < size[0] && isBar(x, y)) {
                    top = std::max(top, y);
                    break;
                }
        const double expected = y0 + level.culling.efficiency * (y1 - y0);
        if (level.culling.efficiency < 0.01) continue;  // a bar too low to see
        EXPECT_NEAR(double(top), expected, 4.0) << "level " << level.level << ", efficiency " << level.culling.efficiency;
    }
}

// In a chart as small as the plots dock's, the record labels cover no point, no K-cone line, no
// other label and not the ceiling, the per-triangle one included: crowded rows go without a label.
TEST(GranularityChart, RecordLabelsCoverNoPointLineLabelOrCeiling) {
    const std::vector<std::string> records = {"minimal/octagon", "minimal/aabb", "minimal/sphere", "minimal/apex",
                                              "cones-2", "cones-4", "cones-8", "cones-2-compact", "cones-4-compact",
                                              "cones-8-compact", "triangle"};
    // Screen pixels (y up) in a 460 x 120 picture whose plot area is x 40..440, y 20..100; the
    // ceiling at y 92, cones-8-compact just under it and the one-cone records crowded together.
    const std::vector<glm::dvec2> points = {{250, 30}, {180, 28}, {186, 30}, {176, 33}, {230, 50}, {270, 62},
                                            {380, 70}, {120, 50}, {160, 70}, {300, 89}, {60, 92}};
    std::vector<glm::dvec2> sizes;
    for (const std::string& record : records) sizes.emplace_back(6.0 * double(record.size()), 12.0);
    const PixelBox area{40, 20, 440, 100};
    const std::vector<RecordLabel> placed = placeRecordLabels(points, records, sizes, area, 460, 120);
    ASSERT_FALSE(placed.empty());
    EXPECT_EQ(records[placed.front().row], "triangle");  // the ceiling's own label comes first
    EXPECT_LT(placed.size(), records.size());            // the crowded ones cannot all have one
    const double ceiling = points.back().y;
    for (size_t a = 0; a < placed.size(); ++a) {
        const PixelBox& box = placed[a].spot.box;
        const std::string& record = records[placed[a].row];
        EXPECT_TRUE(box.x0 >= area.x0 && box.x1 <= area.x1 && box.y0 >= area.y0 && box.y1 <= area.y1) << record;
        for (size_t b = a + 1; b < placed.size(); ++b) EXPECT_FALSE(box.intersects(placed[b].spot.box)) << record;
        for (const glm::dvec2& point : points) EXPECT_FALSE(box.intersects({point.x - 4, point.y - 4, point.x + 4, point.y + 4})) << record;
        EXPECT_FALSE(box.y0 < ceiling && box.y1 > ceiling) << record << " lies on the ceiling";
        // Off the K-cone lines: sampled along each segment.
        for (const bool compact : {false, true}) {
            const size_t first = compact ? 7 : 4;
            for (size_t s = first; s + 1 < first + 3; ++s)
                for (double t = 0.0; t <= 1.0; t += 0.05) {
                    const glm::dvec2 along = points[s] + t * (points[s + 1] - points[s]);
                    EXPECT_FALSE(along.x > box.x0 && along.x < box.x1 && along.y > box.y0 && along.y < box.y1) << record;
                }
        }
    }
}

}  // namespace
}  // namespace conescope
