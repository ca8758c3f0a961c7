// What a cluster file gives a mesh: a cluster per face and, from a meshlet file, the bounds the
// engine stored per cluster. io's ClusterFiles.h reads them; the file builder takes them from the
// mesh (Mesh::fileClusters), so whatever read the mesh read its partition with it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace conescope {

// meshoptimizer's meshopt_Bounds, field for field (its header stays out of the core's public
// headers). cone_cutoff = cos of the half-angle; the 8-bit fields decode as value / 127.
struct MeshletBounds {
    std::array<float, 3> center{};
    float radius = 0.0f;
    std::array<float, 3> coneApex{};
    std::array<float, 3> coneAxis{};
    float coneCutoff = 1.0f;
    std::array<int8_t, 3> coneAxisS8{};
    int8_t coneCutoffS8 = 127;
};

struct FileClusters {
    std::vector<uint32_t> clusterOfFace;  // one per face of the mesh, ids as the file numbers them
    uint32_t clusterCount = 0;            // every id below it has a face
    // Per cluster for a meshlet file: the ones it stored, else meshoptimizer's of its own meshlets.
    std::vector<MeshletBounds> bounds;
};

}  // namespace conescope
