// The cross-section (core/CrossSection.h) as shapes and labels in pixels, laid out for one picture:
// the diagram of angles from V1 (the normals and their count, the cone, the band of view vectors
// that cull, v, and what the test compares: B, asin(r/d), the corner vectors, the octagon's planes)
// and, for the apex, octagon and sphere tests from a near eye, a small figure of the eye and the
// test's point in the page. Plain geometry, y up as VTK's display coordinates: the scene turns it
// into actors and places the labels (LabelPlacement.h) where nothing is drawn.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/CrossSection.h"
#include "scene/ClusterPalette.h"
#include "scene/LabelPlacement.h"

namespace conescope {

struct FigureShape {
    std::vector<glm::dvec2> points;  // a polyline, or (filled) triangles, 3 points each
    bool filled = false;
    Rgb colour{0.0, 0.0, 0.0};
    double width = 1.0;              // a line's, in pixels
    bool underLabels = false;        // a pale fill a label may lie on
};

struct FigureLabel {
    std::string text;
    glm::dvec2 anchor{0.0};          // the point it names
    glm::dvec2 toward{0.0, 1.0};     // the side it would rather be on
    Rgb colour{0.0, 0.0, 0.0};
    std::optional<PixelBox> within;  // where it should stay if it can (the small figure's frame)
};

struct CrossSectionFigure {
    std::vector<FigureShape> shapes;  // in drawing order, the last on top
    std::vector<FigureLabel> labels;  // most important first
};

// The figure fitted into `area`; `unit` is a line's width in pixels (larger on big or HiDPI pictures).
CrossSectionFigure drawCrossSection(const CrossSection& section, const PixelBox& area, double unit);

}  // namespace conescope
