#include "OctagonCones.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "Culling.h"  // kCullMargin

namespace conescope {

namespace {

using Point = glm::dvec2;

double turn(const Point& o, const Point& a, const Point& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Convex hull, counter-clockwise (Andrew's monotone chain); only its corners bound the octagon.
std::vector<Point> convexHull(std::vector<Point> points) {
    std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (points.size() < 3) return points;
    std::vector<Point> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0) --k;
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

// The four side directions of an octagon turned by `angle`: 0, 45, 90 and 135 degrees on from it.
std::array<Point, 4> sideDirections(double angle) {
    std::array<Point, 4> directions;
    for (int j = 0; j < 4; ++j) directions[j] = Point(std::cos(angle + j * M_PI / 4.0), std::sin(angle + j * M_PI / 4.0));
    return directions;
}

// Lowest and highest projection of the hull on each direction: the octagon's four strips.
struct Strips {
    std::array<double, 4> low, high;
};

Strips stripsAround(const std::vector<Point>& hull, const std::array<Point, 4>& directions) {
    Strips strips;
    for (int j = 0; j < 4; ++j) {
        strips.low[j] = strips.high[j] = glm::dot(directions[j], hull[0]);
        for (const Point& p : hull) {
            const double s = glm::dot(directions[j], p);
            strips.low[j] = std::min(strips.low[j], s), strips.high[j] = std::max(strips.high[j], s);
        }
    }
    return strips;
}

// The octagon's area, nearly: the rectangle of strips 0 and 2 less the four corners the diagonal
// strips cut off (exact unless two cuts overlap). Only compares turns with each other.
double octagonArea(const Strips& s) {
    const double root2 = std::sqrt(2.0);
    const double corners[4] = {s.high[0] + s.high[2] - root2 * s.high[1], root2 * s.low[1] - s.low[0] - s.low[2],
                               s.high[2] - s.low[0] - root2 * s.high[3], s.high[0] - s.low[2] + root2 * s.low[3]};
    double area = (s.high[0] - s.low[0]) * (s.high[2] - s.low[2]);
    for (double cut : corners) area -= 0.5 * std::max(0.0, cut) * std::max(0.0, cut);
    return area;
}

// The part of a convex polygon where direction.p <= bound (Sutherland-Hodgman, one edge).
std::vector<Point> clip(const std::vector<Point>& polygon, const Point& direction, double bound) {
    std::vector<Point> kept;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Point& a = polygon[i];
        const Point& b = polygon[(i + 1) % polygon.size()];
        const double da = glm::dot(direction, a) - bound, db = glm::dot(direction, b) - bound;
        if (da <= 0.0) kept.push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) kept.push_back(a + (b - a) * (da / (da - db)));
    }
    return kept;
}

// The octagon's corners, counter-clockwise: a square around everything cut by the eight sides;
// corners closer than rounding (a side through a corner) count once.
std::vector<Point> octagonCorners(const Strips& strips, const std::array<Point, 4>& directions, double extent) {
    std::vector<Point> polygon = {{-extent, -extent}, {extent, -extent}, {extent, extent}, {-extent, extent}};
    for (int j = 0; j < 4; ++j) {
        polygon = clip(polygon, directions[j], strips.high[j]);
        polygon = clip(polygon, -directions[j], -strips.low[j]);
    }
    std::vector<Point> corners;
    for (const Point& p : polygon)
        if (corners.empty() || glm::length(p - corners.back()) > 1e-14 * extent) corners.push_back(p);
    while (corners.size() > 1 && glm::length(corners.front() - corners.back()) <= 1e-14 * extent) corners.pop_back();
    return corners;
}

constexpr int kTurns = 16;  // evenly spaced turns tried over the octagon's 45 degree period

}  // namespace

OctagonCone octagonCone(const ConeOfNormals& cone, const glm::dvec3* normals, size_t count) {
    OctagonCone octagon;
    if (!cone.cullable || !(cone.cosHalfAngle > 0.0) || count == 0) return octagon;
    const glm::dvec3& axis = cone.axis;
    const glm::dvec3 u = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 w = glm::cross(axis, u);
    std::vector<Point> points;
    points.reserve(count);
    double reach = 0.0;
    for (size_t i = 0; i < count; ++i) {
        if (normals[i] == glm::dvec3(0.0)) continue;  // a degenerate face: no normal to hold
        const double along = glm::dot(normals[i], axis);
        if (!(along > 0.0)) return octagon;  // the cone holds every normal, so never; but never divide by it
        points.emplace_back(glm::dot(normals[i], u) / along, glm::dot(normals[i], w) / along);
        reach = std::max(reach, glm::length(points.back()));
    }
    if (points.empty()) return octagon;
    const std::vector<Point> hull = convexHull(std::move(points));
    // Turns tried: a side along each edge of the hull (the least area has one there, as the least
    // rectangle does), and evenly spaced ones for hulls of a point or two.
    std::vector<double> turns;
    for (int t = 0; t < kTurns; ++t) turns.push_back(t * (M_PI / 4.0) / kTurns);
    for (size_t i = 0; hull.size() > 1 && i < hull.size(); ++i) {
        const Point edge = hull[(i + 1) % hull.size()] - hull[i];
        turns.push_back(std::atan2(edge.y, edge.x));
    }
    double bestArea = std::numeric_limits<double>::infinity(), bestTurn = 0.0;
    for (double angle : turns) {
        const double area = octagonArea(stripsAround(hull, sideDirections(angle)));
        if (area < bestArea) bestArea = area, bestTurn = angle;
    }
    const std::array<Point, 4> directions = sideDirections(bestTurn);
    Strips strips = stripsAround(hull, directions);
    // Widened by far more than the rounding of the projections and of the corners below, so every
    // normal lies inside the lifted octagon.
    const double pad = 1e-10 * (1.0 + reach);
    for (int j = 0; j < 4; ++j) strips.low[j] -= pad, strips.high[j] += pad;
    const std::vector<Point> corners = octagonCorners(strips, directions, 2.0 * (1.0 + reach));
    if (corners.size() < 3 || corners.size() > 8) return octagon;
    for (size_t k = 0; k < 8; ++k) {
        const Point& c = corners[std::min(k, corners.size() - 1)];
        octagon.edges[k] = glm::normalize(axis + c.x * u + c.y * w);
    }
    octagon.cullable = true;
    return octagon;
}

bool octagonSeesBack(const OctagonCone& octagon, const glm::dvec3& view) {
    const double length = glm::length(view);
    if (!octagon.cullable || !(length > 0.0)) return false;
    for (const glm::dvec3& edge : octagon.edges)
        if (!(glm::dot(edge, view) > kCullMargin * length)) return false;
    return true;
}

double octagonTightest(const OctagonCone& octagon, const glm::dvec3& view) {
    const double length = glm::length(view);
    if (!octagon.cullable || !(length > 0.0)) return -1.0;
    double tightest = 1.0;
    for (const glm::dvec3& edge : octagon.edges) tightest = std::min(tightest, glm::dot(edge, view) / length);
    return tightest;
}

double octagonCullShare(const OctagonCone& octagon) {
    if (!octagon.cullable) return 0.0;
    double perimeter = 0.0;
    for (size_t k = 0; k < 8; ++k)
        perimeter += std::acos(std::clamp(glm::dot(octagon.edges[k], octagon.edges[(k + 1) % 8]), -1.0, 1.0));
    return std::max(0.0, (2.0 * M_PI - perimeter) / (4.0 * M_PI));
}

std::array<glm::dvec3, 8> octagonPyramidEdges(const OctagonCone& octagon) {
    std::array<glm::dvec3, 8> edges{};
    if (!octagon.cullable) return edges;
    glm::dvec3 inside(0.0);  // a direction inside the octagon: the pyramid opens the other way
    for (const glm::dvec3& edge : octagon.edges) inside += edge;
    // Each pair of neighbouring distinct edges gives the pyramid edge perpendicular to both; edges
    // closer than 1e-7 count once, or the cross product of the pair would be mostly rounding.
    std::vector<glm::dvec3> distinct;
    for (const glm::dvec3& edge : octagon.edges)
        if (distinct.empty() || glm::length(edge - distinct.back()) > 1e-7) distinct.push_back(edge);
    while (distinct.size() > 1 && glm::length(distinct.front() - distinct.back()) <= 1e-7) distinct.pop_back();
    std::vector<glm::dvec3> pyramid;
    for (size_t k = 0; k < distinct.size(); ++k) {
        const glm::dvec3 normal = glm::cross(distinct[k], distinct[(k + 1) % distinct.size()]);
        const double length = glm::length(normal);
        if (!(length > 0.0)) continue;
        pyramid.push_back(glm::dot(normal, inside) > 0.0 ? -normal / length : normal / length);
    }
    if (pyramid.empty()) pyramid.push_back(-glm::normalize(inside));  // a single direction: a thin pyramid
    for (size_t k = 0; k < 8; ++k) edges[k] = pyramid[std::min(k, pyramid.size() - 1)];
    return edges;
}

}  // namespace conescope
