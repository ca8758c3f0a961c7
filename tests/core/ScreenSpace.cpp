#include "ScreenSpace.h"

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace conescope {

double signedArea2D(const glm::dvec2* points, size_t count) {
    double twiceArea = 0.0;
    for (size_t i = 0; i < count; ++i) {
        const glm::dvec2& a = points[i];
        const glm::dvec2& b = points[(i + 1) % count];
        twiceArea += a.x * b.y - b.x * a.y;
    }
    return twiceArea;
}

glm::dmat4 viewProjection(const glm::dvec3& eye, const glm::dvec3& target, double fovYDegrees, double aspect,
                          double nearPlane, double farPlane) {
    glm::dvec3 forward = glm::normalize(target - eye);
    // Any up vector not parallel to the view direction will do.
    glm::dvec3 up = std::abs(forward.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    return glm::perspective(glm::radians(fovYDegrees), aspect, nearPlane, farPlane) * glm::lookAt(eye, target, up);
}

ScreenFacing classifyByScreenArea(const glm::dmat4& transform, const glm::dvec3* worldVertices, size_t count) {
    std::vector<glm::dvec2> screen(count);
    for (size_t i = 0; i < count; ++i) {
        const glm::dvec4 clip = transform * glm::dvec4(worldVertices[i], 1.0);
        if (!(clip.w > 0.0)) return ScreenFacing::Clipped;
        screen[i] = glm::dvec2(clip) / clip.w;
    }
    const double area = signedArea2D(screen.data(), count);
    if (area > 0.0) return ScreenFacing::Front;
    if (area < 0.0) return ScreenFacing::Back;
    return ScreenFacing::EdgeOn;
}

}  // namespace conescope
