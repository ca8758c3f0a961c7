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

vtkSmartPointer<vtkTextProperty> textProperty(double fontSize) {
    auto property = vtkSmartPointer<vtkTextProperty>::New();
    property->SetFontFamilyToArial();
    property->SetFontSize(int(std::lround(fontSize)));
    property->SetColor(1.0, 1.0, 1.0);
    property->ShadowOff();
    property->SetJustificationToLeft();
    property->SetVerticalJustificationToCentered();
    return property;
}

// The text's size in pixels as a text actor draws it in a window of `dpi` (VTK's default is 72).
std::array<double, 2> textSize(const std::string& text, vtkTextProperty* property, int dpi) {
    int box[4] = {0, 0, 0, 0};
    vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
    if (renderer && renderer->GetBoundingBox(property, text, box, dpi)) return {double(box[1] - box[0] + 1), double(box[3] - box[2] + 1)};
    const double ratio = double(dpi) / 72.0;
    return {0.6 * ratio * property->GetFontSize() * double(text.size()), ratio * property->GetFontSize()};
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

double legendScaleFor(int height) { return std::clamp(double(height) / 600.0, 0.75, 1.0); }

double legendScaleFor(int height, size_t rows) {
    const double natural = 2.0 * (legendMargin + legendPadding) + double(rows) * rowHeight;
    return std::min(legendScaleFor(height), std::max(0.7, 0.25 * double(height) / natural));
}

namespace {

size_t rowsOf(const std::vector<LegendEntry>& entries) {
    size_t rows = 0;
    for (const LegendEntry& entry : entries) rows += entry.scale ? 2 : 1;
    return rows;
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

void SceneLegend::addText(const std::string& text, double x, double centreY, double fontSize) {
    auto actor = vtkSmartPointer<vtkTextActor>::New();
    actor->SetInput(text.c_str());
    actor->GetTextProperty()->ShallowCopy(textProperty(fontSize));
    actor->SetDisplayPosition(int(std::lround(x)), int(std::lround(centreY)));
    actor->PickableOff();
    assembly_->AddPart(actor);
    textActors_.push_back(actor);
    const std::array<double, 2> size = textSize(text, actor->GetTextProperty(), int(std::lround(72.0 * pixelRatio_)));
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
    // An eye step sets several layers; each asks again for the same legend. Laying out measures
    // every text with FreeType: done only when something in it changed.
    if (laidOut_ && entries == entries_) return;
    if (viewHeight_ > 0) scale_ = legendScaleFor(viewHeight_, rowsOf(entries));
    layOut(entries);
}

void SceneLegend::layOut(const std::vector<LegendEntry>& entries) {
    laidOut_ = true;
    entries_ = entries;
    for (const auto& actor : textActors_) assembly_->RemovePart(actor);
    textActors_.clear();
    texts_.clear();
    swatches_.clear();
    colourData_->ShallowCopy(emptyColoured());
    const size_t rows = rowsOf(entries);
    const double k = scale_ * pixelRatio_, margin = k * legendMargin, padding = k * legendPadding, row = k * rowHeight;
    const double left = margin + padding;
    const double top = margin + 2.0 * padding + double(rows) * row;
    double y = top - padding - 0.5 * row;  // the centre of the current row
    for (const LegendEntry& entry : entries) {
        if (!entry.scale) {
            const Rectangle swatch{left, y - 0.5 * k * swatchHeight, left + k * swatchWidth, y + 0.5 * k * swatchHeight};
            addColours(entry.colours, swatch);
            addText(entry.label, swatch[2] + k * swatchGap, y, scale_ * labelFontSize);
            y -= row;
            continue;
        }
        // A continuous colouring: its label, and under it the bar with its ends written beside them.
        addText(entry.label, left, y, scale_ * labelFontSize);
        y -= row;
        addText(scaleText((*entry.scale)[0]), left, y, scale_ * scaleFontSize);
        const double barLeft = texts_.back().box[2] + 0.5 * k * swatchGap;
        const Rectangle bar{barLeft, y - 0.5 * k * swatchHeight, barLeft + k * barWidth, y + 0.5 * k * swatchHeight};
        addColours(entry.colours, bar);
        addText(scaleText((*entry.scale)[1]), bar[2] + 0.5 * k * swatchGap, y, scale_ * scaleFontSize);
        y -= row;
    }
    double right = left;
    for (const Placed& text : texts_) right = std::max(right, text.box[2]);
    for (const Rectangle& swatch : swatches_) right = std::max(right, swatch[2]);
    box_ = {margin, margin, right + padding, top};
    backgroundData_->ShallowCopy(emptyColoured());
    addRectangle(backgroundData_, box_, {0.0, 0.0, 0.0});
    backgroundData_->Modified();
    colourData_->Modified();
    setVisible(visible_);
}

void SceneLegend::setScale(double scale, double pixelRatio) {
    if ((scale == scale_ && pixelRatio == pixelRatio_) || !(scale > 0.0) || !(pixelRatio > 0.0)) return;
    scale_ = scale;
    pixelRatio_ = pixelRatio;
    layOut(std::vector<LegendEntry>(entries_));
}

void SceneLegend::fitTo(int viewHeight, double pixelRatio) {
    viewHeight_ = viewHeight;
    setScale(legendScaleFor(viewHeight, rowsOf(entries_)), pixelRatio);
}

void SceneLegend::setVisible(bool visible) {
    visible_ = visible;
    assembly_->SetVisibility(drawn());
}

bool SceneLegend::drawn() const { return visible_ && !entries_.empty(); }

}  // namespace conescope
