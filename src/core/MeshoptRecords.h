// meshoptimizer's per-cluster record, meshopt_Bounds, as engines ship it: made by the library
// (meshopt_computeMeshletBounds, 0.18) and tested as shaders test it, in float and NOT made
// conservative, so its false culls can be counted (CullTest::MeshoptApexF32, MeshoptSphereS8).
//   apex-f32:  dot(normalize(cone_apex - eye), cone_axis) >= cone_cutoff      (meshoptimizer.h's perspective test)
//              record: cone_apex, cone_axis, cone_cutoff as floats: 28 bytes
//   sphere-s8: dot(center - eye, axis) >= cutoff * length(center - eye) + radius, with
//              axis = cone_axis_s8 / 127 and cutoff = cone_cutoff_s8 / 127   (niagara, src/shaders/math.h, coneCull)
//              record: center and radius as floats, cone_axis_s8 and cone_cutoff_s8: 20 bytes
// An orthographic view (direction d) tests dot(d, axis) >= cutoff, as meshoptimizer.h gives it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "FileClusters.h"
#include "MeshletArrays.h"
#include "Views.h"

namespace conescope {

// The library's bounds of meshlet m of `arrays`, whose vertex ids index `positions`. A meshlet of
// more than 512 triangles (the library's limit) or with coordinates beyond 1e18 (it squares them in
// float) gets bounds that never cull: cone_cutoff 1, cone_cutoff_s8 127, the rest zero.
MeshletBounds meshoptMeshletBounds(const MeshletArrays& arrays, size_t meshlet, const std::vector<glm::vec3>& positions);
std::vector<MeshletBounds> meshoptBoundsOfMeshlets(const MeshletArrays& arrays, const std::vector<glm::vec3>& positions);

// The same for a cluster given as triangles (three indices each, into `positions`).
MeshletBounds meshoptClusterBounds(const std::vector<uint32_t>& indices, const std::vector<glm::vec3>& positions);

// The two tests from an eye, in float. `eye.position` is rounded to float as a shader gets it.
bool meshoptApexCulls(const MeshletBounds& bounds, const Eye& eye);
bool meshoptSphereS8Culls(const MeshletBounds& bounds, const Eye& eye);
// sphere-s8's float original: the same test with cone_axis and cone_cutoff as floats.
bool meshoptSphereF32Culls(const MeshletBounds& bounds, const Eye& eye);

// How far each passes its threshold (above 0 it culls), in units of the unit view's dot product.
double meshoptApexMargin(const MeshletBounds& bounds, const Eye& eye);
double meshoptSphereS8Margin(const MeshletBounds& bounds, const Eye& eye);

// Share of view directions (eye at infinity) each culls from: (1 - cutoff) / 2, 0 when cutoff >= 1.
double meshoptApexCullShare(const MeshletBounds& bounds);
double meshoptSphereS8CullShare(const MeshletBounds& bounds);

}  // namespace conescope
