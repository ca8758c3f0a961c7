#include "scene/SceneLegend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkPropAssembly.h>
#include <vtkProperty2D.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkUnsignedCharArray.h>

namespace conescope {

namespace {

// Sizes in pixels. The swatch sits left of its label with a gap; a colour bar is as wide as a short
// sentence, so its colours can be told apart.
constexpr double legendMargin = 8.0, legendPadding = 6.0, rowHeight = 18.0;
constexpr double swatchWidth = 22.0, swatchHeight = 12.0, swatchGap = 8.0, barWidth = 150.0;
constexpr int labelFontSize = 13, scaleFontSize = 12;
const Rgb frameColour{0.85, 0.85, 0.85};  // around every swatch, so dark colours show on the dark box

vtkSmartPointer<vtkTextProperty> textProperty(int fontSize) {
    auto property = vtkSmartPointer<vtkTextProperty>::New();
    property->SetFontFamilyToArial();
    property->SetFontSize(fontSize);
    property->SetColor(1.0, 1.0, 1.0);
    property->ShadowOff();
    property->SetJustificationToLeft();
    property->SetVerticalJustificationToCentered();
    return property;
}

// The text's size in pixels as a text actor draws it in a window of 72 dpi (VTK's default).
std::array<double, 2> textSize(const std::string& text, vtkTextProperty* property) {
    int box[4] = {0, 0, 0, 0};
    vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
    if (renderer && renderer->GetBoundingBox(property, text, box, 72)) return {double(box[1] - box[0] + 1), double(box[3] - box[2] + 1)};
    return {0.6 * property->GetFontSize() * double(text.size()), double(property->GetFontSize())};
}

std::string scaleText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

unsigned char byte(double component) { return static_cast<unsigned char>(std::lround(std::clamp(component, 0.0, 1.0) * 255.0)); }

vtkSmartPointer<vtkActor2D> actorOf(vtkPolyData* data) {
    vtkNew<vtkPolyDataMapper2D> mapper;
    mapper->SetInputData(data);
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    auto actor = vtkSmartPointer<vtkActor2D>::New();
    actor->SetMapper(mapper);
    actor->PickableOff();
    return actor;
}

vtkSmartPointer<vtkPolyData> emptyColoured() {
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(vtkSmartPointer<vtkPoints>::New());
    data->SetPolys(vtkSmartPointer<vtkCellArray>::New());
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    data->GetCellData()->SetScalars(colours);
    return data;
}

// A rectangle of one colour; 2D polygons are drawn in the order they were added.
void addRectangle(vtkPolyData* data, const SceneLegend::Rectangle& r, const Rgb& colour) {
    vtkPoints* points = data->GetPoints();
    const vtkIdType first = points->GetNumberOfPoints();
    points->InsertNextPoint(r[0], r[1], 0.0);
    points->InsertNextPoint(r[2], r[1], 0.0);
    points->InsertNextPoint(r[2], r[3], 0.0);
    points->InsertNextPoint(r[0], r[3], 0.0);
    const vtkIdType corners[4] = {first, first + 1, first + 2, first + 3};
    data->GetPolys()->InsertNextCell(4, corners);
    vtkUnsignedCharArray::SafeDownCast(data->GetCellData()->GetScalars())
        ->InsertNextTuple3(byte(colour[0]), byte(colour[1]), byte(colour[2]));
}

}  // namespace

SceneLegend::SceneLegend()
    : assembly_(vtkSmartPointer<vtkPropAssembly>::New()), backgroundData_(emptyColoured()), colourData_(emptyColoured()) {
    background_ = actorOf(backgroundData_);
    background_->GetProperty()->SetOpacity(0.55);
    colours_ = actorOf(colourData_);
    assembly_->AddPart(background_);
    assembly_->AddPart(colours_);
    assembly_->PickableOff();
    assembly_->SetVisibility(false);
}

SceneLegend::~SceneLegend() = default;

vtkProp* SceneLegend::prop() const { return assembly_; }

void SceneLegend::addText(const std::string& text, double x, double centreY, int fontSize) {
    auto actor = vtkSmartPointer<vtkTextActor>::New();
    actor->SetInput(text.c_str());
    actor->GetTextProperty()->ShallowCopy(textProperty(fontSize));
    actor->SetDisplayPosition(int(std::lround(x)), int(std::lround(centreY)));
    actor->PickableOff();
    assembly_->AddPart(actor);
    textActors_.push_back(actor);
    const std::array<double, 2> size = textSize(text, actor->GetTextProperty());
    texts_.push_back({text, {x, centreY - 0.5 * size[1], x + size[0], centreY + 0.5 * size[1]}});
}

void SceneLegend::addColours(const std::vector<Rgb>& colours, const Rectangle& where) {
    // The frame, then the colours side by side inside it.
    addRectangle(colourData_, where, frameColour);
    const double inset = 1.5, width = (where[2] - where[0] - 2.0 * inset) / double(std::max<size_t>(colours.size(), 1));
    for (size_t i = 0; i < colours.size(); ++i) {
        const double x0 = where[0] + inset + double(i) * width;
        addRectangle(colourData_, {x0, where[1] + inset, x0 + width, where[3] - inset}, colours[i]);
    }
    swatches_.push_back(where);
}

void SceneLegend::show(const std::vector<LegendEntry>& entries) {
    entries_ = entries;
    for (const auto& actor : textActors_) assembly_->RemovePart(actor);
    textActors_.clear();
    texts_.clear();
    swatches_.clear();
    colourData_->ShallowCopy(emptyColoured());
    size_t rows = 0;
    for (const LegendEntry& entry : entries) rows += entry.scale ? 2 : 1;
    const double left = legendMargin + legendPadding;
    const double top = legendMargin + 2.0 * legendPadding + double(rows) * rowHeight;
    double y = top - legendPadding - 0.5 * rowHeight;  // the centre of the current row
    for (const LegendEntry& entry : entries) {
        if (!entry.scale) {
            const Rectangle swatch{left, y - 0.5 * swatchHeight, left + swatchWidth, y + 0.5 * swatchHeight};
            addColours(entry.colours, swatch);
            addText(entry.label, swatch[2] + swatchGap, y, labelFontSize);
            y -= rowHeight;
            continue;
        }
        // A continuous colouring: its label, and under it the bar with its ends written beside them.
        addText(entry.label, left, y, labelFontSize);
        y -= rowHeight;
        addText(scaleText((*entry.scale)[0]), left, y, scaleFontSize);
        const double barLeft = texts_.back().box[2] + 0.5 * swatchGap;
        const Rectangle bar{barLeft, y - 0.5 * swatchHeight, barLeft + barWidth, y + 0.5 * swatchHeight};
        addColours(entry.colours, bar);
        addText(scaleText((*entry.scale)[1]), bar[2] + 0.5 * swatchGap, y, scaleFontSize);
        y -= rowHeight;
    }
    double right = left;
    for (const Placed& text : texts_) right = std::max(right, text.box[2]);
    for (const Rectangle& swatch : swatches_) right = std::max(right, swatch[2]);
    box_ = {legendMargin, legendMargin, right + legendPadding, top};
    backgroundData_->ShallowCopy(emptyColoured());
    addRectangle(backgroundData_, box_, {0.0, 0.0, 0.0});
    backgroundData_->Modified();
    colourData_->Modified();
    setVisible(visible_);
}

void SceneLegend::setVisible(bool visible) {
    visible_ = visible;
    assembly_->SetVisibility(drawn());
}

bool SceneLegend::drawn() const { return visible_ && !entries_.empty(); }

}  // namespace conescope
