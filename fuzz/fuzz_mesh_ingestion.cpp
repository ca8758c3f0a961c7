// The core's ingestion and culling on arbitrary meshes: bytes become positions, faces, a model
// matrix and eyes. A mesh validateMesh accepts must go through face geometry, every builder that
// takes any mesh, every cone and every test without a crash — and no test may cull a cluster that
// the exact oracle says holds a front-facing face.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/Culling.h"
#include "core/RecordTests.h"
#include "core/Settings.h"

namespace {
struct Reader {
    const uint8_t* data;
    size_t size;
    size_t at = 0;
    bool empty() const { return at >= size; }
    uint8_t byte() { return at < size ? data[at++] : 0; }
    float number() {
        float value = 0.0f;
        if (at + 4 <= size) std::memcpy(&value, data + at, 4);
        at += 4;
        return value;
    }
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace conescope;
    Reader in{data, size};
    Mesh mesh;
    const size_t vertexCount = 3 + in.byte() % 64;
    for (size_t v = 0; v < vertexCount; ++v) mesh.positions.emplace_back(in.number(), in.number(), in.number());
    const size_t faceCount = 1 + in.byte() % 64;
    for (size_t f = 0; f < faceCount && !in.empty(); ++f) {
        const size_t corners = 3 + in.byte() % 3;
        std::vector<uint32_t> face;
        for (size_t k = 0; k < corners; ++k) face.push_back(in.byte() % vertexCount);
        mesh.addFace(face.data(), face.size());
    }
    if (in.byte() & 1)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) mesh.model[c][r] = in.number();
    try {
        validateMesh(mesh);
    } catch (const std::runtime_error&) {
        return 0;
    }
    const std::vector<glm::vec3> world = worldPositions(mesh);
    for (const glm::vec3& p : world)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return 0;  // matrix overflowed
    const FaceGeometry faces = computeFaceGeometry(mesh);
    const Partition partition = buildMeshlets(mesh, faces, MeshletLimits{size_t(8 + in.byte() % 32), size_t(4 + in.byte() % 32)});
    std::vector<Eye> eyes = {Eye::perspective({0, 0, 0}), Eye::orthographicAlong({0, 0, 1})};
    while (!in.empty()) {
        const glm::dvec3 point(in.number(), in.number(), in.number());
        if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z)) continue;
        eyes.push_back(Eye::perspective(point));
        if (glm::length(point) > 0.0 && std::isfinite(glm::length(point))) eyes.push_back(Eye::orthographicAlong(point));
    }
    const ClusterFaces rows = facesByCluster(partition);
    for (ConeMethod cone : allConeMethods()) {
        const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, cone);
        const CullingInput input{mesh, world, faces, bounds};
        for (const Eye& eye : eyes) {
            const std::vector<Facing> facing = classifyFaces(mesh, world, faces, eye);
            for (CullTest test : allCullTests())
                for (uint32_t c = 0; c < partition.clusterCount; ++c) {
                    // Engine records as shipped are run (they must not crash) but may cull visible faces.
                    if (!cullCluster(input, c, eye, test) || reproducesEngineRecord(test)) continue;
                    for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i)
                        if (facing[rows.faces[i]] == Facing::Front) __builtin_trap();  // a false cull
                }
        }
    }
    return 0;
}
