// Caps of unit vectors, {x : x.axis >= cosRadius}, and the smallest cap holding a set of them:
// Welzl's algorithm on the sphere (the recursion is in Welzl.h). Two constructions share it and
// differ only in rounding:
//  - minimalConeCap, where minimalCone (Cones.h) starts: move-to-front, the circle through three
//    points tried before the pairs, a containment slack of 1e-14;
//  - minimalCap / minimalCapWith, which the optimized builder evaluates millions of times: no
//    allocation, a work budget on points wider than a hemisphere (where Welzl's steps mean nothing
//    and can take cubic time), the pairs tried first (the circle's plane is ill-conditioned near a
//    great circle), a slack of 1e-10, and the normals that bound the cap kept, for cheap bounds on
//    a grown or shrunk cap.
// Replacing one by the other moves the cones' last bits and changes the optimized partitions.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace conescope {

struct Cap {
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double cosRadius = 2.0;  // > 1: no normals yet; <= 0: no cone (wider than a hemisphere)
    glm::dvec3 support[3];   // normals on the boundary that determine the cap (minimalCap only)
    uint32_t supportCount = 0;
};

// The smallest cap holding points (reordered in place) as minimalCone builds it; empty for none.
Cap minimalConeCap(glm::dvec3* points, size_t count);

// --- The optimized builder's caps --------------------------------------------------------------

// Whether the cap holds a normal, with the builder's slack of 1e-10.
inline bool contains(const Cap& cap, const glm::dvec3& normal) { return glm::dot(normal, cap.axis) >= cap.cosRadius - 1e-10; }
// A cap that stands for "no cone"; the axis is kept only so that it stays defined.
Cap noCone(const glm::dvec3& axis);
// The cap of a single normal (radius 0).
Cap capThrough(const glm::dvec3& normal);

// Minimal cap of points (reordered in place); an empty cap for no points.
Cap minimalCap(glm::dvec3* points, size_t count);
// Minimal cap of points plus `added`, which lies outside the minimal cap of points.
Cap minimalCapWith(glm::dvec3* points, size_t count, const glm::dvec3& added);

// Minimal cap of points, given the minimal cap (with its bounding points) of some of them: grown
// by the points outside it, a few at a time; usually far cheaper than minimalCap when the subset's
// cap is near the answer (one normal more or less).
Cap minimalCapFromSubset(const glm::dvec3* points, size_t count, Cap subsetCap);

// Minimal cap of a cap's bounding points plus or minus one normal: a subset of the real points,
// so its radius is a lower bound on the real cap's.
Cap supportCapAdding(const Cap& cap, const glm::dvec3& added);
// With no bounding point left the bound is a single direction (radius 0).
Cap supportCapRemoving(const Cap& cap, const glm::dvec3& removed);

// sin of the half-angle: 1 for no cone or for no normals.
inline double sinOf(const Cap& cap) {
    if (!(cap.cosRadius > 0.0) || cap.cosRadius > 1.0) return 1.0;
    return std::sqrt(std::max(0.0, 1.0 - cap.cosRadius * cap.cosRadius));
}

// sin of the half-angle of the smallest cap holding `cap` and a normal at cos(theta) from its
// axis: (alpha + theta) / 2 by half-angle formulas. An upper bound on the exact minimal cap.
// When alpha + theta passes 180 degrees the cap is wider than a hemisphere (no cone): sin 1, not
// the smaller |sin((alpha + theta) / 2)| the half-angle formula alone would give.
double sinAfterAdding(const Cap& cap, double cosTheta);

// The smallest cap holding `cap` and `normal` (turned towards the normal by half the excess).
// Contains every point the old cap did, so it is a valid if loose cap of the grown set.
Cap growCap(const Cap& cap, const glm::dvec3& normal);

}  // namespace conescope
