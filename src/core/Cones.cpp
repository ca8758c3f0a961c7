#include "Cones.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "Spheres.h"

namespace conescope {

namespace {
// Rounding slack for cos(alpha): the double dot products below are exact to ~1e-16.
constexpr double kConeSlack = 1e-12;

bool isZero(const glm::dvec3& v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; }

ConeOfNormals neverCullable() { return ConeOfNormals{}; }

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
    cone.cosHalfAngle = std::min(1.0, minimum) - kConeSlack;
    cone.cullable = cone.cosHalfAngle > 0.0;
    cone.sinHalfAngle = cone.cullable ? std::sqrt(1.0 - cone.cosHalfAngle * cone.cosHalfAngle) + kConeSlack : 1.0;
    if (!cone.cullable) cone.cosHalfAngle = std::max(cone.cosHalfAngle, -1.0);
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
    cone.cosHalfAngle = std::min(cone.cosHalfAngle, cosSeed - kConeSlack);
    cone.cullable = cone.cosHalfAngle > 0.0;
    cone.sinHalfAngle = cone.cullable ? std::sqrt(1.0 - cone.cosHalfAngle * cone.cosHalfAngle) + kConeSlack : 1.0;
    return cone;
}

namespace {

// A spherical cap {x : x.axis >= cosRadius}.
struct Cap {
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double cosRadius = 2.0;  // > 1: empty
    bool contains(const glm::dvec3& p) const { return glm::dot(p, axis) >= cosRadius - 1e-14; }
};

Cap capThrough(const glm::dvec3* boundary, size_t count) {
    if (count == 0) return Cap{};
    if (count == 1) return {boundary[0], 1.0};
    if (count == 2) {
        const glm::dvec3 mid = boundary[0] + boundary[1];
        const double length = glm::length(mid);
        if (!(length > 0.0)) return {boundary[0], -1.0};  // antipodal: only the whole sphere
        const glm::dvec3 axis = mid / length;
        return {axis, glm::dot(boundary[0], axis)};
    }
    // The circle through three points lies in the plane through them; its cap centre is that
    // plane's normal on the side of the points (the smaller cap).
    glm::dvec3 normal = glm::cross(boundary[1] - boundary[0], boundary[2] - boundary[0]);
    const double length = glm::length(normal);
    if (!(length > 0.0)) {
        // Coincident or on one great circle: the widest pair decides.
        Cap best = capThrough(boundary, 2);
        for (size_t i = 0; i < 3; ++i)
            for (size_t j = i + 1; j < 3; ++j) {
                const glm::dvec3 pair[2] = {boundary[i], boundary[j]};
                const Cap candidate = capThrough(pair, 2);
                if (candidate.cosRadius < best.cosRadius) best = candidate;
            }
        return best;
    }
    normal /= length;
    double cosRadius = glm::dot(boundary[0], normal);
    if (cosRadius < 0.0) normal = -normal, cosRadius = -cosRadius;
    return {normal, cosRadius};
}

// Welzl over caps: valid while the normals fit in an open hemisphere, which is the only case where a
// cone can cull at all. coneAroundAxis afterwards makes the result valid in every case.
Cap welzlCap(std::vector<glm::dvec3>& points, size_t end, glm::dvec3* boundary, size_t boundaryCount) {
    Cap cap = capThrough(boundary, boundaryCount);
    if (boundaryCount == 3) return cap;
    for (size_t i = 0; i < end; ++i) {
        if (cap.cosRadius <= 1.0 && cap.contains(points[i])) continue;
        boundary[boundaryCount] = points[i];
        cap = welzlCap(points, i, boundary, boundaryCount + 1);
        std::rotate(points.begin(), points.begin() + long(i), points.begin() + long(i) + 1);
    }
    return cap;
}

}  // namespace

ConeOfNormals minimalCone(const glm::dvec3* normals, size_t count) {
    std::vector<glm::dvec3> points = nonDegenerate(normals, count);
    if (points.empty()) return neverCullable();
    shuffleReproducibly(points, 0x2545F4914F6CDD1Dull);
    glm::dvec3 boundary[3];
    const Cap cap = welzlCap(points, points.size(), boundary, 0);
    ConeOfNormals cone = coneAroundAxis(cap.axis, normals, count);
    // Never report a wider cone than the plain average when rounding made Welzl's axis worse.
    const ConeOfNormals average = averageCone(normals, count);
    if (average.cosHalfAngle > cone.cosHalfAngle) return average;
    return cone;
}

}  // namespace conescope
