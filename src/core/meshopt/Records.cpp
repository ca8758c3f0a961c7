// meshoptimizer's records tested as engines test them: in float, in the shaders' order of
// operations, and not made conservative (Meshopt.h, "Engine records").
#include "Meshopt.h"
#include "Reproduction.h"

#include <algorithm>
#include <cmath>

namespace conescope {

namespace {

using Float3 = std::array<float, 3>;

Float3 minus(const Float3& a, const glm::vec3& b) { return {a[0] - b.x, a[1] - b.y, a[2] - b.z}; }

// Left to right, as a shader's dot and length compile without fused multiply-adds.
float dot3(const Float3& a, const Float3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Float3 decodedAxis(const MeshletBounds& b) {
    return {b.coneAxisS8[0] / 127.0f, b.coneAxisS8[1] / 127.0f, b.coneAxisS8[2] / 127.0f};
}

// The sphere test with an axis and a cutoff: dot(c - e, axis) >= cutoff |c - e| + r.
bool sphereTest(const MeshletBounds& b, const Float3& axis, float cutoff, const Eye& eye) {
    if (eye.orthographic) return dot3(Float3{float(eye.direction.x), float(eye.direction.y), float(eye.direction.z)}, axis) >= cutoff;
    const Float3 toCenter = minus(b.center, glm::vec3(eye.position));
    return dot3(toCenter, axis) >= cutoff * std::sqrt(dot3(toCenter, toCenter)) + b.radius;
}

}  // namespace

std::vector<MeshletBounds> meshoptBoundsOfMeshlets(const MeshletArrays& arrays, const std::vector<glm::vec3>& positions) {
    std::vector<MeshletBounds> bounds(arrays.meshlets.size());
    for (size_t m = 0; m < bounds.size(); ++m) bounds[m] = meshoptMeshletBounds(arrays, m, positions);
    return bounds;
}

std::vector<MeshletBounds> meshoptBoundsOfFileMeshlets(const MeshletArrays& arrays, const Mesh& mesh) {
    std::vector<glm::vec3> world = worldPositions(mesh);
    if (!mesh.fileVertices.empty()) {
        std::vector<glm::vec3> file(mesh.fileVertices.size());
        for (size_t v = 0; v < file.size(); ++v) file[v] = world[mesh.fileVertices[v]];
        world = std::move(file);
    }
    return meshoptBoundsOfMeshlets(arrays, world);
}

bool meshoptApexCulls(const MeshletBounds& b, const Eye& eye) {
    if (eye.orthographic)
        return dot3(Float3{float(eye.direction.x), float(eye.direction.y), float(eye.direction.z)}, b.coneAxis) >= b.coneCutoff;
    const Float3 view = minus(b.coneApex, glm::vec3(eye.position));
    const float length = std::sqrt(dot3(view, view));
    const Float3 unit{view[0] / length, view[1] / length, view[2] / length};
    return dot3(unit, b.coneAxis) >= b.coneCutoff;
}

bool meshoptSphereS8Culls(const MeshletBounds& b, const Eye& eye) { return sphereTest(b, decodedAxis(b), b.coneCutoffS8 / 127.0f, eye); }

bool meshoptSphereF32Culls(const MeshletBounds& b, const Eye& eye) { return sphereTest(b, b.coneAxis, b.coneCutoff, eye); }

double meshoptApexMargin(const MeshletBounds& b, const Eye& eye) {
    const glm::dvec3 axis(b.coneAxis[0], b.coneAxis[1], b.coneAxis[2]);
    glm::dvec3 view = eye.direction;
    if (!eye.orthographic) view = glm::dvec3(b.coneApex[0], b.coneApex[1], b.coneApex[2]) - eye.position;
    const double length = glm::length(view);
    return length > 0.0 ? glm::dot(view, axis) / length - b.coneCutoff : -1.0;
}

double meshoptSphereS8Margin(const MeshletBounds& b, const Eye& eye) {
    const Float3 axis = decodedAxis(b);
    const glm::dvec3 a(axis[0], axis[1], axis[2]);
    const double cutoff = b.coneCutoffS8 / 127.0;
    if (eye.orthographic) return glm::dot(eye.direction, a) - cutoff;
    const glm::dvec3 toCenter = glm::dvec3(b.center[0], b.center[1], b.center[2]) - eye.position;
    const double length = glm::length(toCenter);
    return length > 0.0 ? (glm::dot(toCenter, a) - b.radius) / length - cutoff : -1.0;
}

double meshoptApexCullShare(const MeshletBounds& b) {
    // A zero axis (a cluster of zero-area triangles) passes from everywhere when the cutoff is not above 0.
    if (dot3(b.coneAxis, b.coneAxis) == 0.0f) return b.coneCutoff <= 0.0f ? 1.0 : 0.0;
    return b.coneCutoff >= 1.0f ? 0.0 : (1.0 - std::max(-1.0, double(b.coneCutoff))) / 2.0;
}

double meshoptSphereS8CullShare(const MeshletBounds& b) {
    // The decoded axis is not quite unit: the cone it tests is dot(d, axis / |axis|) >= cutoff / |axis|.
    const Float3 axis = decodedAxis(b);
    const double length = std::sqrt(double(dot3(axis, axis)));
    if (!(length > 0.0)) return b.coneCutoffS8 <= 0 ? 1.0 : 0.0;
    const double cutoff = std::clamp(b.coneCutoffS8 / 127.0 / length, -1.0, 1.0);
    return cutoff >= 1.0 ? 0.0 : (1.0 - cutoff) / 2.0;
}

}  // namespace conescope
