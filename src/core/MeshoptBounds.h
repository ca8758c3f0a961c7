// meshoptimizer's own per-meshlet bounds (meshopt_computeMeshletBounds), for the meshlets an engine
// would ship: written beside a partition (partition -o) and scored by the engine tests when a
// meshlet file stored none.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "FileClusters.h"
#include "MeshletArrays.h"

namespace conescope {

// The library's bounds of meshlet m of `arrays`, whose vertex ids index `positions`. A meshlet of
// more than 512 triangles (the library's limit) gets bounds that never cull: cone_cutoff 1,
// cone_cutoff_s8 127, the rest zero.
MeshletBounds meshoptMeshletBounds(const MeshletArrays& arrays, size_t meshlet, const std::vector<glm::vec3>& positions);

// The same for every meshlet.
std::vector<MeshletBounds> meshoptBoundsOfMeshlets(const MeshletArrays& arrays, const std::vector<glm::vec3>& positions);

}  // namespace conescope
