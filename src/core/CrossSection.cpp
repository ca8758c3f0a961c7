#include "CrossSection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "LessonText.h"
#include "RecordTests.h"

namespace conescope {

using namespace lessontext;

namespace {

glm::dvec2 direction(double angleFromAxis) { return {std::sin(angleFromAxis), std::cos(angleFromAxis)}; }

// The plane's right-hand direction: v's part across V1, or any perpendicular when v is along V1.
glm::dvec3 rightOf(const glm::dvec3& up, const glm::dvec3& view) {
    glm::dvec3 across = view - glm::dot(view, up) * up;
    if (glm::length(across) > 1e-9) return glm::normalize(across);
    const glm::dvec3 helper = std::abs(up.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(up, helper));
}

// The view vectors in the plane that a round cone test culls from: within acos(threshold) of V1.
std::array<double, 2> roundWedge(double threshold) {
    if (!(threshold < 1.0)) return {0.0, 0.0};
    const double half = std::acos(std::max(threshold, -1.0));
    return {-half, half};
}

// The octagon test culls v = sin(psi) right + cos(psi) up when g.v > 0 for each edge g, that is
// |psi - theta_g| < 90 degrees with theta_g = atan2(g.right, g.up).
std::array<double, 2> octagonWedge(const std::array<glm::dvec3, 8>& edges, const glm::dvec3& up, const glm::dvec3& right) {
    double low = -M_PI, high = M_PI;
    for (const glm::dvec3& g : edges) {
        const double theta = std::atan2(glm::dot(g, right), glm::dot(g, up));
        low = std::max(low, theta - M_PI / 2.0);
        high = std::min(high, theta + M_PI / 2.0);
    }
    return {low, high};
}

// Where the octagon's cone meets the plane on the side `sign` (+1 right, -1 left): the ray from the
// axis along +-right in the plane tangent to the unit sphere at V1 (the gnomonic projection, in which
// the octagon is a convex polygon around the axis) leaves the polygon at distance t.
glm::dvec2 octagonBoundary(const std::array<glm::dvec3, 8>& edges, const glm::dvec3& up, const glm::dvec3& right, double sign) {
    const glm::dvec3 third = glm::cross(up, right);
    std::array<glm::dvec2, 8> polygon;
    for (size_t k = 0; k < 8; ++k) {
        const glm::dvec3 p = edges[k] / std::max(glm::dot(edges[k], up), 1e-12);
        polygon[k] = {glm::dot(p, right), glm::dot(p, third)};
    }
    double reach = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < 8; ++k) {
        const glm::dvec2 a = polygon[k], b = polygon[(k + 1) % 8];
        // a + u (b - a) on the x axis (y = 0), with u in [0, 1] and x on the `sign` side.
        if ((a.y > 0.0) == (b.y > 0.0) && a.y != 0.0) continue;
        const double u = a.y == b.y ? 0.0 : a.y / (a.y - b.y);
        const double x = a.x + u * (b.x - a.x);
        if (x * sign > 0.0) reach = std::min(reach, std::abs(x));
    }
    if (!std::isfinite(reach)) return {0.0, 1.0};
    return glm::normalize(glm::dvec2(sign * reach, 1.0));
}

std::string captionOf(const Lesson& lesson, const CrossSection& section) {
    std::string text = "Red: the face normals, each turned about V1 into the page, keeping its angle to V1.";
    if (section.cone)
        text += " Green: the cone's boundary lines, \u03b1 = " + degrees(glm::degrees(section.alpha)) +
                " from V1. Blue: the line perpendicular to V1, B = " + degrees(glm::degrees(section.angleB)) +
                " from the boundary lines.";
    if (section.octagon) text += " Yellow: where the octagon test's eight-sided cone meets the page.";
    const double vAngle = glm::degrees(std::atan2(section.view.x, section.view.y));
    const std::string v = lesson.eye.orthographic ? "d" : "v";
    if (section.hasWedge() && readsOwnRecord(lesson.test))
        text += " This cone culls when " + v + " lies in the shaded wedge (" + v + " is " + degrees(vAngle) +
                " from V1); the record's test compares its own cone and bound (step 5), so its verdict can differ.";
    else if (section.hasWedge())
        text += " The test culls when " + v + " lies in the shaded wedge; " + v + " is " + degrees(vAngle) + " from V1.";
    else if (lesson.test != CullTest::Oracle)
        text += " No " + v + " in this page makes the test cull.";
    return text;
}

}  // namespace

CrossSection crossSectionOf(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    CrossSection section;
    section.up = glm::length(why.axis) > 0.0 ? glm::normalize(why.axis) : glm::dvec3(0.0, 0.0, 1.0);
    section.right = rightOf(section.up, why.view);
    for (const glm::dvec3& n : lesson.normals) {
        const double along = std::clamp(glm::dot(n, section.up), -1.0, 1.0);
        const double side = glm::dot(n, section.right) < 0.0 ? -1.0 : 1.0;
        section.normals.push_back({side * std::sqrt(std::max(0.0, 1.0 - along * along)), along});
    }
    section.cone = why.cullable;
    section.alpha = glm::radians(why.halfAngleDegrees);
    section.angleB = glm::radians(why.angleBDegrees);
    section.boundaries = {direction(-section.alpha), direction(section.alpha)};
    section.perpendicular = {glm::dvec2(-1.0, 0.0), glm::dvec2(1.0, 0.0)};
    const double viewUp = glm::dot(why.view, section.up);
    section.view = glm::length(why.view) > 0.0 ? glm::dvec2(glm::dot(why.view, section.right), viewUp) : glm::dvec2(0.0, 1.0);
    if (why.cullable && lesson.test != CullTest::Oracle && !std::isnan(why.margin)) {
        if (lesson.test == CullTest::Octagon) {
            section.cullingAngles = octagonWedge(why.octagonEdges, section.up, section.right);
        } else {
            double threshold = why.threshold;
            if (lesson.test == CullTest::MeshoptSphere && !lesson.eye.orthographic && why.distance > 0.0)
                threshold += why.radius / why.distance;
            section.cullingAngles = roundWedge(threshold);
        }
    }
    if (why.cullable && lesson.test == CullTest::Octagon) {
        section.octagon = true;
        section.octagonBoundaries = {octagonBoundary(why.octagonEdges, section.up, section.right, -1.0),
                                     octagonBoundary(why.octagonEdges, section.up, section.right, 1.0)};
    }
    section.title = "Cluster " + std::to_string(lesson.cluster) + ": the plane of V1 and " + (lesson.eye.orthographic ? "d" : "v");
    section.caption = captionOf(lesson, section);
    return section;
}

}  // namespace conescope
