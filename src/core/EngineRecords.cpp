#include "EngineRecords.h"

#include <stdexcept>

#include "Parallel.h"
#include "meshopt/Meshopt.h"

namespace conescope {

namespace {

// Fills `out` once (the flag says whether it was made), under the records' lock.
template <typename Make>
void makeOnce(std::mutex& mutex, bool& made, Make make) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!made) make(), made = true;
}

}  // namespace

std::shared_ptr<EngineRecords> makeEngineRecords() { return std::make_shared<EngineRecords>(); }

std::vector<std::vector<uint32_t>> clusterTriangles(const CullingInput& input) {
    const ClusterFaces& rows = input.bounds.faces;
    std::vector<std::vector<uint32_t>> triangles(input.bounds.count());
    for (size_t c = 0; c < triangles.size(); ++c)
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            const uint32_t f = rows.faces[i];
            const uint32_t* corners = input.mesh.faceBegin(f);
            for (size_t k = 1; k + 1 < input.mesh.faceSize(f); ++k) triangles[c].insert(triangles[c].end(), {corners[0], corners[k], corners[k + 1]});
        }
    return triangles;
}

void EngineRecords::useStoredMeshoptBounds(const std::vector<MeshletBounds>& stored) {
    std::lock_guard<std::mutex> lock(mutex_);
    stored_ = stored;
    meshoptMade_ = false;
}

const std::vector<MeshletBounds>& EngineRecords::meshopt(const CullingInput& input) const {
    makeOnce(mutex_, meshoptMade_, [&] {
        if (!stored_.empty()) {
            if (stored_.size() != input.bounds.count())
                throw std::runtime_error("the cluster file stored bounds for " + std::to_string(stored_.size()) + " clusters, the partition has " +
                                         std::to_string(input.bounds.count()));
            meshopt_ = stored_;
            return;
        }
        const std::vector<std::vector<uint32_t>> triangles = clusterTriangles(input);
        meshopt_.assign(triangles.size(), MeshletBounds{});
        forRangesInParallel(triangles.size(), 64, [&](size_t begin, size_t end) {
            for (size_t c = begin; c < end; ++c) meshopt_[c] = meshoptEngineBounds(triangles[c], input.world);
        });
    });
    return meshopt_;
}

const Aabb& EngineRecords::object(const CullingInput& input) const {
    makeOnce(mutex_, objectMade_, [&] { object_ = computeAabb(input.world); });
    return object_;
}

const std::vector<CadsceneRecord>& EngineRecords::cadscene(const CullingInput& input) const {
    const Aabb& box = object(input);
    makeOnce(mutex_, cadsceneMade_, [&] {
        const std::vector<std::vector<uint32_t>> triangles = clusterTriangles(input);
        cadscene_.resize(triangles.size());
        cadsceneFloat_.resize(triangles.size());
        for (size_t c = 0; c < triangles.size(); ++c) {
            cadscene_[c] = cadsceneRecord(triangles[c], input.world, box);
            cadsceneFloat_[c] = cadsceneFloatRecord(triangles[c], input.world);
        }
    });
    return cadscene_;
}

const std::vector<CadsceneFloat>& EngineRecords::cadsceneFloat(const CullingInput& input) const {
    cadscene(input);
    return cadsceneFloat_;
}

const std::vector<CompactOctagon>& EngineRecords::compactOctagons(const CullingInput& input) const {
    const ApexGrid grid = apexGridOver(object(input));
    makeOnce(mutex_, compactMade_, [&] {
        const ClusterFaces& rows = input.bounds.faces;
        compact_.resize(input.bounds.count());
        decoded_.resize(input.bounds.count());
        forRangesInParallel(input.bounds.count(), 64, [&](size_t begin, size_t end) {
            for (size_t c = begin; c < end; ++c) {
                const uint32_t* faces = rows.faces.data() + rows.starts[c];
                const size_t count = rows.starts[c + 1] - rows.starts[c];
                compact_[c] = encodeCompactOctagon(input.bounds.cones[c], input.mesh, input.world, input.faces, faces, count, grid);
                decoded_[c] = decodeCompactOctagon(compact_[c], grid);
            }
        });
    });
    return compact_;
}

const std::vector<DecodedOctagon>& EngineRecords::decodedOctagons(const CullingInput& input) const {
    compactOctagons(input);
    return decoded_;
}

}  // namespace conescope
