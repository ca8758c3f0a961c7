// The eye swept across a cluster's cull boundary, for a lesson's animation: eye positions on an arc
// around the cluster (the mesh centre for an orthographic eye) in the plane of the cone axis V1 and the
// current view vector, at the eye's distance, crossing the angle where the displayed test's decision
// flips. The boundary is found with the test itself, so the sweep is true to every test (round, box,
// octagon, an engine's record) without a formula per test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "Pipeline.h"

namespace conescope {

struct EyeSweep {
    std::vector<glm::dvec3> positions;  // the eye at each frame, in order
    std::vector<uint8_t> culled;        // the displayed test's decision at each (1 = culled)
    double boundaryDegrees = 0.0;       // the angle between V1 and the view direction where the decision flips
    double startDegrees = 0.0, endDegrees = 0.0;  // the first and last frame's angle
    glm::dvec3 centre{0.0};             // what the arc turns around
    double distance = 0.0;              // the arc's radius
};

// `frames` (at least 2) eye positions from the side of the boundary the eye at `position` is on to
// the other, evenly spaced in angle over `spanDegrees` either side of the boundary (clamped to the
// arc), no frame on the boundary itself. The arc is at the eye's distance, or farther (up to 16 times)
// when no eye at that distance is culled (a sphere test near the cluster). Throws
// std::invalid_argument when the cluster has no cone (no eye culls it) or no eye on the arcs tried is
// culled, and for fewer than 2 frames.
EyeSweep sweepAcrossCull(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings, uint32_t cluster,
                         const glm::dvec3& position, size_t frames, double spanDegrees = 12.0);

}  // namespace conescope
