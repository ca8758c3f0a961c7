#include "scene/CrossSectionScene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkImageData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkUnsignedCharArray.h>

#include "scene/CrossSectionFigure.h"
#include "scene/LabelPlacement.h"
#include "scene/SceneRendering.h"

namespace conescope {

namespace {

constexpr Rgb ink{0.10, 0.10, 0.12};
// VTK's own Arial has no Greek letters; Debian's DejaVu Sans (fonts-dejavu-core) has.
const char* const greekFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const char* const greekBoldFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

// A new property for every text: VTK's font cache keeps the property it first met for a look
// (vtkFreeTypeTools' lookup) and loads faces from it later, so one changed afterwards gives a text
// another's font.
vtkSmartPointer<vtkTextProperty> fontOf(double points, const Rgb& colour, bool bold) {
    auto property = vtkSmartPointer<vtkTextProperty>::New();
    property->SetFontSize(std::max(6, int(std::lround(points))));
    const char* font = bold ? greekBoldFont : greekFont;
    if (std::filesystem::exists(font)) {
        property->SetFontFamily(VTK_FONT_FILE);
        property->SetFontFile(font);
    } else {
        property->SetFontFamilyToArial();
    }
    property->SetBold(bold);
    property->SetColor(colour[0], colour[1], colour[2]);
    property->SetJustificationToLeft();
    property->SetVerticalJustificationToBottom();
    property->SetLineSpacing(1.1);
    return property;
}

// The ink's box of `text` drawn at (0, 0): x0, x1, y0, y1 in pixels.
std::array<int, 4> inkBox(vtkTextProperty* property, const std::string& text, int dpi) {
    std::array<int, 4> box{0, 0, 0, 0};
    if (!text.empty()) vtkTextRenderer::GetInstance()->GetBoundingBox(property, text, box.data(), dpi);
    return box;
}

// Words broken into lines no wider than `width` pixels.
std::string wrapped(vtkTextProperty* property, const std::string& text, double width, int dpi) {
    std::istringstream words(text);
    std::string word, line, result;
    while (words >> word) {
        const std::string longer = line.empty() ? word : line + " " + word;
        const std::array<int, 4> box = inkBox(property, longer, dpi);
        if (!line.empty() && box[1] - box[0] > width) {
            result += line + "\n";
            line = word;
        } else {
            line = longer;
        }
    }
    return result + line;
}

// Shapes as cells of one polydata, each cell its colour, each shape a little above the one before.
vtkSmartPointer<vtkPolyData> cellsOf(const std::vector<const FigureShape*>& shapes, size_t firstDepth) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    auto addColour = [&colours](const Rgb& c) {
        const unsigned char rgb[3] = {static_cast<unsigned char>(std::lround(255 * c[0])), static_cast<unsigned char>(std::lround(255 * c[1])),
                                      static_cast<unsigned char>(std::lround(255 * c[2]))};
        colours->InsertNextTypedTuple(rgb);
    };
    for (size_t s = 0; s < shapes.size(); ++s) {
        const FigureShape& shape = *shapes[s];
        const double z = 1e-3 * double(firstDepth + s);
        const vtkIdType first = points->GetNumberOfPoints();
        for (const glm::dvec2& p : shape.points) points->InsertNextPoint(p.x, p.y, z);
        if (shape.filled) {
            for (size_t t = 0; t + 2 < shape.points.size(); t += 3) {
                const vtkIdType ids[3] = {first + vtkIdType(t), first + vtkIdType(t) + 1, first + vtkIdType(t) + 2};
                cells->InsertNextCell(3, ids);
                addColour(shape.colour);
            }
        } else {
            cells->InsertNextCell(vtkIdType(shape.points.size()));
            for (size_t i = 0; i < shape.points.size(); ++i) cells->InsertCellPoint(first + vtkIdType(i));
            addColour(shape.colour);
        }
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    if (!shapes.empty() && shapes.front()->filled)
        data->SetPolys(cells);
    else
        data->SetLines(cells);
    data->GetCellData()->SetScalars(colours);
    return data;
}

vtkSmartPointer<vtkActor> actorOf(vtkPolyData* data, double width) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(data);
    mapper->SetScalarModeToUseCellData();
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->SetLineWidth(float(width));
    actor->PickableOff();
    return actor;
}

}  // namespace

