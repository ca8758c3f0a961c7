// Bounding spheres of point sets.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace conescope {

struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// Ritter's two-pass approximation: fast, at most a few percent larger than the minimum.
Sphere ritterSphere(const glm::dvec3* points, size_t count);

// The exact smallest enclosing sphere (Welzl, move-to-front). The radius is finally set to the
// largest distance from the centre, so every point is inside whatever the rounding.
Sphere minimalSphere(const glm::dvec3* points, size_t count);

// The sphere with this centre that holds every point (largest distance, plus a rounding margin).
Sphere sphereAround(const glm::dvec3& center, const glm::dvec3* points, size_t count);

}  // namespace conescope
