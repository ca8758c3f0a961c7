#include "CadsceneCones.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace conescope {

namespace {

// nvmeshlet_builder.hpp's vec helpers, in float and in its order of operations.
float dotf(const glm::vec3& a, const glm::vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
float lengthf(const glm::vec3& a) { return std::sqrt(dotf(a, a)); }
glm::vec3 crossf(const glm::vec3& a, const glm::vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// vec_normalize is `a * 1.0f / len`: a division per component (and GLSL's normalize is x / length(x)).
glm::vec3 normalizef(const glm::vec3& a) { return a / glm::vec3(lengthf(a)); }

glm::vec3 octSignNotZero(const glm::vec3& v) { return {v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f, 1.0f}; }

// float32x3_to_oct: the unit sphere onto the octahedron, then onto the xy plane.
glm::vec3 toOct(const glm::vec3& v) {
    const glm::vec3 p = glm::vec3(v.x, v.y, 0.0f) * (1.0f / (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)));
    return v.z <= 0.0f ? glm::vec3(1.0f - std::fabs(p.y), 1.0f - std::fabs(p.x), 0.0f) * octSignNotZero(p) : p;
}

// oct_to_float32x3 (the builder's; the shader's oct_to_vec3 is the same arithmetic).
glm::vec3 fromOct(const glm::vec3& e) {
    glm::vec3 v(e.x, e.y, 1.0f - std::fabs(e.x) - std::fabs(e.y));
    if (v.z < 0.0f) v = glm::vec3(1.0f - std::fabs(v.y), 1.0f - std::fabs(v.x), v.z) * octSignNotZero(v);
    return normalizef(v);
}

// float32x3_to_octn_precise(v, 16): floor to 8-bit SNORM, then the best of floor and ceiling per component.
glm::vec3 toOctPrecise(const glm::vec3& v) {
    const float m = float(1 << 7) - 1.0f;
    glm::vec3 s = toOct(v);
    s = glm::floor(glm::clamp(s, -1.0f, 1.0f) * m) * (1.0f / m);
    glm::vec3 best = s;
    float highest = dotf(fromOct(s), v);
    for (int i = 0; i <= 1; ++i)
        for (int j = 0; j <= 1; ++j)
            if (i != 0 || j != 0) {
                const glm::vec3 candidate = glm::vec3(float(i), float(j), 0.0f) * (1.0f / m) + s;
                const float cosine = dotf(fromOct(candidate), v);
                if (cosine > highest) best = candidate, highest = cosine;
            }
    return best;
}

// The triangles' box and unit normals (zero-length ones kept as they are), as the builder finds them.
struct Triangles {
    Aabb box;
    std::vector<glm::vec3> normals;
    glm::vec3 sum{0.0f};
};

Triangles trianglesOf(const std::vector<uint32_t>& triangles, const std::vector<glm::vec3>& world) {
    Triangles t;
    t.box.min = glm::vec3(FLT_MAX);
    t.box.max = glm::vec3(-FLT_MAX);
    for (size_t i = 0; i + 2 < triangles.size(); i += 3) {
        const glm::vec3 a = world[triangles[i]], b = world[triangles[i + 1]], c = world[triangles[i + 2]];
        t.box.min = glm::min(glm::min(glm::min(t.box.min, a), b), c);
        t.box.max = glm::max(glm::max(glm::max(t.box.max, a), b), c);
        const glm::vec3 cross = crossf(b - a, c - a);
        const float length = lengthf(cross);
        const glm::vec3 normal = length > FLT_EPSILON ? cross * (1.0f / length) : cross;
        t.sum = t.sum + normal;
        t.normals.push_back(normal);
    }
    return t;
}

glm::vec3 averageAxis(const glm::vec3& sum) {
    const float length = lengthf(sum);
    return length > FLT_EPSILON ? sum / glm::vec3(length) : glm::vec3(0.0f);
}

float smallestDot(const std::vector<glm::vec3>& normals, const glm::vec3& axis) {
    float smallest = 1.0f;
    for (const glm::vec3& n : normals) smallest = std::min(smallest, dotf(n, axis));
    return smallest;
}

// float to int as the sample's x86 compilers convert (cvttss2si): truncated, and INT_MIN for NaN or
// out of range, where C++ leaves the conversion undefined.
int32_t truncated(float value) {
    return value >= -2147483648.0f && value < 2147483648.0f ? int32_t(value) : std::numeric_limits<int32_t>::min();
}

// A flat object has no extent on some axis: its grid there is the whole 0..255.
float onGrid(float value, float low, float extent, float fallback) { return extent > 0.0f ? (value - low) / extent : fallback; }

bool boxCornersSeeBack(const std::array<glm::vec3, 8>& corners, const glm::vec3& axis, float angle, const Eye& eye) {
    bool backface = angle < 0.0f;
    if (eye.orthographic) return backface && dotf(axis, -glm::vec3(eye.direction)) < angle;
    const glm::vec3 position(eye.position);
    for (const glm::vec3& corner : corners) backface = backface && dotf(axis, normalizef(position - corner)) < angle;
    return backface;
}

std::array<glm::vec3, 8> cornersOf(const glm::vec3& low, const glm::vec3& high) {
    std::array<glm::vec3, 8> corners;
    for (int n = 0; n < 8; ++n) corners[n] = glm::vec3((n & 1) ? high.x : low.x, (n & 2) ? high.y : low.y, (n & 4) ? high.z : low.z);
    return corners;
}

}  // namespace

CadsceneRecord cadsceneRecord(const std::vector<uint32_t>& triangles, const std::vector<glm::vec3>& world, const Aabb& object) {
    const Triangles t = trianglesOf(triangles, world);
    CadsceneRecord record;
    const glm::vec3 extent = object.max - object.min;
    const int gridLast = 255;
    for (int k = 0; k < 3; ++k) {
        const float low = onGrid(t.box.min[k], object.min[k], extent[k], 0.0f), high = onGrid(t.box.max[k], object.min[k], extent[k], 1.0f);
        record.boxMin[k] = uint8_t(std::max(0, std::min(truncated(std::trunc(low * float(gridLast))), gridLast - 1)));
        record.boxMax[k] = uint8_t(std::max(0, std::min(truncated(std::ceil(high * float(gridLast))), gridLast)));
    }
    const glm::vec3 average = averageAxis(t.sum);
    if (average == glm::vec3(0.0f)) {
        // Only zero-area triangles: the sample's encoding of a zero axis is NaN, which x86 converts to
        // -127 in each component, and its smallest dot is not positive: never culled.
        record.coneOctX = record.coneOctY = -127;
        return record;
    }
    const glm::vec3 packed = toOctPrecise(average);
    record.coneOctX = int8_t(std::min(127, std::max(-127, truncated(packed.x * 127.0f))));
    record.coneOctY = int8_t(std::min(127, std::max(-127, truncated(packed.y * 127.0f))));
    const glm::vec3 axis = fromOct(glm::vec3(float(record.coneOctX) / 127.0f, float(record.coneOctY) / 127.0f, 0.0f));
    // The sample's safety delta for the quantised axis, then -sin(angle) when the cone is narrower than a hemisphere.
    const float mindot = std::max(-1.0f, smallestDot(t.normals, axis) - 1.0f / 127.0f);
    record.coneAngle = 127;
    if (mindot > 0.0f) record.coneAngle = int8_t(std::max(-127, std::min(127, truncated(-std::sin(std::acos(mindot)) * 127.0f))));
    return record;
}

CadsceneCone decodeCadsceneCone(const CadsceneRecord& record) {
    // unpackSnorm4x8: clamp(value / 127, -1, 1); the world normal is normalized once more.
    auto snorm = [](int8_t value) { return std::clamp(float(value) / 127.0f, -1.0f, 1.0f); };
    const glm::vec3 axis = fromOct(glm::vec3(snorm(record.coneOctX), snorm(record.coneOctY), 0.0f));
    return {normalizef(axis), snorm(record.coneAngle)};
}

std::array<glm::vec3, 8> decodeCadsceneCorners(const CadsceneRecord& record, const Aabb& object) {
    const glm::vec3 extent = object.max - object.min;
    glm::vec3 low, high;
    for (int k = 0; k < 3; ++k) {
        low[k] = float(record.boxMin[k]) / 255.0f * extent[k] + object.min[k];
        high[k] = float(record.boxMax[k]) / 255.0f * extent[k] + object.min[k];
    }
    return cornersOf(low, high);
}

bool cadsceneCulls(const CadsceneRecord& record, const Aabb& object, const Eye& eye) {
    const CadsceneCone cone = decodeCadsceneCone(record);
    return boxCornersSeeBack(decodeCadsceneCorners(record, object), cone.axis, cone.angle, eye);
}

CadsceneFloat cadsceneFloatRecord(const std::vector<uint32_t>& triangles, const std::vector<glm::vec3>& world) {
    const Triangles t = trianglesOf(triangles, world);
    CadsceneFloat record;
    record.box = t.box;
    record.axis = averageAxis(t.sum);
    const float mindot = smallestDot(t.normals, record.axis);
    record.angle = mindot > 0.0f ? -std::sin(std::acos(mindot)) : 1.0f;
    return record;
}

bool cadsceneFloatCulls(const CadsceneFloat& record, const Eye& eye) {
    return boxCornersSeeBack(cornersOf(record.box.min, record.box.max), record.axis, record.angle, eye);
}

double cadsceneMargin(const CadsceneRecord& record, const Aabb& object, const Eye& eye) {
    const CadsceneCone cone = decodeCadsceneCone(record);
    if (eye.orthographic) return cone.angle - glm::dot(glm::dvec3(cone.axis), -eye.direction);
    double margin = std::numeric_limits<double>::infinity();
    for (const glm::vec3& corner : decodeCadsceneCorners(record, object)) {
        const glm::dvec3 toEye = eye.position - glm::dvec3(corner);
        const double length = glm::length(toEye);
        margin = std::min(margin, length > 0.0 ? double(cone.angle) - glm::dot(glm::dvec3(cone.axis), toEye) / length : -1.0);
    }
    return margin;
}

double cadsceneCullShare(const CadsceneRecord& record) {
    const float angle = decodeCadsceneCone(record).angle;
    return angle < 0.0f ? (1.0 + double(angle)) / 2.0 : 0.0;
}

}  // namespace conescope