// The shapes in order (the figure's, then the labels' leaders), one actor for each run of the same
// kind and width.
static std::vector<vtkSmartPointer<vtkActor>> actorsOf(const std::vector<FigureShape>& shapes, const std::vector<FigureShape>& leaders) {
    std::vector<const FigureShape*> all;
    for (const FigureShape& shape : shapes) all.push_back(&shape);
    for (const FigureShape& shape : leaders) all.push_back(&shape);
    std::vector<vtkSmartPointer<vtkActor>> actors;
    for (size_t start = 0; start < all.size();) {
        size_t end = start + 1;
        while (end < all.size() && all[end]->filled == all[start]->filled && all[end]->width == all[start]->width) ++end;
        actors.push_back(actorOf(cellsOf({all.begin() + long(start), all.begin() + long(end)}, start), all[start]->width));
        start = end;
    }
    return actors;
}

struct CrossSectionScene::Impl {
    std::optional<CrossSection> section;
    bool captionVisible = true, textVisible = true;
    std::vector<vtkRenderer*> renderers;
    std::vector<vtkSmartPointer<vtkActor>> actors;
    std::vector<vtkSmartPointer<vtkTextActor>> texts;
    std::vector<CrossSectionLabel> labels;
    std::vector<std::string> leftOut;
    int width = 0, height = 0;

    void detach() {
        for (vtkRenderer* renderer : renderers) {
            for (const auto& actor : actors) renderer->RemoveActor(actor);
            for (const auto& text : texts) renderer->RemoveViewProp(text);
        }
    }
    void attach() {
        for (vtkRenderer* renderer : renderers) {
            for (const auto& actor : actors) renderer->AddActor(actor);
            for (const auto& text : texts) renderer->AddViewProp(text);
        }
    }
    // A text whose ink's lower-left corner is at `corner`; its box is recorded for the JSON.
    void addText(const std::string& text, const std::string& shown, vtkTextProperty* property, const glm::dvec2& corner, int dpi) {
        auto actor = vtkSmartPointer<vtkTextActor>::New();
        actor->SetTextProperty(property);
        actor->SetInput(shown.c_str());
        const std::array<int, 4> box = inkBox(property, shown, dpi);
        actor->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
        actor->SetPosition(corner.x - box[0], corner.y - box[2]);
        actor->PickableOff();
        actor->SetVisibility(textVisible);
        texts.push_back(actor);
        const double x1 = corner.x + (box[1] - box[0]), y1 = corner.y + (box[3] - box[2]);
        labels.push_back({text, {corner.x, double(height) - y1, x1, double(height) - corner.y}});
    }
    void layOut(int dpi);
};

CrossSectionScene::CrossSectionScene() : impl_(std::make_unique<Impl>()) {}

CrossSectionScene::~CrossSectionScene() { impl_->detach(); }

bool CrossSectionScene::hasSection() const { return impl_->section.has_value(); }

void CrossSectionScene::show(const std::optional<CrossSection>& section) { impl_->section = section; }

void CrossSectionScene::setCaptionVisible(bool visible) { impl_->captionVisible = visible; }

void CrossSectionScene::setTextVisible(bool visible) {
    impl_->textVisible = visible;
    for (const auto& text : impl_->texts) text->SetVisibility(visible);
}

void CrossSectionScene::fitTo(int widthPixels, int heightPixels, int dpi) {
    impl_->width = std::max(widthPixels, 1);
    impl_->height = std::max(heightPixels, 1);
    impl_->detach();
    impl_->layOut(std::max(dpi, 1));
    impl_->attach();
}

