#include "CrossSection.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "CullTestGeometry.h"
#include "Lesson.h"
#include "RecordTests.h"

namespace conescope {

namespace {

constexpr double pi = 3.14159265358979323846;

glm::dvec2 direction(double angleFromAxis) { return {std::sin(angleFromAxis), std::cos(angleFromAxis)}; }

// The page's right-hand direction: v's part across V1, or any perpendicular when v is along V1.
glm::dvec3 rightOf(const glm::dvec3& up, const glm::dvec3& view) {
    const glm::dvec3 across = view - glm::dot(view, up) * up;
    if (glm::length(across) > 1e-9) return glm::normalize(across);
    const glm::dvec3 helper = std::abs(up.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(up, helper));
}

// A direction's angle to V1, turned about V1 into the page on the side it leans to. atan2 keeps
// the digits near V1 that acos loses.
double turnedAngle(const glm::dvec3& n, const glm::dvec3& up, const glm::dvec3& right) {
    const double angle = std::atan2(glm::length(glm::cross(n, up)), glm::dot(n, up));
    return glm::dot(n, right) < 0.0 ? -angle : angle;
}

// The view vectors within acos(threshold) of V1: what v.V1 > threshold keeps.
std::vector<AngleRange> roundRegion(double threshold) {
    if (!(threshold < 1.0)) return {};
    const double half = std::acos(std::max(threshold, -1.0));
    return {{-half, half}};
}

// The octagon test culls u = sin(psi) right + cos(psi) up when g.u > t for each edge g; in the page
// g.u = A cos(psi - theta) with A and theta the length and angle of g's part in the page.
void octagonRegion(const CullExplanation& why, CrossSection& section) {
    double low = -pi, high = pi;
    for (size_t k = 0; k < why.octagonEdges.size(); ++k) {
        const glm::dvec3& g = why.octagonEdges[k];
        const double inPage = std::hypot(glm::dot(g, section.right), glm::dot(g, section.up));
        if (!(inPage > why.threshold)) return;  // an edge across the page: no v in it sees it from behind
        const double theta = std::atan2(glm::dot(g, section.right), glm::dot(g, section.up));
        const double half = std::acos(why.threshold / inPage);
        if (theta - half > low) {
            low = theta - half;
            section.boundingEdges[0] = k;
            section.boundingEdgeAngles[0] = theta;
        }
        if (theta + half < high) {
            high = theta + half;
            section.boundingEdges[1] = k;
            section.boundingEdgeAngles[1] = theta;
        }
    }
    if (low < high) section.cullRegion = {{low, high}};
}

// Where culls(psi) holds, psi in [-pi, pi]: sampled every half degree and at v, each change of
// answer narrowed down by bisection to the last bit.
std::vector<AngleRange> askedRegion(const std::function<bool(double)>& culls, double viewAngle) {
    constexpr int samples = 720;
    std::vector<double> angles;
    for (int i = 0; i <= samples; ++i) angles.push_back(-pi + 2.0 * pi * i / samples);
    angles.push_back(viewAngle);
    std::sort(angles.begin(), angles.end());
    std::vector<AngleRange> ranges;
    bool inside = culls(angles[0]);
    double start = angles[0];
    for (size_t i = 1; i < angles.size(); ++i) {
        const bool next = culls(angles[i]);
        if (next == inside) continue;
        double low = angles[i - 1], high = angles[i];  // culls(low) == inside, culls(high) == next
        for (int step = 0; step < 60 && low < high; ++step) {
            const double middle = 0.5 * (low + high);
            if (middle <= low || middle >= high) break;
            (culls(middle) == inside ? low : high) = middle;
        }
        if (inside) ranges.push_back({start, low});
        start = high;
        inside = next;
    }
    if (inside) ranges.push_back({start, pi});
    ranges.erase(std::remove_if(ranges.begin(), ranges.end(), [](const AngleRange& r) { return !(r[0] < r[1]); }), ranges.end());
    return ranges;
}

glm::dvec3 pageDirection(const CrossSection& section, double angle) {
    return std::sin(angle) * section.right + std::cos(angle) * section.up;
}

// The eye and the point v runs to in the page, with the eyes the test culls from.
void placeOf(const Lesson& lesson, const CullingInput& input, CrossSection& section) {
    const CullExplanation& why = lesson.why;
    const bool toApex = section.test == CullTest::Apex || section.test == CullTest::Octagon;
    const bool toCentre = section.test == CullTest::Sphere || section.test == CullTest::MeshoptSphere;
    // A cluster without a cone has no apex behind its faces and no test to place.
    if (lesson.eye.orthographic || (!toApex && !toCentre) || !why.cullable) return;
    CrossSectionPlace& place = section.place;
    const glm::dvec3 origin = toApex ? why.apex : lesson.sphere.center;
    auto inPage = [&](const glm::dvec3& point) {
        return glm::dvec2(glm::dot(point - origin, section.right), glm::dot(point - origin, section.up));
    };
    place.shown = true;
    place.toApex = toApex;
    place.eye = inPage(lesson.eye.position);
    place.centre = inPage(lesson.sphere.center);
    place.radius = lesson.sphere.radius;
    place.distance = why.distance;
    place.spread = why.distance > place.radius ? std::asin(place.radius / why.distance) : pi / 2.0;
    const double across = glm::dot(lesson.sphere.center - origin, glm::cross(section.right, section.up));
    place.sectionRadius = std::sqrt(std::max(0.0, place.radius * place.radius - across * across));
    const double reach = 1.25 * std::max({glm::length(place.eye), glm::length(place.centre) + place.radius, 2.0 * place.radius});
    if (toApex) {
        // The eyes behind the apex: e = apex - s u(psi) for every psi of the region.
        for (const AngleRange& range : section.cullRegion) {
            constexpr int steps = 48;
            for (int i = 0; i < steps; ++i) {
                const double a = range[0] + (range[1] - range[0]) * i / steps, b = range[0] + (range[1] - range[0]) * (i + 1) / steps;
                place.cullingEyes.push_back({glm::dvec2(0.0), -reach * direction(a), -reach * direction(b)});
            }
        }
        return;
    }
    if (!section.hasRegion()) return;
    const CullRegion region = cullRegion(input.bounds, lesson.cluster, section.test, false, reach);
    // Around -V1 from the centre: at distance d the eyes within angle(d) of it, in small polar cells.
    auto at = [](double d, double angle) { return glm::dvec2(d * std::sin(angle), -d * std::cos(angle)); };
    constexpr int cells = 24;
    for (size_t i = 0; i + 1 < region.distances.size(); ++i) {
        const double d0 = region.distances[i], d1 = region.distances[i + 1];
        const double a0 = region.angles[i], a1 = region.angles[i + 1];
        for (int j = 0; j < cells; ++j) {
            const double s0 = -1.0 + 2.0 * j / cells, s1 = -1.0 + 2.0 * (j + 1) / cells;
            place.cullingEyes.push_back({at(d0, s0 * a0), at(d1, s0 * a1), at(d1, s1 * a1)});
            place.cullingEyes.push_back({at(d0, s0 * a0), at(d1, s1 * a1), at(d0, s1 * a0)});
        }
    }
}

// The round tests' region and what the bound takes off B.
void roundRegionOf(const Lesson& lesson, CrossSection& section) {
    const CullExplanation& why = lesson.why;
    section.rule = CullRegionRule::Round;
    double threshold = why.threshold;
    if (!lesson.eye.orthographic && section.test == CullTest::Sphere) section.narrowing = glm::radians(why.sphereAngleDegrees);
    if (!lesson.eye.orthographic && section.test == CullTest::MeshoptSphere) {
        threshold += why.distance > 0.0 ? why.radius / why.distance : 1.0;
        section.narrowing = threshold < 1.0 ? section.angleB - std::acos(std::max(threshold, -1.0)) : section.angleB;
    }
    section.regionHalfAngle = threshold < 1.0 ? std::acos(std::max(threshold, -1.0)) : 0.0;
    if (section.test == CullTest::Sphere && !lesson.eye.orthographic) section.regionHalfAngle = std::max(0.0, section.angleB - section.narrowing);
    // Where the test compares nothing (inside the sphere, a sphere wider than B) no v culls.
    if (!std::isnan(why.margin)) section.cullRegion = roundRegion(threshold);
}

// The box and vertex tests: each point's view vector, the tightest one standing for v.
void pointsOf(const Lesson& lesson, CrossSection& section) {
    const CullExplanation& why = lesson.why;
    std::vector<glm::dvec3> points(why.corners.begin(), why.corners.end());
    if (section.test == CullTest::Vertices) points = why.vertices;
    double lowest = 2.0;
    for (size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3 view = points[i] - lesson.eye.position;
        const double length = glm::length(view);
        const double along = length > 0.0 ? glm::dot(view, why.axis) / length : 0.0;
        section.pointAngles.push_back(length > 0.0 ? turnedAngle(view, section.up, section.right) : 0.0);
        if (along < lowest) {
            lowest = along;
            section.tightestPoint = i;
        }
    }
    if (!section.pointAngles.empty()) section.viewAngle = section.pointAngles[section.tightestPoint];
}

}  // namespace

bool CrossSection::inRegion(double angle) const {
    for (const AngleRange& range : cullRegion)
        if (range[0] < angle && angle < range[1]) return true;
    return false;
}

CrossSection crossSectionOf(const Lesson& lesson, const CullingInput& input) {
    const CullExplanation& why = lesson.why;
    CrossSection section;
    section.cluster = lesson.cluster;
    section.test = lesson.test;
    section.orthographic = lesson.eye.orthographic;
    section.viewName = lesson.eye.orthographic ? "d" : "v";
    section.up = glm::length(why.axis) > 0.0 ? glm::normalize(why.axis) : glm::dvec3(0.0, 0.0, 1.0);
    section.right = rightOf(section.up, why.view);
    for (const glm::dvec3& n : lesson.normals) section.normalAngles.push_back(turnedAngle(n, section.up, section.right));
    section.cone = why.cullable;
    section.alpha = glm::radians(why.halfAngleDegrees);
    section.angleB = glm::radians(why.angleBDegrees);
    section.viewAngle = glm::length(why.view) > 0.0 ? turnedAngle(why.view, section.up, section.right) : 0.0;
    section.culls = why.culled;
    const CullTest test = lesson.test;
    // From a far eye every point's view vector is d: the box and vertex tests are d's alone.
    if ((test == CullTest::Aabb || test == CullTest::AabbFast || test == CullTest::Vertices) && !lesson.eye.orthographic) pointsOf(lesson, section);
    if (test == CullTest::Oracle || readsOwnRecord(test)) {
        // The rule is the record's (or every face's): ask it from eyes on the circle through this one.
        section.rule = CullRegionRule::Asked;
        const glm::dvec3 centre = lesson.sphere.center;
        auto culls = [&](double angle) {
            const glm::dvec3 u = pageDirection(section, angle);
            const Eye eye = lesson.eye.orthographic ? Eye::orthographicAlong(u) : Eye::perspective(centre - why.distance * u);
            return cullCluster(input, lesson.cluster, eye, test);
        };
        section.cullRegion = askedRegion(culls, section.viewAngle);
    } else if (!why.cullable) {
        section.rule = CullRegionRule::None;
    } else if (test == CullTest::Octagon) {
        section.rule = CullRegionRule::Octagon;
        if (input.bounds.octagons[lesson.cluster].cullable) octagonRegion(why, section);
    } else {
        roundRegionOf(lesson, section);
    }
    placeOf(lesson, input, section);
    section.title = "Cluster " + std::to_string(lesson.cluster) + ", " + testInWords(test) + ": the page of " +
                    (section.cone ? "V1" : "the axis") + " and " + section.viewName;
    section.caption = crossSectionCaption(lesson, section);
    return section;
}

}  // namespace conescope
