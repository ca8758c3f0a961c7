#include "Views.h"

#include <cmath>

namespace conescope {

Eye Eye::orthographicAlong(const glm::dvec3& direction) {
    Eye eye;
    eye.direction = glm::normalize(direction);
    eye.orthographic = true;
    return eye;
}

std::vector<glm::dvec3> spiralDirections(size_t count) {
    std::vector<glm::dvec3> directions;
    directions.reserve(count);
    const double goldenAngle = M_PI * (3.0 - std::sqrt(5.0));
    for (size_t i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (double(i) + 0.5) / double(count);
        const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
        const double phi = double(i) * goldenAngle;
        directions.emplace_back(std::cos(phi) * r, y, std::sin(phi) * r);
    }
    return directions;
}

std::vector<Eye> orbitViews(const Aabb& box, size_t count, double distance, bool orthographic) {
    std::vector<Eye> views;
    views.reserve(count);
    const glm::dvec3 center(box.center());
    const double radius = box.halfDiagonal();
    for (const glm::dvec3& direction : spiralDirections(count)) {
        const glm::dvec3 offset = distance * radius * direction;
        Eye eye = Eye::perspective(center + offset);
        if (orthographic) {
            eye.orthographic = true;
            eye.direction = glm::normalize(-offset);
        }
        views.push_back(eye);
    }
    return views;
}

}  // namespace conescope
