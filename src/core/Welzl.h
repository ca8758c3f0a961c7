// Welzl's smallest enclosing ball, written once for every kind of ball the core needs: spheres in
// space (Spheres.cpp) and caps on the unit sphere (SphericalCaps.cpp). Only "the ball through these
// boundary points" and "does the ball hold this point" differ between them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

#include <glm/glm.hpp>

namespace conescope {

// A fixed pseudo-random order for Welzl-style algorithms: expected linear time on sorted input,
// and the same result on every run.
inline void shuffleReproducibly(glm::dvec3* points, size_t count, uint64_t seed) {
    uint64_t state = seed;
    for (size_t i = count; i > 1; --i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;  // 64-bit LCG
        std::swap(points[i - 1], points[(state >> 33) % i]);
    }
}

// What a kind of ball tells the recursion (see the balls in Spheres.cpp and SphericalCaps.cpp):
//   using Ball = ...;                       the ball type; Ball{} is the empty ball
//   static constexpr size_t kMaxBoundary;   points that determine a ball (4 in space, 3 on the sphere)
//   static constexpr bool kMoveToFront;     Gartner's move-to-front: later passes meet support points first
//   Ball through(const glm::dvec3* boundary, size_t count);   smallest ball with these on its boundary
//   bool holds(const Ball&, const glm::dvec3&);              false for the empty ball
//   bool spend(size_t boundaryCount, size_t end);            false: give up this branch (a work budget)
//   Ball giveUp(const glm::dvec3* boundary);                 what a branch returns when it gives up
//
// The smallest ball holding points[0, end) with boundary[0, boundaryCount) on its boundary.
// points may be reordered (move-to-front); boundary needs room for kMaxBoundary points.
template <class Kind>
typename Kind::Ball welzl(Kind& kind, glm::dvec3* points, size_t end, glm::dvec3* boundary, size_t boundaryCount) {
    if (!kind.spend(boundaryCount, end)) return kind.giveUp(boundary);
    typename Kind::Ball ball = kind.through(boundary, boundaryCount);
    if (boundaryCount == Kind::kMaxBoundary) return ball;
    for (size_t i = 0; i < end; ++i) {
        if (kind.holds(ball, points[i])) continue;
        boundary[boundaryCount] = points[i];
        ball = welzl(kind, points, i, boundary, boundaryCount + 1);
        if constexpr (Kind::kMoveToFront) std::rotate(points, points + i, points + i + 1);
    }
    return ball;
}

}  // namespace conescope
