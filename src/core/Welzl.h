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
//   Ball giveUp(const glm::dvec3* boundary);                 what a branch gives up with: a ball that
//                                                            holds every point, so nothing recurses
//
// The smallest ball holding points[0, end) with boundary[0, BoundaryCount) on its boundary; call
// it with BoundaryCount 0 (or 1 to force a point onto the boundary). points may be reordered
// (move-to-front); boundary needs room for kMaxBoundary points. The boundary count is a template
// argument so that each level is its own function, with `through` for a known count inlined.
template <size_t BoundaryCount, class Kind>
typename Kind::Ball welzl(Kind& kind, glm::dvec3* points, size_t end, glm::dvec3* boundary) {
    // One named result (no early return), so that it is built in place and never copied out.
    typename Kind::Ball ball = kind.spend(BoundaryCount, end) ? kind.through(boundary, BoundaryCount) : kind.giveUp(boundary);
    if constexpr (BoundaryCount < Kind::kMaxBoundary) {
        for (size_t i = 0; i < end; ++i) {
            if (kind.holds(ball, points[i])) continue;
            boundary[BoundaryCount] = points[i];
            ball = welzl<BoundaryCount + 1>(kind, points, i, boundary);
            if constexpr (Kind::kMoveToFront) {  // points[i] to the front, the others one on: a rotation, as one move
                const glm::dvec3 moved = points[i];
                std::move_backward(points, points + i, points + i + 1);
                points[0] = moved;
            }
        }
    }
    return ball;
}

}  // namespace conescope
