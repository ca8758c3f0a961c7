// NVIDIA's cadscene sample's meshlet cull record and test, reproduced as shipped (CullTest::
// CadsceneBoxS8, not conservative: its false culls are counted). From nvpro-samples/
// gl_vk_meshlet_cadscene: the packing in nvmeshlet_packbasic.hpp (buildMeshletEarlyCulling, the
// octahedral helpers in nvmeshlet_builder.hpp) and the test in nvmeshlet_utils.glsl (earlyCull).
//   record (9 bytes of its 16-byte descriptor): the meshlet's box on an 8-bit grid over the object's
//   box (min truncated, max rounded up), the average normal octahedrally encoded in two SNORM8 after
//   the best of floor/ceil (float32x3_to_octn_precise), and -sin of the cone angle as SNORM8, the
//   angle from the smallest dot of a triangle normal with the decoded axis less 1/127; 127 when
//   that dot is not positive (never culled).
//   test: angle < 0 and, for each of the box's eight corners k, dot(N, normalize(eye - k)) < angle.
// Everything in float, as the sample computes and its shader tests it. The object is the mesh in
// world space (its world box is the grid's box).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "Mesh.h"
#include "Views.h"

namespace conescope {

struct CadsceneRecord {
    std::array<uint8_t, 3> boxMin{}, boxMax{};  // UNORM8 on the object's box
    int8_t coneOctX = 0, coneOctY = 0;          // SNORM8 octahedral axis
    int8_t coneAngle = 127;                      // SNORM8 -sin(angle); positive: never culled
};

// The record of a cluster whose triangles are `triangles` (three vertex ids each, into `world`),
// on the grid of `object`.
CadsceneRecord cadsceneRecord(const std::vector<uint32_t>& triangles, const std::vector<glm::vec3>& world, const Aabb& object);

// The record's cone as its shader decodes it: the axis (oct_to_vec3, normalized) and the angle.
struct CadsceneCone {
    glm::vec3 axis{0.0f};
    float angle = 1.0f;
};
CadsceneCone decodeCadsceneCone(const CadsceneRecord& record);
// The box's corners in world space as the shader decodes them.
std::array<glm::vec3, 8> decodeCadsceneCorners(const CadsceneRecord& record, const Aabb& object);

// earlyCull's back-face part. An orthographic eye looking along d tests dot(N, -d) < angle.
bool cadsceneCulls(const CadsceneRecord& record, const Aabb& object, const Eye& eye);
// The same with the unquantised (float) box, axis and angle: the record's float original.
struct CadsceneFloat {
    Aabb box;
    glm::vec3 axis{0.0f};
    float angle = 1.0f;
};
CadsceneFloat cadsceneFloatRecord(const std::vector<uint32_t>& triangles, const std::vector<glm::vec3>& world);
bool cadsceneFloatCulls(const CadsceneFloat& record, const Eye& eye);

// How far it passes (above 0 culls): min over the corners of angle - dot(N, normalize(eye - k)).
double cadsceneMargin(const CadsceneRecord& record, const Aabb& object, const Eye& eye);
// Share of view directions it culls from at infinity: (1 + angle) / 2 for angle < 0, else 0.
double cadsceneCullShare(const CadsceneRecord& record);

}  // namespace conescope
