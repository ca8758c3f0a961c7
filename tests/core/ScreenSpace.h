// Seed 001's second test, kept with the tests as a second oracle (the product uses the normal test):
// after the view-projection, a face is back-facing when its signed screen area is negative
// (counter-clockwise = front). It must agree with n.(e - q) < 0 for faces entirely in front of the eye.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "core/Views.h"

namespace conescope {

// Twice the signed area of a 2D polygon (shoelace); > 0 for counter-clockwise.
double signedArea2D(const glm::dvec2* points, size_t count);

// A right-handed look-at + perspective projection (OpenGL conventions) for an eye looking at target.
glm::dmat4 viewProjection(const glm::dvec3& eye, const glm::dvec3& target, double fovYDegrees, double aspect,
                          double nearPlane, double farPlane);

enum class ScreenFacing { Front, Back, EdgeOn, Clipped };

// Projects the polygon's world vertices; Clipped when any vertex has clip w <= 0 (behind the eye).
ScreenFacing classifyByScreenArea(const glm::dmat4& viewProjection, const glm::dvec3* worldVertices, size_t count);

}  // namespace conescope
