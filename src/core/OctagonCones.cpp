#include "OctagonCones.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <vector>

#include "CullTest.h"  // kCullMargin

namespace conescope {

namespace {

using Point = glm::dvec2;

// The normals seen from the cone's axis: n / (n.axis) in the plane that touches the unit sphere
// there (u, w), with the normal each point came from. Empty when some normal is not in front of
// the axis (the cone is not cullable); zero normals are left out.
struct Projection {
    glm::dvec3 u, w;
    std::vector<Point> points;
    std::vector<uint32_t> source;  // index of each point's normal
    double reach = 0.0;            // the largest |point|
};

Projection project(const glm::dvec3& axis, const glm::dvec3* normals, size_t count) {
    Projection projection;
    projection.u = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
    projection.w = glm::cross(axis, projection.u);
    projection.points.reserve(count);
    projection.source.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        if (normals[i] == glm::dvec3(0.0)) continue;  // a degenerate face: no normal to hold
        const double along = glm::dot(normals[i], axis);
        if (!(along > 0.0)) return {};  // the cone holds every normal, so never; but never divide by it
        projection.points.emplace_back(glm::dot(normals[i], projection.u) / along, glm::dot(normals[i], projection.w) / along);
        projection.source.push_back(uint32_t(i));
        projection.reach = std::max(projection.reach, glm::dot(projection.points.back(), projection.points.back()));
    }
    projection.reach = std::sqrt(projection.reach);  // one root: the largest length is the root of the largest square
    return projection;
}

double turn(const Point& o, const Point& a, const Point& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Convex hull, counter-clockwise (Andrew's monotone chain), as indices into `points`. Points
// strictly inside the quadrilateral of the four extreme points (lowest and highest x + y and
// x - y) cannot be corners and are left out before the sort: most of a cluster's normals.
std::vector<uint32_t> convexHull(const std::vector<Point>& points) {
    std::vector<uint32_t> order;
    order.reserve(points.size());
    if (points.size() >= 8) {
        uint32_t extreme[4] = {0, 0, 0, 0};  // min x+y, max x-y, max x+y, min x-y: counter-clockwise
        double lowSum = points[0].x + points[0].y, highSum = lowSum;
        double highDifference = points[0].x - points[0].y, lowDifference = highDifference;
        for (uint32_t i = 1; i < points.size(); ++i) {
            const double sum = points[i].x + points[i].y, difference = points[i].x - points[i].y;
            if (sum < lowSum) lowSum = sum, extreme[0] = i;
            if (difference > highDifference) highDifference = difference, extreme[1] = i;
            if (sum > highSum) highSum = sum, extreme[2] = i;
            if (difference < lowDifference) lowDifference = difference, extreme[3] = i;
        }
        // Each side's start, direction and margin, once for all the points.
        Point start[4], along[4];
        double margin[4];
        for (int k = 0; k < 4; ++k) {
            start[k] = points[extreme[k]];
            along[k] = points[extreme[(k + 1) % 4]] - start[k];
            const double scale = std::abs(along[k].x) + std::abs(along[k].y);
            margin[k] = 1e-9 * scale * (scale + 1.0);
        }
        for (uint32_t i = 0; i < points.size(); ++i) {
            bool inside = true;  // strictly left of every side of the quadrilateral (a margin against rounding)
            for (int k = 0; k < 4 && inside; ++k)
                inside = along[k].x * (points[i].y - start[k].y) - along[k].y * (points[i].x - start[k].x) > margin[k];
            if (!inside) order.push_back(i);
        }
    } else {
        for (uint32_t i = 0; i < points.size(); ++i) order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return points[a].x < points[b].x || (points[a].x == points[b].x && points[a].y < points[b].y);
    });
    if (order.size() < 3) return order;
    std::vector<uint32_t> hull(2 * order.size());
    size_t k = 0;
    for (size_t i = 0; i < order.size(); ++i) {
        while (k >= 2 && turn(points[hull[k - 2]], points[hull[k - 1]], points[order[i]]) <= 0.0) --k;
        hull[k++] = order[i];
    }
    for (size_t i = order.size() - 1, lower = k + 1; i > 0; --i) {
        while (k >= lower && turn(points[hull[k - 2]], points[hull[k - 1]], points[order[i - 1]]) <= 0.0) --k;
        hull[k++] = order[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

// (2 pi - the perimeter of a convex polygon on the unit sphere) / 4 pi: the area of the directions
// that see every corner from behind (the polar polygon), as a share of the sphere.
double polarShare(const glm::dvec3* corners, size_t count) {
    double perimeter = 0.0;
    for (size_t k = 0; count > 1 && k < count; ++k)
        perimeter += std::acos(std::clamp(glm::dot(corners[k], corners[(k + 1) % count]), -1.0, 1.0));
    return std::max(0.0, (2.0 * M_PI - perimeter) / (4.0 * M_PI));
}

// The four side directions of an octagon whose first side runs along `first` (a unit vector):
// 0, 45, 90 and 135 degrees on from it.
std::array<Point, 4> sideDirections(const Point& first) {
    const Point quarter(-first.y, first.x);
    return {first, (first + quarter) * M_SQRT1_2, quarter, (quarter - first) * M_SQRT1_2};
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

// A polygon of at most 16 corners, on the stack: a square cut by eight sides has at most 12. Rounding
// could make a nearly flat polygon cross a side more than twice; a corner beyond the 16th marks it
// overflowed, and the octagon is then given up (not cullable), never written past the end.
struct SmallPolygon {
    std::array<Point, 16> corners;
    size_t size = 0;
    bool overflowed = false;
    void add(const Point& p) {
        if (size < corners.size()) corners[size++] = p;
        else overflowed = true;
    }
};

// The part of a convex polygon where direction.p <= bound (Sutherland-Hodgman, one edge).
SmallPolygon clip(const SmallPolygon& polygon, const Point& direction, double bound) {
    SmallPolygon kept;
    kept.overflowed = polygon.overflowed;
    for (size_t i = 0; i < polygon.size; ++i) {
        const Point& a = polygon.corners[i];
        const Point& b = polygon.corners[(i + 1) % polygon.size];
        const double da = glm::dot(direction, a) - bound, db = glm::dot(direction, b) - bound;
        if (da <= 0.0) kept.add(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) kept.add(a + (b - a) * (da / (da - db)));
    }
    return kept;
}

// The octagon's corners, counter-clockwise: a square around everything cut by the eight sides;
// corners closer than rounding (a side through a corner) count once.
std::vector<Point> octagonCorners(const Strips& strips, const std::array<Point, 4>& directions, double extent) {
    SmallPolygon polygon;
    for (const Point& corner : {Point(-extent, -extent), Point(extent, -extent), Point(extent, extent), Point(-extent, extent)})
        polygon.add(corner);
    for (int j = 0; j < 4; ++j) {
        polygon = clip(polygon, directions[j], strips.high[j]);
        polygon = clip(polygon, -directions[j], -strips.low[j]);
    }
    std::vector<Point> corners;
    if (polygon.overflowed) return corners;  // fewer than three corners: no octagon
    for (size_t i = 0; i < polygon.size; ++i) {
        const Point& p = polygon.corners[i];
        if (corners.empty() || glm::length(p - corners.back()) > 1e-14 * extent) corners.push_back(p);
    }
    while (corners.size() > 1 && glm::length(corners.front() - corners.back()) <= 1e-14 * extent) corners.pop_back();
    return corners;
}

constexpr int kTurns = 16;  // evenly spaced turns tried over the octagon's 45 degree period

}  // namespace

namespace {

// The octagon with these corners in the gnomonic plane about `axis`, lifted to unit edges (the last
// repeated where it has fewer than eight). Not cullable unless it has 3 to 8 corners.
OctagonCone liftedOctagon(const glm::dvec3& axis, const Projection& basis, const std::vector<Point>& corners) {
    OctagonCone octagon;
    if (corners.size() < 3 || corners.size() > 8) return octagon;
    for (size_t k = 0; k < 8; ++k) {
        const Point& c = corners[std::min(k, corners.size() - 1)];
        octagon.edges[k] = glm::normalize(axis + c.x * basis.u + c.y * basis.w);
    }
    octagon.cullable = true;
    return octagon;
}

// The octagon around the hull (indices into projection.points) of the normals projected about
// `cone`'s axis.
OctagonCone octagonAround(const ConeOfNormals& cone, const Projection& projection, const std::vector<uint32_t>& hullIndices) {
    std::vector<Point> hull;
    for (uint32_t i : hullIndices) hull.push_back(projection.points[i]);
    // Turns tried: a side along each edge of the hull (the least area has one there, as the least
    // rectangle does), and evenly spaced ones for hulls of a point or two.
    static const std::array<Point, kTurns> evenTurns = [] {
        std::array<Point, kTurns> turns;
        for (int t = 0; t < kTurns; ++t) turns[t] = Point(std::cos(t * (M_PI / 4.0) / kTurns), std::sin(t * (M_PI / 4.0) / kTurns));
        return turns;
    }();
    double bestArea = std::numeric_limits<double>::infinity();
    Point bestTurn = evenTurns.front();
    auto consider = [&](const Point& first) {
        const double area = octagonArea(stripsAround(hull, sideDirections(first)));
        if (area < bestArea) bestArea = area, bestTurn = first;
    };
    for (const Point& first : evenTurns) consider(first);
    for (size_t i = 0; hull.size() > 1 && i < hull.size(); ++i) {
        const Point edge = hull[(i + 1) % hull.size()] - hull[i];
        const double length = glm::length(edge);
        if (length > 0.0) consider(edge / length);
    }
    const std::array<Point, 4> directions = sideDirections(bestTurn);
    Strips strips = stripsAround(hull, directions);
    // Widened by far more than the rounding of the projections and of the corners below, so every
    // normal lies inside the lifted octagon.
    const double pad = 1e-10 * (1.0 + projection.reach);
    for (int j = 0; j < 4; ++j) strips.low[j] -= pad, strips.high[j] += pad;
    return liftedOctagon(cone.axis, projection, octagonCorners(strips, directions, 2.0 * (1.0 + projection.reach)));
}

// normalsCullShare from the hull of the projected normals: its corners are the normals' hull on the sphere.
double shareOfHull(const glm::dvec3* normals, const Projection& projection, const std::vector<uint32_t>& hullIndices) {
    std::vector<glm::dvec3> corners;
    for (uint32_t i : hullIndices) corners.push_back(normals[projection.source[i]]);
    return polarShare(corners.data(), corners.size());
}

// Whether a cone's axis can serve for the gnomonic projection of the normals it holds.
bool projectsAbout(const ConeOfNormals& cone) { return cone.cullable && cone.cosHalfAngle > 0.0; }

}  // namespace

std::optional<OctagonStrips> octagonStripsOf(const glm::dvec3& axis, double turn, const glm::dvec3* normals, size_t count) {
    const Projection projection = project(axis, normals, count);
    if (projection.points.empty()) return std::nullopt;
    const Strips strips = stripsAround(projection.points, sideDirections(Point(std::cos(turn), std::sin(turn))));
    OctagonStrips result{axis, turn, strips.low, strips.high};
    const double pad = 1e-10 * (1.0 + projection.reach);
    for (int j = 0; j < 4; ++j) result.low[j] -= pad, result.high[j] += pad;
    return result;
}

OctagonCone octagonFromStrips(const OctagonStrips& strips) {
    const Projection basis = project(strips.axis, nullptr, 0);
    double reach = 0.0;
    for (int j = 0; j < 4; ++j) reach = std::max({reach, std::abs(strips.low[j]), std::abs(strips.high[j])});
    if (!std::isfinite(reach)) return {};
    return liftedOctagon(strips.axis, basis,
                         octagonCorners(Strips{strips.low, strips.high}, sideDirections(Point(std::cos(strips.turn), std::sin(strips.turn))),
                                        2.0 * (1.0 + reach)));
}

OctagonCone octagonCone(const ConeOfNormals& cone, const glm::dvec3* normals, size_t count) {
    if (!projectsAbout(cone)) return {};
    const Projection projection = project(cone.axis, normals, count);
    if (projection.points.empty()) return {};
    return octagonAround(cone, projection, convexHull(projection.points));
}

double normalsCullShare(const glm::dvec3* normals, size_t count, const ConeOfNormals* holding) {
    if (count == 0) return 0.0;
    // Any cone holding every normal in front of its axis gives the same hull; else the minimal one decides.
    const ConeOfNormals cone = holding && projectsAbout(*holding) ? *holding : minimalCone(normals, count);
    if (!projectsAbout(cone)) return 0.0;
    const Projection projection = project(cone.axis, normals, count);
    if (projection.points.empty()) return 0.0;
    return shareOfHull(normals, projection, convexHull(projection.points));
}

OctagonAndShare octagonAndNormalsShare(const ConeOfNormals& cone, const glm::dvec3* normals, size_t count) {
    if (!projectsAbout(cone)) {
        // The minimal cone decides the share; it is found without the zero normals, as the octagon leaves them out.
        std::vector<glm::dvec3> nonzero;
        for (size_t i = 0; i < count; ++i)
            if (normals[i] != glm::dvec3(0.0)) nonzero.push_back(normals[i]);
        return {OctagonCone{}, normalsCullShare(nonzero.data(), nonzero.size(), nullptr)};
    }
    const Projection projection = project(cone.axis, normals, count);
    if (projection.points.empty()) return {};
    const std::vector<uint32_t> hull = convexHull(projection.points);
    return {octagonAround(cone, projection, hull), shareOfHull(normals, projection, hull)};
}

bool octagonSeesBack(const OctagonCone& octagon, const glm::dvec3& view, double slack) {
    const double length = glm::length(view);
    if (!octagon.cullable || !(length > 0.0)) return false;
    for (const glm::dvec3& edge : octagon.edges)
        if (!(glm::dot(edge, view) > kCullMargin * length + slack)) return false;
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
    return octagon.cullable ? polarShare(octagon.edges.data(), octagon.edges.size()) : 0.0;
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
