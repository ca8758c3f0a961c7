#include "scene/CrossSectionScene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkImageData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "scene/SceneGeometry.h"
#include "scene/SceneLayer.h"
#include "scene/SceneRendering.h"

namespace conescope {

namespace {

// Seed 000's figure: normals red, boundaries green, axis and view vector dark red, the perpendicular dark blue.
constexpr Rgb boundaryGreen{0.05, 0.60, 0.10};
constexpr Rgb darkRed{0.55, 0.00, 0.05};
constexpr Rgb darkBlue{0.05, 0.10, 0.55};
constexpr Rgb circleGrey{0.80, 0.80, 0.82};
constexpr Rgb wedgeGreen{0.80, 0.94, 0.78};
constexpr Rgb octagonGold{0.85, 0.60, 0.00};
constexpr Rgb ink{0.10, 0.10, 0.12};
// The figure's extent in the plane: the unit circle and the lines drawn a little past it.
constexpr double figureLow = -1.30, figureHigh = 1.50, figureHalfWidth = 1.45;
// Share of the picture's height the figure takes; the caption goes below.
constexpr double figureShare = 0.72;

glm::vec3 at(const glm::dvec2& p, double z = 0.0) { return glm::vec3(float(p.x), float(p.y), float(z)); }
glm::dvec2 direction(double angle) { return {std::sin(angle), std::cos(angle)}; }

GlyphGeometry lines(const std::vector<std::pair<glm::dvec2, glm::dvec2>>& segments) {
    GlyphGeometry geometry;
    for (const auto& [from, to] : segments) {
        const int64_t first = int64_t(geometry.points.size());
        geometry.points.push_back(at(from));
        geometry.points.push_back(at(to));
        geometry.addCell({first, first + 1}, 0);
    }
    return geometry;
}

// An arc of radius `radius` from angle `from` to `to` (angles from V1, clockwise to the right).
GlyphGeometry arc(double radius, double from, double to) {
    GlyphGeometry geometry;
    constexpr int steps = 32;
    for (int i = 0; i <= steps; ++i) geometry.points.push_back(at(radius * direction(from + (to - from) * i / steps)));
    for (int i = 0; i < steps; ++i) geometry.addCell({i, i + 1}, 0);
    return geometry;
}

// A filled sector from the origin, behind the lines.
GlyphGeometry sector(double radius, double from, double to) {
    GlyphGeometry geometry;
    constexpr int steps = 48;
    geometry.points.push_back(at({0.0, 0.0}, -0.02));
    for (int i = 0; i <= steps; ++i) geometry.points.push_back(at(radius * direction(from + (to - from) * i / steps), -0.02));
    for (int i = 1; i <= steps; ++i) geometry.addCell({0, i, i + 1}, 0);
    return geometry;
}

// A filled arrowhead at `tip` pointing along `along`.
GlyphGeometry arrowHead(const glm::dvec2& tip, const glm::dvec2& along) {
    const glm::dvec2 d = glm::normalize(along), n(-d.y, d.x);
    GlyphGeometry geometry;
    geometry.points = {at(tip, 0.01), at(tip - 0.09 * d + 0.035 * n, 0.01), at(tip - 0.09 * d - 0.035 * n, 0.01)};
    geometry.addCell({0, 1, 2}, 0);
    return geometry;
}

vtkSmartPointer<vtkActor> flatActor(const Rgb& colour) {
    auto actor = actorFor(plainMapper(emptyPolyData()));
    setColour(actor, colour);
    actor->GetProperty()->LightingOff();
    return actor;
}

vtkSmartPointer<vtkActor> strokeActor(const Rgb& colour, double width) {
    auto actor = lineActor(plainMapper(emptyPolyData()), width);
    setColour(actor, colour);
    return actor;
}

// VTK's own Arial has no Greek letters; Debian's DejaVu Sans (fonts-dejavu-core) has.
const char* const greekFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const char* const greekBoldFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

vtkSmartPointer<vtkTextActor> textActor(int size, const Rgb& colour, bool bold = false) {
    auto text = vtkSmartPointer<vtkTextActor>::New();
    vtkTextProperty* property = text->GetTextProperty();
    property->SetFontSize(size);
    const char* font = bold ? greekBoldFont : greekFont;
    if (std::filesystem::exists(font)) {
        property->SetFontFamily(VTK_FONT_FILE);
        property->SetFontFile(font);
    } else {
        property->SetFontFamilyToArial();
    }
    property->SetColor(colour[0], colour[1], colour[2]);
    property->SetBold(bold);
    text->PickableOff();
    return text;
}

void placeLabel(vtkTextActor* label, const std::string& text, const glm::dvec2& where) {
    label->SetInput(text.c_str());
    label->GetPositionCoordinate()->SetCoordinateSystemToWorld();
    label->GetPositionCoordinate()->SetValue(where.x, where.y, 0.05);
    label->SetVisibility(!text.empty());
}

std::string degreesText(double radians) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f\u00b0", glm::degrees(radians));
    return text;
}

// Words broken into lines of at most `width` characters (UTF-8 continuation bytes not counted).
std::string wrapped(const std::string& text, size_t width) {
    std::istringstream words(text);
    std::string word, line, result;
    auto length = [](const std::string& s) {
        size_t n = 0;
        for (unsigned char c : s) n += (c & 0xC0) != 0x80;
        return n;
    };
    while (words >> word) {
        if (!line.empty() && length(line) + 1 + length(word) > width) {
            result += line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    return result + line;
}

}  // namespace

struct CrossSectionScene::Impl {
    vtkSmartPointer<vtkActor> wedge = flatActor(wedgeGreen);
    vtkSmartPointer<vtkActor> circle = strokeActor(circleGrey, 1.5);
    vtkSmartPointer<vtkActor> perpendicular = strokeActor(darkBlue, 2.5);
    vtkSmartPointer<vtkActor> normals = strokeActor(SceneColours::lessonNormal, 1.5);
    vtkSmartPointer<vtkActor> boundaries = strokeActor(boundaryGreen, 3.0);
    vtkSmartPointer<vtkActor> octagon = strokeActor(octagonGold, 2.5);
    vtkSmartPointer<vtkActor> alphaArc = strokeActor(boundaryGreen, 1.5);
    vtkSmartPointer<vtkActor> angleBArc = strokeActor(darkBlue, 1.5);
    vtkSmartPointer<vtkActor> axis = strokeActor(darkRed, 3.0);
    vtkSmartPointer<vtkActor> view = strokeActor(darkRed, 3.5);
    vtkSmartPointer<vtkActor> heads = flatActor(darkRed);
    vtkSmartPointer<vtkTextActor> title = textActor(18, ink, true);
    vtkSmartPointer<vtkTextActor> caption = textActor(14, ink);
    std::vector<vtkSmartPointer<vtkTextActor>> labels;  // V1, v, alpha, B, perpendicular, wedge, octagon
    std::optional<CrossSection> section;
    size_t captionWidth = 84;  // characters per line

    std::vector<vtkActor*> actors() const {
        return {wedge, circle, perpendicular, normals, boundaries, octagon, alphaArc, angleBArc, axis, view, heads};
    }
    std::vector<vtkTextActor*> texts() const {
        std::vector<vtkTextActor*> all = {title, caption};
        for (const auto& label : labels) all.push_back(label);
        return all;
    }
};

CrossSectionScene::CrossSectionScene() : impl_(std::make_unique<Impl>()) {
    for (const Rgb& colour : {darkRed, darkRed, boundaryGreen, darkBlue, darkBlue, boundaryGreen, octagonGold})
        impl_->labels.push_back(textActor(15, colour, true));
    for (vtkTextActor* text : {impl_->title.Get(), impl_->caption.Get()}) text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    impl_->title->GetPositionCoordinate()->SetValue(0.03, 0.95);
    impl_->title->GetTextProperty()->SetVerticalJustificationToTop();
    impl_->caption->GetPositionCoordinate()->SetValue(0.03, 0.02);
    impl_->caption->GetTextProperty()->SetVerticalJustificationToBottom();
    impl_->caption->GetTextProperty()->SetLineSpacing(1.1);
    show(std::nullopt);
}

CrossSectionScene::~CrossSectionScene() = default;

bool CrossSectionScene::hasSection() const { return impl_->section.has_value(); }

void CrossSectionScene::show(const std::optional<CrossSection>& section) {
    Impl& scene = *impl_;
    scene.section = section;
    for (vtkActor* actor : scene.actors()) actor->SetVisibility(section.has_value());
    for (const auto& label : scene.labels) label->SetVisibility(false);
    if (!section) {
        scene.title->SetInput("Pick a cluster: its normals, cone and view vector appear here, in the plane of V1 and v.");
        scene.caption->SetInput("");
        return;
    }
    const CrossSection& s = *section;
    scene.title->SetInput(s.title.c_str());
    scene.caption->SetInput(wrapped(s.caption, scene.captionWidth).c_str());
    setInput(scene.circle, polyDataFrom(arc(1.0, -M_PI, M_PI), CellKind::Lines));
    setInput(scene.perpendicular, polyDataFrom(lines({{{-1.3, 0.0}, {1.3, 0.0}}}), CellKind::Lines));
    std::vector<std::pair<glm::dvec2, glm::dvec2>> normals;
    for (const glm::dvec2& n : s.normals) normals.push_back({{0.0, 0.0}, n});
    setInput(scene.normals, polyDataFrom(lines(normals), CellKind::Lines));
    const glm::dvec2 axisTip = 1.35 * s.axis, viewTip = 1.2 * s.view;
    setInput(scene.axis, polyDataFrom(lines({{{0.0, 0.0}, axisTip}}), CellKind::Lines));
    setInput(scene.view, polyDataFrom(lines({{{0.0, 0.0}, viewTip}}), CellKind::Lines));
    GlyphGeometry heads = arrowHead(axisTip, s.axis);
    const GlyphGeometry viewHead = arrowHead(viewTip, s.view);
    for (size_t i = 0; i < viewHead.points.size(); ++i) heads.points.push_back(viewHead.points[i]);
    heads.addCell({3, 4, 5}, 0);
    setInput(scene.heads, polyDataFrom(heads, CellKind::Polygons));
    placeLabel(scene.labels[0], "V1", axisTip + glm::dvec2(0.06, -0.02));
    placeLabel(scene.labels[1], "v", viewTip + 0.08 * s.view + glm::dvec2(0.02, -0.03));
    scene.boundaries->SetVisibility(s.cone);
    scene.alphaArc->SetVisibility(s.cone);
    scene.angleBArc->SetVisibility(s.cone);
    if (s.cone) {
        setInput(scene.boundaries, polyDataFrom(lines({{{0.0, 0.0}, 1.3 * s.boundaries[0]}, {{0.0, 0.0}, 1.3 * s.boundaries[1]}}), CellKind::Lines));
        // alpha outside the normals (which reach the unit circle), B inside them.
        setInput(scene.alphaArc, polyDataFrom(arc(1.1, 0.0, s.alpha), CellKind::Lines));
        setInput(scene.angleBArc, polyDataFrom(arc(0.6, s.alpha, M_PI / 2.0), CellKind::Lines));
        placeLabel(scene.labels[2], "\u03b1 = " + degreesText(s.alpha), 1.16 * direction(0.5 * s.alpha) + glm::dvec2(0.03, 0.0));
        placeLabel(scene.labels[3], "B = " + degreesText(s.angleB), 0.66 * direction(0.5 * (s.alpha + M_PI / 2.0)));
    }
    placeLabel(scene.labels[4], "perpendicular to V1", {-1.3, -0.12});
    scene.wedge->SetVisibility(s.hasWedge());
    if (s.hasWedge()) {
        setInput(scene.wedge, polyDataFrom(sector(1.25, s.cullingAngles[0], s.cullingAngles[1]), CellKind::Polygons));
        placeLabel(scene.labels[5], "v culls here", 1.27 * direction(s.cullingAngles[0]) + glm::dvec2(-0.42, 0.0));
    }
    scene.octagon->SetVisibility(s.octagon);
    if (s.octagon) {
        setInput(scene.octagon, polyDataFrom(lines({{{0.0, 0.0}, 1.12 * s.octagonBoundaries[0]}, {{0.0, 0.0}, 1.12 * s.octagonBoundaries[1]}}),
                                             CellKind::Lines));
        placeLabel(scene.labels[6], "octagon", 1.14 * s.octagonBoundaries[1] + glm::dvec2(0.03, 0.0));
    }
}

void CrossSectionScene::fitTo(int widthPixels, int heightPixels) {
    // Sized for a 480-pixel picture; the caption has about 7.5 pixels a character at 14 points.
    const double scale = std::clamp(std::min(widthPixels, heightPixels) / 480.0, 0.6, 1.5);
    impl_->title->GetTextProperty()->SetFontSize(int(std::lround(18 * scale)));
    impl_->caption->GetTextProperty()->SetFontSize(int(std::lround(14 * scale)));
    for (const auto& label : impl_->labels) label->GetTextProperty()->SetFontSize(int(std::lround(15 * scale)));
    impl_->captionWidth = size_t(std::max(24, int((widthPixels - 20) / (7.5 * scale))));
    if (impl_->section) impl_->caption->SetInput(wrapped(impl_->section->caption, impl_->captionWidth).c_str());
}

void CrossSectionScene::setCaptionVisible(bool visible) { impl_->caption->SetVisibility(visible); }

void CrossSectionScene::addTo(vtkRenderer* renderer) const {
    for (vtkActor* actor : impl_->actors()) renderer->AddActor(actor);
    for (vtkTextActor* text : impl_->texts()) renderer->AddViewProp(text);
}

void CrossSectionScene::removeFrom(vtkRenderer* renderer) const {
    for (vtkActor* actor : impl_->actors()) renderer->RemoveActor(actor);
    for (vtkTextActor* text : impl_->texts()) renderer->RemoveViewProp(text);
}

void CrossSectionScene::placeCamera(vtkCamera* camera, double aspect) const {
    // The figure fills the top share of the height (and fits the width); the caption the rest.
    const double figureHeight = figureHigh - figureLow;
    // Without the caption (shown as text beside it) the figure takes nearly the whole height.
    double visibleHeight = figureHeight / (impl_->caption->GetVisibility() ? figureShare : 0.9);
    if (aspect > 0.0 && visibleHeight * aspect < 2.0 * figureHalfWidth) visibleHeight = 2.0 * figureHalfWidth / aspect;
    const double bottom = figureHigh - visibleHeight + 0.1 * figureHeight;
    const double centreY = bottom + visibleHeight / 2.0;
    camera->ParallelProjectionOn();
    camera->SetParallelScale(visibleHeight / 2.0);
    camera->SetFocalPoint(0.0, centreY, 0.0);
    camera->SetPosition(0.0, centreY, 10.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetClippingRange(1.0, 20.0);
}

vtkSmartPointer<vtkImageData> renderCrossSectionToImage(CrossSectionScene& scene, int width, int height) {
    requireDisplay();
    scene.fitTo(width, height);
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetBackground(1.0, 1.0, 1.0);
    scene.addTo(renderer);
    scene.placeCamera(renderer->GetActiveCamera(), double(width) / double(height));
    vtkSmartPointer<vtkImageData> image = renderOffScreen(renderer, width, height);
    scene.removeFrom(renderer);
    return image;
}

}  // namespace conescope
