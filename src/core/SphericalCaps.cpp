#include "SphericalCaps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "Welzl.h"

namespace conescope {

// ---------------------------------------------------------------------------------------------
// minimalCone's construction.

namespace {

Cap capAround(const glm::dvec3& axis, double cosRadius) {
    Cap cap;
    cap.axis = axis;
    cap.cosRadius = cosRadius;
    return cap;
}

// The smallest cap with 0..3 given points on its boundary.
Cap coneCapThrough(const glm::dvec3* boundary, size_t count) {
    if (count == 0) return Cap{};
    if (count == 1) return capAround(boundary[0], 1.0);
    if (count == 2) {
        const glm::dvec3 mid = boundary[0] + boundary[1];
        const double length = glm::length(mid);
        if (!(length > 0.0)) return capAround(boundary[0], -1.0);  // antipodal: only the whole sphere
        const glm::dvec3 axis = mid / length;
        return capAround(axis, glm::dot(boundary[0], axis));
    }
    // The circle through three points lies in the plane through them; its cap centre is that
    // plane's normal on the side of the points (the smaller cap).
    glm::dvec3 normal = glm::cross(boundary[1] - boundary[0], boundary[2] - boundary[0]);
    const double length = glm::length(normal);
    if (!(length > 0.0)) {
        // Coincident or on one great circle: the widest pair decides.
        Cap best = coneCapThrough(boundary, 2);
        for (size_t i = 0; i < 3; ++i)
            for (size_t j = i + 1; j < 3; ++j) {
                const glm::dvec3 pair[2] = {boundary[i], boundary[j]};
                const Cap candidate = coneCapThrough(pair, 2);
                if (candidate.cosRadius < best.cosRadius) best = candidate;
            }
        return best;
    }
    normal /= length;
    double cosRadius = glm::dot(boundary[0], normal);
    if (cosRadius < 0.0) normal = -normal, cosRadius = -cosRadius;
    return capAround(normal, cosRadius);
}

// Caps for Welzl's recursion, move-to-front and unbounded: valid while the normals fit in an open
// hemisphere, which is the only case where a cone can cull at all. coneAroundAxis afterwards makes
// the cone valid in every case.
struct ConeCaps {
    using Ball = Cap;
    static constexpr size_t kMaxBoundary = 3;
    static constexpr bool kMoveToFront = true;
    Cap through(const glm::dvec3* boundary, size_t count) const { return coneCapThrough(boundary, count); }
    bool holds(const Cap& cap, const glm::dvec3& p) const {
        return cap.cosRadius <= 1.0 && glm::dot(p, cap.axis) >= cap.cosRadius - 1e-14;
    }
    bool spend(size_t, size_t) const { return true; }
    Cap giveUp(const glm::dvec3*) const { return Cap{}; }  // never called: spend always agrees
};

}  // namespace

Cap minimalConeCap(glm::dvec3* points, size_t count) {
    shuffleReproducibly(points, count, 0x2545F4914F6CDD1Dull);
    glm::dvec3 boundary[3];
    ConeCaps caps;
    return welzl<0>(caps, points, count, boundary);
}

// ---------------------------------------------------------------------------------------------
// The optimized builder's construction.

Cap noCone(const glm::dvec3& axis) { return capAround(axis, -1.0); }

Cap capThrough(const glm::dvec3& a) {
    Cap cap;
    cap.axis = a;
    cap.cosRadius = 1.0;
    cap.support[0] = a;
    cap.supportCount = 1;
    return cap;
}

namespace {

Cap capThrough(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 middle = a + b;
    const double length = glm::length(middle);
    if (!(length > 1e-300)) return noCone(a);  // antipodal
    Cap cap;
    cap.axis = middle / length;
    cap.cosRadius = std::min(glm::dot(a, cap.axis), glm::dot(b, cap.axis));
    cap.support[0] = a, cap.support[1] = b;
    cap.supportCount = 2;
    return cap;
}

// Smallest cap holding three points: a pair's cap when it holds the third point, else the circle
// through all three. Checking the pairs first also covers points near one great circle, where the
// circle's plane is ill-conditioned.
Cap capThrough(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    Cap best;
    bool found = false;
    const Cap pairs[3] = {capThrough(a, b), capThrough(a, c), capThrough(b, c)};
    const glm::dvec3* thirds[3] = {&c, &b, &a};
    for (int i = 0; i < 3; ++i)
        if (contains(pairs[i], *thirds[i]) && (!found || pairs[i].cosRadius > best.cosRadius)) best = pairs[i], found = true;
    if (found) return best;
    glm::dvec3 normal = glm::cross(b - a, c - a);
    const double length = glm::length(normal);
    if (!(length > 1e-300)) return noCone(a);
    normal /= length;
    if (glm::dot(a, normal) < 0.0) normal = -normal;  // the smaller of the two caps
    Cap cap;
    cap.axis = normal;
    cap.cosRadius = std::min({glm::dot(a, normal), glm::dot(b, normal), glm::dot(c, normal)});
    cap.support[0] = a, cap.support[1] = b, cap.support[2] = c;
    cap.supportCount = 3;
    return cap;
}

// Caps for Welzl's recursion as the builder needs them: in the given (shuffled) order, a branch
// stops growing once it has no cone, and every branch with two boundary points spends the points
// it looks at from `budget`; running out means "no cone".
struct SearchCaps {
    using Ball = Cap;
    static constexpr size_t kMaxBoundary = 3;
    static constexpr bool kMoveToFront = false;
    size_t budget;
    Cap through(const glm::dvec3* boundary, size_t count) const {
        switch (count) {
            case 0: return Cap{};
            case 1: return conescope::capThrough(boundary[0]);  // declared outside this namespace
            case 2: return capThrough(boundary[0], boundary[1]);
            default: return capThrough(boundary[0], boundary[1], boundary[2]);
        }
    }
    // A cap without a cone stops growing; the empty cap (cosRadius 2) holds no unit normal.
    bool holds(const Cap& cap, const glm::dvec3& p) const { return !(cap.cosRadius > 0.0) || contains(cap, p); }
    bool spend(size_t boundaryCount, size_t end) {
        if (boundaryCount != 2) return true;
        if (budget < end) return false;
        budget -= end;
        return true;
    }
    Cap giveUp(const glm::dvec3* boundary) const { return noCone(boundary[0]); }
};

// Points all on the positive side of their mean lie in a hemisphere, where Welzl is exact and
// fast; otherwise a small budget decides (such sets almost never have a cone).
size_t welzlBudget(const glm::dvec3* points, size_t count) {
    glm::dvec3 mean(0.0);
    for (size_t i = 0; i < count; ++i) mean += points[i];
    for (size_t i = 0; i < count; ++i)
        if (!(glm::dot(points[i], mean) > 0.0)) return 4 * count + 64;
    return std::numeric_limits<size_t>::max();
}

Cap checkedCap(const Cap& cap, const glm::dvec3* points, size_t count) {
    if (!(cap.cosRadius > 0.0)) return noCone(cap.axis);
    for (size_t i = 0; i < count; ++i)
        if (!contains(cap, points[i])) return noCone(cap.axis);
    return cap;
}

// The fixed order of the builder's caps (a different seed from minimalConeCap's).
constexpr uint64_t kSearchShuffleSeed = 0x9E3779B97F4A7C15ull;

}  // namespace

Cap minimalCap(glm::dvec3* points, size_t count) {
    if (count == 0) return Cap{};
    shuffleReproducibly(points, count, kSearchShuffleSeed);
    SearchCaps caps{welzlBudget(points, count)};
    glm::dvec3 boundary[3];
    return checkedCap(welzl<0>(caps, points, count, boundary), points, count);
}

Cap minimalCapWith(glm::dvec3* points, size_t count, const glm::dvec3& added) {
    shuffleReproducibly(points, count, kSearchShuffleSeed);
    SearchCaps caps{welzlBudget(points, count)};
    glm::dvec3 boundary[3] = {added};
    const Cap cap = welzl<1>(caps, points, count, boundary);
    if (!(cap.cosRadius > 0.0) || !contains(cap, added)) return noCone(cap.axis);
    return checkedCap(cap, points, count);
}

Cap minimalCapFromSubset(const glm::dvec3* points, size_t count, Cap cap) {
    // Each round the point farthest outside joins the support of the cap so far; the cap of that
    // handful grows strictly, so a round never repeats, and the first cap holding every point is
    // the minimal one (a subset's minimal cap that holds the whole set is the set's).
    constexpr int kRounds = 24;
    for (int round = 0; round < kRounds; ++round) {
        if (!(cap.cosRadius > 0.0) || cap.cosRadius > 1.0) break;
        double lowest = cap.cosRadius - 1e-10;
        size_t outside = count;
        for (size_t i = 0; i < count; ++i) {
            const double along = glm::dot(points[i], cap.axis);
            if (along < lowest) lowest = along, outside = i;
        }
        if (outside == count) return cap;
        glm::dvec3 handful[4];
        size_t n = 0;
        for (uint32_t i = 0; i < cap.supportCount; ++i) handful[n++] = cap.support[i];
        handful[n++] = points[outside];
        cap = minimalCap(handful, n);
    }
    if (cap.cosRadius <= 1.0 && !(cap.cosRadius > 0.0)) return noCone(cap.axis);  // a subset already has no cone
    std::vector<glm::dvec3> copy(points, points + count);
    return minimalCap(copy.data(), count);
}

Cap supportCapAdding(const Cap& cap, const glm::dvec3& added) {
    glm::dvec3 points[4];
    size_t count = 0;
    for (uint32_t i = 0; i < cap.supportCount; ++i) points[count++] = cap.support[i];
    points[count++] = added;
    return minimalCap(points, count);
}

Cap supportCapRemoving(const Cap& cap, const glm::dvec3& removed) {
    glm::dvec3 points[3];
    size_t count = 0;
    for (uint32_t i = 0; i < cap.supportCount; ++i)
        if (cap.support[i] != removed) points[count++] = cap.support[i];
    return count > 0 ? minimalCap(points, count) : capThrough(removed);
}

double sinAfterAdding(const Cap& cap, double cosTheta) {
    if (cap.cosRadius > 1.0) return 0.0;
    if (cosTheta >= cap.cosRadius) return sinOf(cap);
    if (!(cap.cosRadius > 0.0)) return 1.0;
    const double sinRadius = std::sqrt(std::max(0.0, 1.0 - cap.cosRadius * cap.cosRadius));
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double cosSum = cap.cosRadius * cosTheta - sinRadius * sinTheta;  // cos(alpha + theta)
    const double sinSum = sinRadius * cosTheta + cap.cosRadius * sinTheta;  // sin(alpha + theta)
    if (cosSum <= -1.0 + 1e-15 || sinSum < 0.0) return 1.0;
    return std::sqrt(std::max(0.0, 0.5 * (1.0 - cosSum)));
}

Cap growCap(const Cap& cap, const glm::dvec3& normal) {
    if (cap.cosRadius > 1.0) return capThrough(normal);
    if (!(cap.cosRadius > 0.0) || contains(cap, normal)) return cap;
    const double radius = std::acos(std::clamp(cap.cosRadius, -1.0, 1.0));
    const double theta = std::acos(std::clamp(glm::dot(normal, cap.axis), -1.0, 1.0));
    const double grown = 0.5 * (radius + theta);
    const double sinTheta = std::sin(theta);
    if (grown >= M_PI / 2 || !(sinTheta > 1e-12)) return noCone(cap.axis);
    const double turn = grown - radius;
    Cap result;
    result.axis = glm::normalize((std::sin(theta - turn) * cap.axis + std::sin(turn) * normal) / sinTheta);
    result.cosRadius = std::cos(grown) - 1e-12;
    result.support[0] = normal;  // only the new point is known to be on the boundary
    result.supportCount = 1;
    return result;
}

}  // namespace conescope
