// The textbook figure of seed 000 for one lesson: the plane spanned by the cone axis V1 and the view
// vector v, V1 pointing up (y) and v leaning right (x). It holds the face normals, the cone's two
// boundary lines, the axis, the view vector and the line perpendicular to the axis, plus the wedge
// of view vectors from which the test culls. Plain 2D coordinates (unit circle = unit vectors); the
// scene only draws them.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Lesson.h"

namespace conescope {

struct CrossSection {
    glm::dvec3 up{0.0, 1.0, 0.0};     // V1 in 3D
    glm::dvec3 right{1.0, 0.0, 0.0};  // v's part across V1 (any perpendicular when v is along V1)
    // Each face normal turned about V1 into the plane, keeping its angle to V1, on the right when it
    // leans towards v: a normal inside the cone stays between the boundary lines.
    std::vector<glm::dvec2> normals;
    bool cone = false;                          // a cone narrower than a half-sphere holds the normals
    double alpha = 0.0;                         // the cone's half-angle (radians)
    double angleB = 0.0;                        // 90 degrees - alpha
    glm::dvec2 axis{0.0, 1.0};
    std::array<glm::dvec2, 2> boundaries{};     // unit directions at -alpha and +alpha from V1
    std::array<glm::dvec2, 2> perpendicular{};  // the line through the origin at right angles to V1
    glm::dvec2 view{0.0, 1.0};                  // the unit view vector v (for a far eye: d)
    // The view vectors in this plane from which the test culls: angles from V1 (negative left), an
    // empty range (first >= second) when there are none here or the test has no such wedge (the
    // oracle, a cluster without a cone). The round tests' wedge is symmetric; the octagon's is not.
    std::array<double, 2> cullingAngles{0.0, 0.0};
    bool hasWedge() const { return cullingAngles[0] < cullingAngles[1]; }
    // The octagon test: where its eight-sided cone of normals meets the plane (unit directions).
    bool octagon = false;
    std::array<glm::dvec2, 2> octagonBoundaries{};
    std::string title;    // "cluster 12: the plane of V1 and v"
    std::string caption;  // what the figure shows, in words
};

CrossSection crossSectionOf(const Lesson& lesson);

}  // namespace conescope
