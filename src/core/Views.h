// Where the cull decisions are made from. Views are plain data so the CLI, the GUI's orbit
// animation and the tests walk the same list.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "Mesh.h"

namespace conescope {

struct Eye {
    // Perspective: the eye point. Orthographic: the point the direction was taken from (the orbit
    // point or the given eye), reported with the view; culling does not use it.
    glm::dvec3 position{0.0};
    // Orthographic: the unit direction the eye looks along (from the eye into the scene).
    glm::dvec3 direction{0.0, 0.0, -1.0};
    bool orthographic = false;

    static Eye perspective(const glm::dvec3& position) { return Eye{position, {0.0, 0.0, -1.0}, false}; }
    static Eye orthographicAlong(const glm::dvec3& direction);
};

// N unit directions spread evenly over the sphere (the golden-angle spiral): for i = 0..N-1,
// y = 1 - 2(i + 0.5)/N, r = sqrt(1 - y^2), phi = i*pi*(3 - sqrt 5), d = (cos(phi) r, y, sin(phi) r).
std::vector<glm::dvec3> spiralDirections(size_t count);

// The standard orbit: the settings' default views and distance (Settings.h); the chosen cone counts
// eyes on its sphere (ChosenCones.h).
constexpr size_t kStandardOrbitViews = 128;
constexpr double kStandardOrbitDistance = 3.0;

// The standard orbit: for i = 0..N-1, y = 1 - 2(i + 0.5)/N, r = sqrt(1 - y^2), phi = i*pi*(3 - sqrt 5),
// eye = c + D*R*(cos(phi) r, y, sin(phi) r), c the AABB centre and R half its diagonal.
// Orthographic views look from the same points towards c.
std::vector<Eye> orbitViews(const Aabb& box, size_t count, double distance, bool orthographic = false);

}  // namespace conescope
