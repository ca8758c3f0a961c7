#include "scene/CrossSectionFigure.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/LessonText.h"
#include "scene/SceneTypes.h"

namespace conescope {

namespace {

constexpr double pi = 3.14159265358979323846;

// Seed 000's colours on white: normals red, the cone green, V1 and v dark red; the views that cull
// blue, a shape (a band outside the circle) of their own; the octagon gold; a failing corner orange.
constexpr Rgb ink{0.10, 0.10, 0.12};
constexpr Rgb darkRed{0.55, 0.00, 0.05};
constexpr Rgb coneGreen{0.05, 0.55, 0.10};
constexpr Rgb bandBlue{0.25, 0.42, 0.90};
constexpr Rgb blueInk{0.10, 0.20, 0.62};
constexpr Rgb paleBlue{0.86, 0.90, 1.00};
constexpr Rgb gold{0.80, 0.55, 0.00};
constexpr Rgb failing{0.95, 0.45, 0.00};
constexpr Rgb circleGrey{0.66, 0.66, 0.70};
constexpr Rgb frameGrey{0.78, 0.78, 0.80};
constexpr Rgb sphereGrey{0.40, 0.40, 0.45};

// The diagram's radii, the unit circle being the Gauss sphere's section.
constexpr double barsFrom = 1.03, barsTo = 1.18;   // the normals' count, outside the circle
constexpr double bandFrom = 1.25, bandTo = 1.35;   // the view vectors that cull
constexpr double viewTip = 1.44;                   // v and the corner vectors cross the band
constexpr double arcRadius = 1.52, outerArcRadius = 1.62;
constexpr double axisTip = 1.72;
constexpr double alphaRadius = 0.42;
constexpr double halfWidth = 1.75, top = 1.82;     // with room for labels around

glm::dvec2 direction(double angle) { return {std::sin(angle), std::cos(angle)}; }
std::string angleText(double radians) { return lessontext::degrees(glm::degrees(radians)); }
// The octagon's edge k as g with a subscript, counted from 1: g₃.
std::string edgeName(size_t k) { return "g" + std::string("\u2081\u2082\u2083\u2084\u2085\u2086\u2087\u2088").substr(3 * (k % 8), 3); }

// Draws into a figure with a transform from the drawing's own units to pixels.
struct Pen {
    CrossSectionFigure& figure;
    glm::dvec2 origin;
    double scale;
    double unit;

    glm::dvec2 at(const glm::dvec2& p) const { return origin + scale * p; }

