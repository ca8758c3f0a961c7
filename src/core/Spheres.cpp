#include "Spheres.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "Welzl.h"

namespace conescope {

// Every sphere function ends here: the radius becomes the largest distance from the centre, then is
// nudged up by a relative ulp-scale margin, so containment never depends on the search's rounding.
Sphere sphereAround(const glm::dvec3& center, const glm::dvec3* points, size_t count) {
    double radius = 0.0;
    for (size_t i = 0; i < count; ++i) radius = std::max(radius, glm::length(points[i] - center));
    const double scale = std::max({std::abs(center.x), std::abs(center.y), std::abs(center.z), radius});
    return {center, radius + scale * 1e-12};
}

Sphere ritterSphere(const glm::dvec3* points, size_t count) {
    if (count == 0) return {};
    // Start from a far pair: the point farthest from p0, then the point farthest from that.
    auto farthestFrom = [&](const glm::dvec3& from) {
        size_t best = 0;
        double bestDistance = -1.0;
        for (size_t i = 0; i < count; ++i) {
            const double d = glm::dot(points[i] - from, points[i] - from);
            if (d > bestDistance) bestDistance = d, best = i;
        }
        return best;
    };
    const glm::dvec3 a = points[farthestFrom(points[0])];
    const glm::dvec3 b = points[farthestFrom(a)];
    glm::dvec3 center = 0.5 * (a + b);
    double radius = 0.5 * glm::length(b - a);
    // Grow to take in each point left outside, moving the centre towards it.
    for (size_t i = 0; i < count; ++i) {
        const double d = glm::length(points[i] - center);
        if (d > radius) {
            const double grown = 0.5 * (radius + d);
            center += (d - grown) / d * (points[i] - center);
            radius = grown;
        }
    }
    return sphereAround(center, points, count);
}

namespace {

struct Ball {
    glm::dvec3 center{0.0};
    double radiusSquared = -1.0;
    bool contains(const glm::dvec3& p) const {
        const double d = glm::dot(p - center, p - center);
        return d <= radiusSquared * (1.0 + 1e-12) + 1e-300;
    }
};

// The smallest ball with 1..4 given points on its boundary (circumscribed in their affine hull).
Ball ballThrough(const glm::dvec3* boundary, size_t count) {
    Ball ball;
    if (count == 0) return ball;
    const glm::dvec3 a = boundary[0];
    if (count == 1) return {a, 0.0};
    if (count == 2) {
        ball.center = 0.5 * (a + boundary[1]);
        ball.radiusSquared = glm::dot(boundary[1] - ball.center, boundary[1] - ball.center);
        return ball;
    }
    const glm::dvec3 u = boundary[1] - a, v = boundary[2] - a;
    if (count == 3) {
        // Circumcentre in the plane of the triangle.
        const glm::dvec3 n = glm::cross(u, v);
        const double denominator = 2.0 * glm::dot(n, n);
        if (denominator == 0.0) {  // collinear: the two farthest points span the ball
            glm::dvec3 pair[2] = {a, boundary[1]};
            double best = glm::dot(u, u);
            if (glm::dot(v, v) > best) pair[1] = boundary[2], best = glm::dot(v, v);
            if (glm::dot(v - u, v - u) > best) pair[0] = boundary[1], pair[1] = boundary[2];
            return ballThrough(pair, 2);
        }
        const glm::dvec3 offset = (glm::dot(u, u) * glm::cross(v, n) + glm::dot(v, v) * glm::cross(n, u)) / denominator;
        return {a + offset, glm::dot(offset, offset)};
    }
    const glm::dvec3 w = boundary[3] - a;
    const double determinant = glm::dot(u, glm::cross(v, w));
    if (determinant == 0.0) {  // coplanar: use the best ball through three of them
        Ball best;
        for (size_t skip = 0; skip < 4; ++skip) {
            glm::dvec3 three[3];
            size_t k = 0;
            for (size_t i = 0; i < 4; ++i)
                if (i != skip) three[k++] = boundary[i];
            Ball candidate = ballThrough(three, 3);
            if (candidate.contains(boundary[skip]) && (best.radiusSquared < 0 || candidate.radiusSquared < best.radiusSquared))
                best = candidate;
        }
        return best;
    }
    const glm::dvec3 offset =
        (glm::dot(u, u) * glm::cross(v, w) + glm::dot(v, v) * glm::cross(w, u) + glm::dot(w, w) * glm::cross(u, v)) /
        (2.0 * determinant);
    return {a + offset, glm::dot(offset, offset)};
}

// Balls in space for Welzl's recursion (Welzl.h), in move-to-front form: expected linear time.
struct BallsInSpace {
    using Ball = conescope::Ball;
    static constexpr size_t kMaxBoundary = 4;
    static constexpr bool kMoveToFront = true;
    Ball through(const glm::dvec3* boundary, size_t count) const { return ballThrough(boundary, count); }
    bool holds(const Ball& ball, const glm::dvec3& p) const { return ball.radiusSquared >= 0.0 && ball.contains(p); }
    bool spend(size_t, size_t) const { return true; }
    Ball giveUp(const glm::dvec3*) const { return Ball{}; }  // never called: spend always agrees
};

}  // namespace

Sphere minimalSphere(const glm::dvec3* points, size_t count) {
    if (count == 0) return {};
    std::vector<glm::dvec3> shuffled(points, points + count);
    shuffleReproducibly(shuffled.data(), shuffled.size(), 0x9E3779B97F4A7C15ull);
    glm::dvec3 boundary[4];
    BallsInSpace balls;
    const Ball ball = welzl<0>(balls, shuffled.data(), shuffled.size(), boundary);
    return sphereAround(ball.center, points, count);
}

}  // namespace conescope
