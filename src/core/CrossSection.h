// The textbook figure of seed 000 for one lesson, true to the lesson's test: the page is the plane
// of the cone axis V1 (up) and the view vector v (leaning right). Every angle is measured from V1
// in radians, negative to the left. It holds each face normal's angle to V1 (turned about V1 into
// the page), the cone, the view vectors from which the test culls (a region of the page, not of the
// normals), and what the test itself compares: the box's 8 corner vectors, the sphere's asin(r/d),
// the octagon's bounding planes, a record's own rule. Plain numbers; the scene only draws them.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Culling.h"
#include "LessonData.h"

namespace conescope {

// A range of angles from V1, low < high (radians).
using AngleRange = std::array<double, 2>;

// How the region of view vectors that cull is known.
enum class CullRegionRule {
    None,     // the test has no cone to compare (no region)
    Round,    // within regionHalfAngle of V1: v.V1 > cos(regionHalfAngle)
    Octagon,  // g.v > 0 for each of the eight edges g: between the planes of two of them
    Asked,    // the record's own rule, or the oracle: asked from eyes on a circle in the page
};

// Where the eye and the test's point are, in the page (perspective eyes of the apex, octagon and
// sphere tests): 2D coordinates (along right, along V1) around the point v runs to.
struct CrossSectionPlace {
    bool shown = false;
    bool toApex = false;            // v runs to the apex (else to the sphere's centre)
    glm::dvec2 eye{0.0};
    glm::dvec2 target{0.0};         // the apex or the centre: the origin
    glm::dvec2 centre{0.0};         // the bounding sphere's centre, projected into the page
    double sectionRadius = 0.0;     // where the sphere meets the page (0: it does not)
    double radius = 0.0, distance = 0.0;  // r, and d = |c - e|
    double spread = 0.0;            // asin(r/d), radians
    // The eyes in the page the test culls from, as triangles (apex tests: the mirror of the region
    // of v behind the apex; sphere tests: the region that opens with the distance).
    std::vector<std::array<glm::dvec2, 3>> cullingEyes;
};

struct CrossSection {
    uint32_t cluster = 0;
    CullTest test = kDefaultTest;
    bool orthographic = false;
    std::string viewName = "v";       // "d" for a far eye
    glm::dvec3 up{0.0, 1.0, 0.0};     // V1 in 3D
    glm::dvec3 right{1.0, 0.0, 0.0};  // v's part across V1 (any perpendicular when v is along V1)
    // Each face normal's angle to V1, on the side it leans to (positive: towards v).
    std::vector<double> normalAngles;
    bool cone = false;                // a cone narrower than a half-sphere holds the normals
    double alpha = 0.0, angleB = 0.0;
    double viewAngle = 0.0;           // v's angle from V1 (>= 0; for the box and vertex tests the tightest point's)
    // The box and vertex tests from a near eye: each point's view vector (turned into the page like
    // the normals) and the one with the lowest v.V1, which the verdict turns on.
    std::vector<double> pointAngles;
    size_t tightestPoint = 0;
    // The view vectors in the page from which the test culls, and how they are known.
    CullRegionRule rule = CullRegionRule::None;
    std::vector<AngleRange> cullRegion;
    double regionHalfAngle = 0.0;     // Round: the region's half-angle
    double narrowing = 0.0;           // Round: how much the bound takes off B (asin(r/d), or B - acos(sin a + r/d))
    // Octagon: the two edges whose planes g.v = 0 bound the region (left, right) and each edge's
    // direction projected into the page (angle from V1).
    std::array<size_t, 2> boundingEdges{};
    std::array<double, 2> boundingEdgeAngles{};
    bool culls = false;               // the core's verdict (the lesson's)
    CrossSectionPlace place;
    std::string title;
    std::string caption;              // what the figure shows, in words, per test

    bool hasRegion() const { return !cullRegion.empty(); }
    bool inRegion(double angle) const;
};

// A text of a picture of the figure and where it was drawn: [x0, y0, x1, y1] in pixels from the
// picture's top-left corner, y down.
struct CrossSectionLabel {
    std::string text;
    std::array<double, 4> box{};
};

// `input`: the clusters the lesson was made on (the records' rules and the oracle are asked there).
CrossSection crossSectionOf(const Lesson& lesson, const CullingInput& input);

// The figure's words (CrossSectionCaption.cpp).
std::string crossSectionCaption(const Lesson& lesson, const CrossSection& section);

}  // namespace conescope
