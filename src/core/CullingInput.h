// One cluster set's culling inputs: what every cluster test and every record reads.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "ClusterBounds.h"
#include "Mesh.h"

namespace conescope {

struct ClusterBatch;

// The stages a cluster test reads: the mesh, its world positions and face geometry (from the same
// mesh), the clusters' bounds, and their records (ClusterBounds::records, made on first use).
struct CullingInput {
    const Mesh& mesh;
    const std::vector<glm::vec3>& world;
    const FaceGeometry& faces;
    const ClusterBounds& bounds;
    // The same bounds as float arrays (BatchCulling.h) for many views; made per call when null.
    const ClusterBatch* batch = nullptr;
};

}  // namespace conescope
