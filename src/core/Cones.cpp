#include "Cones.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "SphericalCaps.h"
#include "Spheres.h"

namespace conescope {

namespace {
// Rounding slack for cos(alpha): the double dot products below are exact to ~1e-16.
constexpr double kConeSlack = 1e-12;

bool isZero(const glm::dvec3& v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; }

ConeOfNormals neverCullable() { return ConeOfNormals{}; }

// Every cone's half-angle is set here, from its (already rounded down) cosine: the sine every view
// test compares with is rounded up, and a cone wider than a hemisphere is marked never cullable.
void setHalfAngle(ConeOfNormals& cone, double cosHalfAngle) {
    cone.cosHalfAngle = cosHalfAngle;
    cone.cullable = cone.cosHalfAngle > 0.0;
    cone.sinHalfAngle = cone.cullable ? std::sqrt(1.0 - cone.cosHalfAngle * cone.cosHalfAngle) + kConeSlack : 1.0;
    if (!cone.cullable) cone.cosHalfAngle = std::max(cone.cosHalfAngle, -1.0);
}

std::vector<glm::dvec3> nonDegenerate(const glm::dvec3* normals, size_t count) {
    std::vector<glm::dvec3> kept;
    kept.reserve(count);
    for (size_t i = 0; i < count; ++i)
        if (!isZero(normals[i])) kept.push_back(normals[i]);
    return kept;
}
}  // namespace

double ConeOfNormals::halfAngle() const { return std::acos(std::clamp(cosHalfAngle, -1.0, 1.0)); }

ConeOfNormals coneAroundAxis(const glm::dvec3& axis, const glm::dvec3* normals, size_t count) {
    const double axisLength = glm::length(axis);
    if (!(axisLength > 0.0) || !std::isfinite(axisLength)) return neverCullable();
    ConeOfNormals cone;
    cone.axis = axis / axisLength;
    double minimum = 2.0;
    size_t used = 0;
    for (size_t i = 0; i < count; ++i) {
        if (isZero(normals[i])) continue;  // degenerate faces have no side to cull
        minimum = std::min(minimum, glm::dot(normals[i], cone.axis));
        ++used;
    }
    if (used == 0) return neverCullable();
    setHalfAngle(cone, std::min(1.0, minimum) - kConeSlack);
    return cone;
}

ConeOfNormals averageCone(const glm::dvec3* normals, size_t count) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < count; ++i) sum += normals[i];
    return coneAroundAxis(sum, normals, count);
}

ConeOfNormals seedSphereCone(const glm::dvec3* normals, size_t count) {
    const std::vector<glm::dvec3> tips = nonDegenerate(normals, count);
    if (tips.empty()) return neverCullable();
    const Sphere sphere = minimalSphere(tips.data(), tips.size());
    const double centerDistance = glm::length(sphere.center);
    if (!(centerDistance > sphere.radius)) return neverCullable();  // the origin is inside: no cone
    ConeOfNormals cone = coneAroundAxis(sphere.center, normals, count);
    if (!cone.cullable) return cone;
    // Seed 000: half-angle = asin(r / |c|), the cone tangent to the sphere, which holds every tip.
    const double sinSeed = sphere.radius / centerDistance;
    const double cosSeed = std::sqrt(1.0 - sinSeed * sinSeed);
    setHalfAngle(cone, std::min(cone.cosHalfAngle, cosSeed - kConeSlack));
    return cone;
}

namespace {

// Whether every point is on the positive side of their mean: then they lie in an open hemisphere,
// where Welzl's caps mean what they say.
bool aroundTheirMean(const std::vector<glm::dvec3>& points) {
    glm::dvec3 mean(0.0);
    for (const glm::dvec3& p : points) mean += p;
    for (const glm::dvec3& p : points)
        if (!(glm::dot(p, mean) > 0.0)) return false;
    return true;
}

}  // namespace

ConeOfNormals minimalCone(const glm::dvec3* normals, size_t count) {
    std::vector<glm::dvec3> points = nonDegenerate(normals, count);
    if (points.empty()) return neverCullable();
    // On normals not around their mean (mostly wider than a hemisphere: no cone) unbounded Welzl
    // can take cubic time: the cap grown point by point from a subset decides instead, exactly
    // where they do fit in a hemisphere, and stops once its caps are wider than one.
    const Cap cap = aroundTheirMean(points) ? minimalConeCap(points.data(), points.size())
                                            : minimalCapFromSubset(points.data(), points.size(), capThrough(points[0]));
    ConeOfNormals cone = coneAroundAxis(cap.axis, normals, count);
    // Never report a wider cone than the plain average when rounding made Welzl's axis worse.
    const ConeOfNormals average = averageCone(normals, count);
    if (average.cosHalfAngle > cone.cosHalfAngle) return average;
    return cone;
}

}  // namespace conescope
