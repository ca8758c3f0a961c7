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

std::vector<std::vector<uint32_t>> clusterTriangles(const RecordSource& source) {
    const ClusterFaces& rows = source.clusters;
    std::vector<std::vector<uint32_t>> triangles(source.count());
    for (size_t c = 0; c < triangles.size(); ++c)
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            const uint32_t f = rows.faces[i];
            const uint32_t* corners = source.mesh.faceBegin(f);
            for (size_t k = 1; k + 1 < source.mesh.faceSize(f); ++k) triangles[c].insert(triangles[c].end(), {corners[0], corners[k], corners[k + 1]});
        }
    return triangles;
}

void EngineRecords::useStoredMeshoptBounds(const std::vector<MeshletBounds>& stored) {
    std::lock_guard<std::mutex> lock(mutex_);
    stored_ = stored;
    meshoptMade_ = false;
}

const std::vector<MeshletBounds>& EngineRecords::meshopt(const RecordSource& source) const {
    makeOnce(mutex_, meshoptMade_, [&] {
        if (!stored_.empty()) {
            if (stored_.size() != source.count())
                throw std::runtime_error("the cluster file stored bounds for " + std::to_string(stored_.size()) + " clusters, the partition has " +
                                         std::to_string(source.count()));
            meshopt_ = stored_;
            return;
        }
        const std::vector<std::vector<uint32_t>> triangles = clusterTriangles(source);
        meshopt_.assign(triangles.size(), MeshletBounds{});
        forRangesInParallel(triangles.size(), 64, [&](size_t begin, size_t end) {
            for (size_t c = begin; c < end; ++c) meshopt_[c] = meshoptEngineBounds(triangles[c], source.world);
        });
    });
    return meshopt_;
}

const Aabb& EngineRecords::object(const RecordSource& source) const {
    makeOnce(mutex_, objectMade_, [&] { object_ = computeAabb(source.world); });
    return object_;
}

const std::vector<CadsceneRecord>& EngineRecords::cadscene(const RecordSource& source) const {
    const Aabb& box = object(source);
    makeOnce(mutex_, cadsceneMade_, [&] {
        const std::vector<std::vector<uint32_t>> triangles = clusterTriangles(source);
        cadscene_.resize(triangles.size());
        cadsceneFloat_.resize(triangles.size());
        for (size_t c = 0; c < triangles.size(); ++c) {
            cadscene_[c] = cadsceneRecord(triangles[c], source.world, box);
            cadsceneFloat_[c] = cadsceneFloatRecord(triangles[c], source.world);
        }
    });
    return cadscene_;
}

const std::vector<CadsceneFloat>& EngineRecords::cadsceneFloat(const RecordSource& source) const {
    cadscene(source);
    return cadsceneFloat_;
}

const std::vector<CompactOctagon>& EngineRecords::compactOctagons(const RecordSource& source) const {
    const ApexGrid grid = apexGridOver(object(source));
    makeOnce(mutex_, compactMade_, [&] {
        const ClusterFaces& rows = source.clusters;
        compact_.resize(source.count());
        decoded_.resize(source.count());
        forRangesInParallel(source.count(), 64, [&](size_t begin, size_t end) {
            for (size_t c = begin; c < end; ++c) {
                const uint32_t* faces = rows.faces.data() + rows.starts[c];
                const size_t count = rows.starts[c + 1] - rows.starts[c];
                compact_[c] = encodeCompactOctagon(source.cones[c], source.mesh, source.world, source.faces, faces, count, grid);
                decoded_[c] = decodeCompactOctagon(compact_[c], grid);
            }
        });
    });
    return compact_;
}

const std::vector<DecodedOctagon>& EngineRecords::decodedOctagons(const RecordSource& source) const {
    compactOctagons(source);
    return decoded_;
}

}  // namespace conescope
