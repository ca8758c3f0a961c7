#include "scene/SceneLegend.h"

#include <cmath>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkLegendBoxActor.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

namespace conescope {

namespace {

// Legend size in pixels.
constexpr double legendMargin = 8.0, legendWidth = 210.0, legendEntryHeight = 16.0;

// A unit square split into vertical bars, one per colour, inside a light frame so that dark colours
// stay visible on the legend's dark background. Coloured by its own cell scalars: the legend box would
// otherwise colour the entry's text with the symbol colour.
vtkSmartPointer<vtkPolyData> legendSymbol(const std::vector<Rgb>& colours) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto polygons = vtkSmartPointer<vtkCellArray>::New();
    auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scalars->SetNumberOfComponents(3);
    auto addRectangle = [&](double x0, double y0, double x1, double y1, const Rgb& colour) {
        const vtkIdType first = points->GetNumberOfPoints();
        points->InsertNextPoint(x0, y0, 0);
        points->InsertNextPoint(x1, y0, 0);
        points->InsertNextPoint(x1, y1, 0);
        points->InsertNextPoint(x0, y1, 0);
        const vtkIdType corners[4] = {first, first + 1, first + 2, first + 3};
        polygons->InsertNextCell(4, corners);
        scalars->InsertNextTuple3(std::lround(colour[0] * 255.0), std::lround(colour[1] * 255.0), std::lround(colour[2] * 255.0));
    };
    // 2D polygons are drawn in order: the frame first, the colours over it.
    addRectangle(0.0, 0.0, 1.0, 1.0, {0.85, 0.85, 0.85});
    const double inset = 0.12, width = (1.0 - 2.0 * inset) / double(colours.size());
    for (size_t i = 0; i < colours.size(); ++i)
        addRectangle(inset + i * width, inset, inset + (i + 1) * width, 1.0 - inset, colours[i]);
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetPolys(polygons);
    polyData->GetCellData()->SetScalars(scalars);
    return polyData;
}

}  // namespace

SceneLegend::SceneLegend() : actor_(vtkSmartPointer<vtkLegendBoxActor>::New()) {
    actor_->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    actor_->GetPositionCoordinate()->SetValue(legendMargin, legendMargin);
    actor_->GetPosition2Coordinate()->SetCoordinateSystemToDisplay();
    actor_->BorderOn();
    actor_->UseBackgroundOn();
    actor_->SetBackgroundColor(0.0, 0.0, 0.0);
    actor_->SetBackgroundOpacity(0.55);
    actor_->ScalarVisibilityOn();
    actor_->GetEntryTextProperty()->SetFontFamilyToArial();
    actor_->GetEntryTextProperty()->ShadowOff();
    actor_->PickableOff();
}

void SceneLegend::show(const std::vector<LegendEntry>& entries) {
    actor_->SetNumberOfEntries(int(entries.size()));
    for (size_t i = 0; i < entries.size(); ++i) {
        double white[3] = {1.0, 1.0, 1.0};  // the entry colour is the text colour
        actor_->SetEntry(int(i), legendSymbol(entries[i].colours), entries[i].label.c_str(), white);
    }
    actor_->GetPosition2Coordinate()->SetValue(legendWidth, legendEntryHeight * double(entries.size()));
    setVisible(visible_);
}

void SceneLegend::setVisible(bool visible) {
    visible_ = visible;
    actor_->SetVisibility(visible_ && actor_->GetNumberOfEntries() > 0);
}

}  // namespace conescope