void CrossSectionScene::Impl::layOut(int dpi) {
    actors.clear();
    texts.clear();
    labels.clear();
    leftOut.clear();
    const double ratio = dpi / 72.0;
    // Text in points sized for the picture as the reader sees it (device pixels / ratio).
    const double shortSide = std::min(width, height) / ratio;
    const double textScale = std::clamp(shortSide / 480.0, 0.75, 2.25);
    const double unit = ratio * std::clamp(shortSide / 480.0, 1.0, 2.0);
    const double margin = std::round(0.02 * std::min(width, height) + 4.0 * ratio);
    // The title along the top.
    double titleBottom = height - margin;
    if (captionVisible || !section) {
        const vtkSmartPointer<vtkTextProperty> property = fontOf(18.0 * textScale, ink, true);
        const std::string title = section ? section->title : "Pick a cluster: its normals, cone and view vector appear here, in the plane of V1 and v.";
        const std::string lines = wrapped(property, title, width - 2.0 * margin, dpi);
        const std::array<int, 4> box = inkBox(property, lines, dpi);
        titleBottom = height - margin - (box[3] - box[2]);
        addText(title, lines, property, {margin, titleBottom}, dpi);
    }
    if (!section) return;
    // The caption along the bottom.
    double captionTop = margin;
    std::optional<PixelBox> captionBox;
    if (captionVisible) {
        const vtkSmartPointer<vtkTextProperty> property = fontOf(14.0 * textScale, ink, false);
        const std::string lines = wrapped(property, section->caption, width - 2.0 * margin, dpi);
        const std::array<int, 4> box = inkBox(property, lines, dpi);
        addText(section->caption, lines, property, {margin, margin}, dpi);
        captionTop = margin + (box[3] - box[2]);
        captionBox = PixelBox{margin, margin, margin + (box[1] - box[0]), captionTop};
    }
    const double gap = std::round(6.0 * ratio);
    const PixelBox area{margin, captionTop + gap, width - margin, titleBottom - gap};
    const CrossSectionFigure figure = drawCrossSection(*section, area, unit);
    // The labels, each where nothing else is.
    LabelPlacer placer(width, height, {margin * 0.5, captionTop + 1.0, width - margin * 0.5, titleBottom - 1.0}, 2.0 * ratio, 10.0 * unit);
    for (const FigureShape& shape : figure.shapes) {
        if (shape.underLabels) continue;
        if (shape.filled)
            placer.blockTriangles(shape.points);
        else
            placer.blockLine(shape.points, shape.width);
    }
    placer.blockBox({margin, titleBottom, double(width), double(height)});
    if (captionBox) placer.blockBox(*captionBox);
    std::vector<FigureShape> leaders;
    for (const FigureLabel& label : figure.labels) {
        bool placed = false;
        // Near what it names at full size first; smaller, or farther away on a leader, only when it must.
        // The small figure's labels inside its frame if they can be.
        std::vector<std::tuple<double, double, bool>> tries;
        for (bool framed : {true, false}) {
            if (framed && !label.within) continue;
            for (const auto& [shrink, reach] : std::vector<std::pair<double, double>>{{1.0, 0.12}, {0.85, 0.12}, {1.0, 0.25}, {0.85, 0.25}, {0.72, 0.25}, {1.0, 0.5}, {0.72, 0.5}})
                tries.emplace_back(shrink, reach, framed);
        }
        for (const auto& [shrink, reach, framed] : tries) {
            const vtkSmartPointer<vtkTextProperty> property = fontOf(15.0 * textScale * shrink, label.colour, true);
            const std::array<int, 4> box = inkBox(property, label.text, dpi);
            const glm::dvec2 size(box[1] - box[0], box[3] - box[2]);
            const std::optional<LabelSpot> spot =
                placer.place(label.anchor, label.toward, size, reach * std::min(width, height), framed ? label.within : std::nullopt);
            if (!spot) continue;
            addText(label.text, label.text, property, {spot->box.x0, spot->box.y0}, dpi);
            if (spot->leader) leaders.push_back({{spot->leaderFrom, spot->leaderTo}, false, label.colour, std::max(1.0, 0.75 * unit)});
            placed = true;
            break;
        }
        if (!placed) leftOut.push_back(label.text);
    }
    actors = actorsOf(figure.shapes, leaders);
}

void CrossSectionScene::addTo(vtkRenderer* renderer) {
    if (std::find(impl_->renderers.begin(), impl_->renderers.end(), renderer) != impl_->renderers.end()) return;
    impl_->renderers.push_back(renderer);
    for (const auto& actor : impl_->actors) renderer->AddActor(actor);
    for (const auto& text : impl_->texts) renderer->AddViewProp(text);
}

void CrossSectionScene::removeFrom(vtkRenderer* renderer) {
    for (const auto& actor : impl_->actors) renderer->RemoveActor(actor);
    for (const auto& text : impl_->texts) renderer->RemoveViewProp(text);
    impl_->renderers.erase(std::remove(impl_->renderers.begin(), impl_->renderers.end(), renderer), impl_->renderers.end());
}

void CrossSectionScene::placeCamera(vtkCamera* camera) const {
    const double w = impl_->width, h = impl_->height;
    camera->ParallelProjectionOn();
    camera->SetParallelScale(0.5 * h);
    camera->SetFocalPoint(0.5 * w, 0.5 * h, 0.0);
    camera->SetPosition(0.5 * w, 0.5 * h, 10.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetClippingRange(1.0, 20.0);
}

const std::vector<CrossSectionLabel>& CrossSectionScene::labels() const { return impl_->labels; }

const std::vector<std::string>& CrossSectionScene::leftOut() const { return impl_->leftOut; }

vtkSmartPointer<vtkImageData> renderCrossSectionToImage(CrossSectionScene& scene, int width, int height, int dpi) {
    requireDisplay();
    scene.fitTo(width, height, dpi);
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetBackground(1.0, 1.0, 1.0);
    scene.addTo(renderer);
    scene.placeCamera(renderer->GetActiveCamera());
    vtkSmartPointer<vtkImageData> image = renderOffScreen(renderer, width, height, dpi);
    scene.removeFrom(renderer);
    return image;
}

}  // namespace conescope
