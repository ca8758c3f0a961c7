// The per-cluster records the engine tests and the compact octagon read (RecordTests.h), kept with
// the bounds they belong to and made on first use: meshoptimizer's meshopt_Bounds (meshopt/Meshopt.h;
// a meshlet file's own, stored or made from its meshlets), cadscene's packed cone and box (CadsceneCones.h) and
// the 16-byte octagon (CompactOctagons.h). Made once per kind under a lock, so the window's threads
// may ask together; every caller passes the same stages the bounds were made from.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "CadsceneCones.h"
#include "CompactOctagons.h"
#include "CullingInput.h"
#include "FileClusters.h"
#include "Mesh.h"
#include "Partition.h"

namespace conescope {

class EngineRecords {
public:
    // A meshlet file's meshoptimizer bounds, one per cluster: used instead of the partition's.
    void useStoredMeshoptBounds(const std::vector<MeshletBounds>& stored);

    const std::vector<MeshletBounds>& meshopt(const CullingInput& input) const;
    // The mesh's world box: the grid of cadscene's boxes and of the compact octagon's apexes.
    const Aabb& object(const CullingInput& input) const;
    const std::vector<CadsceneRecord>& cadscene(const CullingInput& input) const;
    const std::vector<CadsceneFloat>& cadsceneFloat(const CullingInput& input) const;
    const std::vector<CompactOctagon>& compactOctagons(const CullingInput& input) const;
    const std::vector<DecodedOctagon>& decodedOctagons(const CullingInput& input) const;

private:
    mutable std::mutex mutex_;
    std::vector<MeshletBounds> stored_;
    mutable bool meshoptMade_ = false, objectMade_ = false, cadsceneMade_ = false, compactMade_ = false;
    mutable std::vector<MeshletBounds> meshopt_;
    mutable Aabb object_;
    mutable std::vector<CadsceneRecord> cadscene_;
    mutable std::vector<CadsceneFloat> cadsceneFloat_;
    mutable std::vector<CompactOctagon> compact_;
    mutable std::vector<DecodedOctagon> decoded_;
};

// The fan triangles of each cluster's faces, in face order: what an engine's meshlet would hold.
std::vector<std::vector<uint32_t>> clusterTriangles(const CullingInput& input);

}  // namespace conescope
