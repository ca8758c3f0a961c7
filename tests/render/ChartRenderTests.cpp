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

}  // namespace
}  // namespace conescope