    void line(std::vector<glm::dvec2> points, const Rgb& colour, double width) const {
        for (glm::dvec2& p : points) p = at(p);
        figure.shapes.push_back({std::move(points), false, colour, width * unit});
    }
    // Pixel-sized dashes along a polyline (OpenGL 3 lines have no stipple).
    void dashed(const std::vector<glm::dvec2>& points, const Rgb& colour, double width) const {
        const double on = 7.0 * unit, off = 5.0 * unit;
        std::vector<glm::dvec2> dash;
        double phase = 0.0;
        for (size_t i = 0; i + 1 < points.size(); ++i) {
            const glm::dvec2 a = at(points[i]), b = at(points[i + 1]);
            const double length = glm::length(b - a);
            for (double s = 0.0; s < length;) {
                const bool drawing = phase < on;
                const double step = std::min(length - s, drawing ? on - phase : on + off - phase);
                if (drawing) {
                    if (dash.empty()) dash.push_back(a + (b - a) * (s / length));
                    dash.push_back(a + (b - a) * ((s + step) / length));
                } else if (!dash.empty()) {
                    figure.shapes.push_back({dash, false, colour, width * unit});
                    dash.clear();
                }
                s += step;
                phase = std::fmod(phase + step, on + off);
            }
        }
        if (dash.size() > 1) figure.shapes.push_back({dash, false, colour, width * unit});
    }
    void triangles(std::vector<glm::dvec2> corners, const Rgb& colour, bool underLabels = false) const {
        for (glm::dvec2& p : corners) p = at(p);
        figure.shapes.push_back({std::move(corners), true, colour, 1.0, underLabels});
    }
    // An arrow from `from` to `to` (own units), its head `head` pixels long.
    void arrow(const glm::dvec2& from, const glm::dvec2& to, const Rgb& colour, double width, bool dashedShaft = false) const {
        const glm::dvec2 a = at(from), b = at(to);
        if (glm::length(b - a) < 1.0) return;
        const glm::dvec2 along = glm::normalize(b - a), across(-along.y, along.x);
        const double head = (9.0 + 1.5 * width) * unit, wing = (3.0 + 0.6 * width) * unit;
        const glm::dvec2 base = b - along * std::min(head, 0.6 * glm::length(b - a));
        const std::vector<glm::dvec2> shaft{a, base + along * (0.3 * head)};
        if (dashedShaft)
            Pen{figure, {0.0, 0.0}, 1.0, unit, std::nullopt}.dashed(shaft, colour, width);
        else
            figure.shapes.push_back({shaft, false, colour, width * unit});
        figure.shapes.push_back({{b, base + across * wing, base - across * wing}, true, colour, 1.0});
    }
    void dot(const glm::dvec2& centre, double radiusPixels, const Rgb& colour) const {
        std::vector<glm::dvec2> corners;
        const glm::dvec2 c = at(centre);
        for (int i = 0; i < 16; ++i) {
            corners.push_back(c);
            corners.push_back(c + radiusPixels * unit * direction(2.0 * pi * i / 16));
            corners.push_back(c + radiusPixels * unit * direction(2.0 * pi * (i + 1) / 16));
        }
        figure.shapes.push_back({std::move(corners), true, colour, 1.0});
    }
    std::optional<PixelBox> frame;  // labels stay in it if they can
    void label(const std::string& text, const glm::dvec2& anchor, const glm::dvec2& toward, const Rgb& colour) const {
        figure.labels.push_back({text, at(anchor), toward, colour, frame});
    }
};

// An arc of radius `radius` about the origin from angle `from` to `to` (angles from V1).
std::vector<glm::dvec2> arc(double radius, double from, double to, const glm::dvec2& centre = {0.0, 0.0}) {
    const int steps = std::max(2, int(std::ceil(std::abs(to - from) / (pi / 90.0))));
    std::vector<glm::dvec2> points;
    for (int i = 0; i <= steps; ++i) points.push_back(centre + radius * direction(from + (to - from) * i / steps));
    return points;
}

// A ring between two radii over [from, to], as triangles.
std::vector<glm::dvec2> ring(double inner, double outer, double from, double to) {
    const int steps = std::max(2, int(std::ceil(std::abs(to - from) / (pi / 120.0))));
    std::vector<glm::dvec2> corners;
    for (int i = 0; i < steps; ++i) {
        const double a = from + (to - from) * i / steps, b = from + (to - from) * (i + 1) / steps;
        corners.insert(corners.end(), {inner * direction(a), outer * direction(a), outer * direction(b)});
        corners.insert(corners.end(), {inner * direction(a), outer * direction(b), inner * direction(b)});
    }
    return corners;
}

// How low the diagram reaches (below the centre when v or a normal points down).
double diagramBottom(const CrossSection& section) {
    double lowest = 0.0;
    for (double a : section.normalAngles) lowest = std::min(lowest, barsTo * std::cos(a));
    lowest = std::min(lowest, viewTip * std::cos(section.viewAngle));
    for (double a : section.pointAngles) lowest = std::min(lowest, viewTip * std::cos(a));
    for (const AngleRange& range : section.cullRegion)
        for (int i = 0; i <= 64; ++i) lowest = std::min(lowest, bandTo * std::cos(range[0] + (range[1] - range[0]) * i / 64));
    return std::min(-0.25, lowest - 0.3);
}

// The normals' count by whole degree (of their signed angle), as bars outside the circle.
void normalBars(const Pen& pen, const CrossSection& section) {
    std::map<long, std::pair<size_t, double>> bins;  // degree -> count, sum of angles
    for (double a : section.normalAngles) {
        auto& bin = bins[std::lround(glm::degrees(a))];
        ++bin.first;
        bin.second += a;
    }
    size_t most = 1;
    for (const auto& [degree, bin] : bins) most = std::max(most, bin.first);
    std::vector<std::pair<size_t, double>> crowded;  // count, angle
    for (const auto& [degree, bin] : bins) {
        const double angle = bin.second / double(bin.first);
        const double length = 0.03 + (barsTo - barsFrom - 0.03) * double(bin.first) / double(most);
        pen.line({barsFrom * direction(angle), (barsFrom + length) * direction(angle)}, SceneColours::lessonNormal, 3.0);
        if (bin.first >= std::max<size_t>(3, section.normalAngles.size() / 5)) crowded.emplace_back(bin.first, angle);
    }
    // Where many normals share a degree, say how many: they are drawn as one line.
    std::sort(crowded.begin(), crowded.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (size_t i = 0; i < std::min<size_t>(crowded.size(), 2); ++i)
        pen.label(std::to_string(crowded[i].first) + " normals", barsTo * direction(crowded[i].second), direction(crowded[i].second),
                  SceneColours::lessonNormal);
}

// The unit circle, above the diagram's bottom.
void unitCircle(const Pen& pen, double bottom) {
    std::vector<glm::dvec2> circle;
    for (const glm::dvec2& p : arc(1.0, -pi, pi)) {
        if (p.y >= bottom + 0.05) {
            circle.push_back(p);
        } else if (!circle.empty()) {
            if (circle.size() > 1) pen.line(circle, circleGrey, 1.0);
            circle.clear();
        }
    }
    if (circle.size() > 1) pen.line(circle, circleGrey, 1.0);
}

// What the round tests measure the band with: angle B (narrowed by the sphere or r/d when they take some).
void roundMeasure(const Pen& pen, const CrossSection& section) {
    if (section.rule != CullRegionRule::Round || !section.cone) return;
    const double edge = section.regionHalfAngle;
    const bool narrowed = section.narrowing > 0.0;
    if (narrowed) {
        for (double side : {-1.0, 1.0}) pen.dashed({1.0 * direction(side * section.angleB), outerArcRadius * direction(side * section.angleB)}, blueInk, 1.5);
        pen.line(arc(outerArcRadius, 0.0, section.angleB), blueInk, 1.5);
        pen.label("B = " + angleText(section.angleB), outerArcRadius * direction(0.5 * section.angleB), direction(0.5 * section.angleB), blueInk);
        const double from = std::max(0.0, section.angleB - section.narrowing);
        pen.line(arc(arcRadius, from, section.angleB), blueInk, 2.5);
        const std::string name = section.test == CullTest::Sphere ? "asin(r/d) = " : "r/d takes ";
        pen.label(name + angleText(section.angleB - from), arcRadius * direction(0.5 * (from + section.angleB)),
                  direction(0.5 * (from + section.angleB) + 0.4), blueInk);
    } else {
        pen.line(arc(arcRadius, 0.0, edge), blueInk, 1.5);
        pen.label("B = " + angleText(edge), arcRadius * direction(0.5 * edge), direction(0.5 * edge), blueInk);
    }
    if (edge > 0.0)
        for (double side : {-1.0, 1.0}) pen.line({barsTo * direction(side * edge), (bandTo + 0.04) * direction(side * edge)}, blueInk, 1.5);
}

void diagram(const Pen& pen, const CrossSection& section, double bottom) {
    const bool cone = section.cone;
    const std::string& v = section.viewName;
    // The band of view vectors that cull, under everything else.
    for (const AngleRange& range : section.cullRegion) pen.triangles(ring(bandFrom, bandTo, range[0], range[1]), bandBlue);
    unitCircle(pen, bottom);
    roundMeasure(pen, section);
    if (section.rule == CullRegionRule::Octagon && cone) {
        for (double side : {-1.0, 1.0}) pen.dashed({1.0 * direction(side * section.angleB), bandTo * direction(side * section.angleB)}, circleGrey, 1.5);
        if (section.hasRegion()) {
            const AngleRange& range = section.cullRegion[0];
            for (int k = 0; k < 2; ++k) {
                const double trace = range[k];
                pen.line({{0.0, 0.0}, (bandTo + 0.08) * direction(trace)}, gold, 2.0);
                pen.label(edgeName(section.boundingEdges[k]) + "\u00b7" + v + " = 0", (bandTo + 0.08) * direction(trace), direction(trace), gold);
            }
        }
    }
    if (cone)
        for (double side : {-1.0, 1.0}) pen.line({{0.0, 0.0}, (barsTo + 0.04) * direction(side * section.alpha)}, coneGreen, 3.0);
    // V1 (dashed, so that normals along it still show), the normals.
    pen.arrow({0.0, 0.0}, {0.0, axisTip}, darkRed, 2.0, true);
    for (double a : section.normalAngles) pen.line({{0.0, 0.0}, direction(a)}, SceneColours::lessonNormal, 1.5);
    // The two edges over the normals: the bars outside the circle still show every normal.
    if (section.rule == CullRegionRule::Octagon && section.hasRegion())
        for (int k = 0; k < 2; ++k) pen.arrow({0.0, 0.0}, 0.8 * direction(section.boundingEdgeAngles[k]), gold, 2.5);
    if (cone) pen.line(arc(alphaRadius, -section.alpha, 0.0), coneGreen, 2.5);
    // The view vectors: the corners' (or vertices') with the tightest as v, else v alone.
    if (!section.pointAngles.empty()) {
        for (size_t i = 0; i < section.pointAngles.size(); ++i) {
            if (i == section.tightestPoint) continue;
            const double a = section.pointAngles[i];
            const bool in = section.inRegion(a);
            pen.line({{0.0, 0.0}, viewTip * direction(a)}, in ? darkRed : failing, in ? 1.2 : 2.0);
        }
    }
    const bool tightFails = !section.pointAngles.empty() && !section.inRegion(section.viewAngle);
    pen.arrow({0.0, 0.0}, viewTip * direction(section.viewAngle), tightFails ? failing : darkRed, 3.0);
    // Labels, the most needed first.
    pen.label(cone ? "V1" : "axis", {0.0, axisTip}, {0.0, 1.0}, darkRed);
    const std::string lowest = section.test == CullTest::Vertices ? ": lowest vertex" : ": lowest corner";
    pen.label(v + (section.pointAngles.empty() ? "" : lowest), viewTip * direction(section.viewAngle),
              direction(section.viewAngle), tightFails ? failing : darkRed);
    if (cone) pen.label("\u03b1 = " + angleText(section.alpha), alphaRadius * direction(-section.alpha), direction(-section.alpha - pi / 2), coneGreen);
    if (section.rule == CullRegionRule::Octagon && section.hasRegion())
        for (int k = 0; k < 2; ++k)
            pen.label(edgeName(section.boundingEdges[k]), 0.8 * direction(section.boundingEdgeAngles[k]), direction(section.boundingEdgeAngles[k]), gold);
    normalBars(pen, section);
    if (section.hasRegion()) {
        // At the band's end away from v, where it is less crowded.
        const AngleRange& range = section.cullRegion.front();
        const double end = std::abs(range[0] - section.viewAngle) > std::abs(range[1] - section.viewAngle) ? range[0] : range[1];
        const double inside = end == range[0] ? std::min(range[0] + 0.05, 0.5 * (range[0] + range[1])) : std::max(range[1] - 0.05, 0.5 * (range[0] + range[1]));
        pen.label(v + " here: culled", bandTo * direction(inside), direction(end), blueInk);
    }
}

// A convex polygon cut to a box (Sutherland-Hodgman, one side at a time).
std::vector<glm::dvec2> clippedTo(const PixelBox& box, std::vector<glm::dvec2> polygon) {
    auto cut = [&polygon](auto inside, auto crossing) {
        std::vector<glm::dvec2> kept;
        for (size_t i = 0; i < polygon.size(); ++i) {
            const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
            if (inside(a)) kept.push_back(a);
            if (inside(a) != inside(b)) kept.push_back(crossing(a, b));
        }
        polygon = kept;
    };
    auto atX = [](double x) { return [x](glm::dvec2 a, glm::dvec2 b) { return a + (b - a) * ((x - a.x) / (b.x - a.x)); }; };
    auto atY = [](double y) { return [y](glm::dvec2 a, glm::dvec2 b) { return a + (b - a) * ((y - a.y) / (b.y - a.y)); }; };
    cut([&](glm::dvec2 p) { return p.x >= box.x0; }, atX(box.x0));
    cut([&](glm::dvec2 p) { return p.x <= box.x1; }, atX(box.x1));
    cut([&](glm::dvec2 p) { return p.y >= box.y0; }, atY(box.y0));
    cut([&](glm::dvec2 p) { return p.y <= box.y1; }, atY(box.y1));
    return polygon;
}

// The eye and the test's point in the page, in the page's own units (mesh units).
struct InsetContent {
    glm::dvec2 low{0.0}, high{0.0};
};

InsetContent insetBounds(const CrossSectionPlace& place) {
    glm::dvec2 low = glm::min(place.eye, place.target), high = glm::max(place.eye, place.target);
    const glm::dvec2 r(place.sectionRadius);
    if (place.sectionRadius > 0.0) {
        low = glm::min(low, place.centre - r);
        high = glm::max(high, place.centre + r);
    }
    // A little of the eyes that cull, behind the point, without letting them take the figure over.
    const double size = std::max({high.x - low.x, high.y - low.y, 2.0 * place.radius, 1e-9});
    low = glm::min(low, place.target - glm::dvec2(0.15 * size, 0.25 * size));
    high = glm::max(high, place.target + glm::dvec2(0.15 * size, 0.15 * size));
    return {low, high};
}

void inset(const Pen& pen, const CrossSection& section, const PixelBox& frame) {
    const CrossSectionPlace& place = section.place;
    // The eyes that cull, cut to the frame.
    std::vector<glm::dvec2> eyes;
    for (const auto& triangle : place.cullingEyes) {
        const std::vector<glm::dvec2> inside = clippedTo(frame, {pen.at(triangle[0]), pen.at(triangle[1]), pen.at(triangle[2])});
        for (size_t k = 1; k + 1 < inside.size(); ++k) eyes.insert(eyes.end(), {inside[0], inside[k], inside[k + 1]});
    }
    if (!eyes.empty()) pen.figure.shapes.push_back({eyes, true, paleBlue, 1.0, true});
    const Pen screen{pen.figure, {0.0, 0.0}, 1.0, pen.unit, std::nullopt};
    screen.line({{frame.x0, frame.y0}, {frame.x1, frame.y0}, {frame.x1, frame.y1}, {frame.x0, frame.y1}, {frame.x0, frame.y0}}, frameGrey, 1.0);
    const double toPixels = pen.scale;
    if (place.sectionRadius * toPixels > 1.0) pen.line(arc(place.sectionRadius, -pi, pi, place.centre), sphereGrey, 1.5);
    const bool sphere = !place.toApex;
    const glm::dvec2 toTarget = place.target - place.eye;
    const double d = glm::length(toTarget);
    if (sphere && place.distance > place.radius && d > 0.0) {
        // r, and the two tangents from the eye that make asin(r/d) with v.
        const glm::dvec2 along = toTarget / d;
        // r drawn across v on the side away from V1, which is drawn up from the centre.
        const glm::dvec2 across = along.x >= 0.0 ? glm::dvec2(along.y, -along.x) : glm::dvec2(-along.y, along.x);
        pen.line({place.centre, place.centre + place.radius * across}, sphereGrey, 1.5);
        pen.label("r = " + lessontext::number(place.radius), place.centre + 0.5 * place.radius * across, across, sphereGrey);
        if (section.test == CullTest::Sphere) {
            const double tangentLength = std::sqrt(d * d - place.radius * place.radius);
            for (double side : {-1.0, 1.0}) {
                const double turn = side * place.spread;
                const glm::dvec2 tangent = along * std::cos(turn) + across * std::sin(turn);
                pen.line({place.eye, place.eye + tangentLength * tangent}, sphereGrey, 1.0);
            }
            const double arcLength = std::max(0.3 * d, 28.0 * pen.unit / toPixels);
            const double base = std::atan2(along.x, along.y);
            pen.line(arc(arcLength, base, base - place.spread, place.eye), blueInk, 2.0);
            pen.label("asin(r/d)", place.eye + arcLength * direction(base - 0.5 * place.spread),
                      direction(base - 0.5 * place.spread - pi / 2), blueInk);
        }
    }
    // V1 at the target, v from the eye to it, the eye.
    const double frameSize = std::min(frame.width(), frame.height()) / toPixels;
    pen.arrow(place.target, place.target + glm::dvec2(0.0, 0.22 * frameSize), darkRed, 1.5, true);
    pen.arrow(place.eye, place.target, darkRed, 2.5);
    pen.dot(place.target, 3.5, place.toApex ? darkRed : sphereGrey);
    pen.dot(place.eye, 4.0, ink);
    const glm::dvec2 away = d > 0.0 ? -toTarget / d : glm::dvec2(0.0, -1.0);
    const glm::dvec2 side = d > 0.0 ? glm::dvec2(-toTarget.y, toTarget.x) / d : glm::dvec2(1.0, 0.0);
    pen.label("eye", place.eye, away, ink);
    pen.label(place.toApex ? "apex" : "centre", place.target, {1.0, -0.3}, place.toApex ? darkRed : sphereGrey);
    pen.label(sphere ? section.viewName + ", d = " + lessontext::number(place.distance) : section.viewName, 0.5 * (place.eye + place.target), side, darkRed);
    pen.label("V1", place.target + glm::dvec2(0.0, 0.22 * frameSize), {0.0, 1.0}, darkRed);
}

}  // namespace

CrossSectionFigure drawCrossSection(const CrossSection& section, const PixelBox& area, double unit) {
    CrossSectionFigure figure;
    const double bottom = diagramBottom(section);
    const double diagramWidth = 2.0 * halfWidth, diagramHeight = top - bottom;
    const bool withInset = section.place.shown;
    const InsetContent content = withInset ? insetBounds(section.place) : InsetContent{};
    const glm::dvec2 contentSize = glm::max(content.high - content.low, glm::dvec2(1e-12));
    const double aspect = std::clamp(contentSize.x / contentSize.y, 0.7, 1.3);
    const double insetHeight = 0.65 * std::min(diagramHeight, 3.0), insetWidth = aspect * insetHeight, gap = 0.15;
    // Side by side or one above the other, whichever draws the diagram larger.
    const double byWidth = withInset ? std::min(area.width() / (diagramWidth + gap + insetWidth), area.height() / std::max(diagramHeight, insetHeight))
                                     : std::min(area.width() / diagramWidth, area.height() / diagramHeight);
    const double byHeight = withInset ? std::min(area.width() / std::max(diagramWidth, insetWidth), area.height() / (diagramHeight + gap + insetHeight)) : 0.0;
    const bool sideBySide = byWidth >= byHeight;
    const double scale = std::max(sideBySide ? byWidth : byHeight, 1e-6);
    const glm::dvec2 total = !withInset ? glm::dvec2(diagramWidth, diagramHeight)
                             : sideBySide ? glm::dvec2(diagramWidth + gap + insetWidth, std::max(diagramHeight, insetHeight))
                                          : glm::dvec2(std::max(diagramWidth, insetWidth), diagramHeight + gap + insetHeight);
    const glm::dvec2 corner = glm::dvec2(area.x0 + 0.5 * (area.width() - scale * total.x), area.y0 + 0.5 * (area.height() - scale * total.y));
    // The diagram's origin (the Gauss sphere's centre) in pixels.
    glm::dvec2 diagramCorner = corner + (sideBySide ? glm::dvec2(0.0, 0.5 * scale * (total.y - diagramHeight))
                                                    : glm::dvec2(0.5 * scale * (total.x - diagramWidth), scale * (total.y - diagramHeight)));
    const Pen pen{figure, diagramCorner + scale * glm::dvec2(halfWidth, -bottom), scale, unit, std::nullopt};
    diagram(pen, section, bottom);
    if (withInset) {
        const glm::dvec2 insetCorner = corner + (sideBySide ? glm::dvec2(scale * (diagramWidth + gap), 0.5 * scale * (total.y - insetHeight))
                                                            : glm::dvec2(0.5 * scale * (total.x - insetWidth), 0.0));
        const PixelBox frame{insetCorner.x, insetCorner.y, insetCorner.x + scale * insetWidth, insetCorner.y + scale * insetHeight};
        // The content fitted into the frame with a margin, centred.
        const double fit = 0.84 * std::min(frame.width() / contentSize.x, frame.height() / contentSize.y);
        const glm::dvec2 middle = 0.5 * (content.low + content.high);
        const glm::dvec2 frameMiddle(0.5 * (frame.x0 + frame.x1), 0.5 * (frame.y0 + frame.y1));
        inset(Pen{figure, frameMiddle - fit * middle, fit, unit, frame}, section, frame);
    }
    return figure;
}

}  // namespace conescope
