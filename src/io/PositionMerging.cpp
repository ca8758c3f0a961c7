#include "io/PositionMerging.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace conescope {

namespace {

// The bits of a position with -0 made +0, so positions equal as floats have equal keys.
std::array<uint32_t, 3> positionKey(const glm::vec3& position) {
    std::array<uint32_t, 3> key{};
    for (int k = 0; k < 3; ++k) {
        const float coordinate = position[k] == 0.0f ? 0.0f : position[k];
        std::memcpy(&key[k], &coordinate, 4);
    }
    return key;
}

// Mixes all three coordinates, so points on a grid (many equal x or z) do not collide.
struct PositionKeyHash {
    size_t operator()(const std::array<uint32_t, 3>& key) const {
        return std::hash<uint64_t>()((uint64_t(key[0]) << 32 | key[1]) ^ (uint64_t(key[2]) * 0x9e3779b97f4a7c15ull));
    }
};

}  // namespace

// Merges as vtkMergePoints does (exact equality) but keeps every face: vtkSTLReader's own merging
// drops each triangle two of whose corners merge, so an STL's degenerate triangles never reached
// degenerate_faces.
void mergeEqualPositions(Mesh& mesh) {
    std::unordered_map<std::array<uint32_t, 3>, uint32_t, PositionKeyHash> mergedIndex;
    std::vector<glm::vec3> merged;
    std::vector<uint32_t> mergedIndexOf(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        auto [entry, isNew] = mergedIndex.try_emplace(positionKey(mesh.positions[i]), uint32_t(merged.size()));
        if (isNew) merged.push_back(mesh.positions[i]);
        mergedIndexOf[i] = entry->second;
    }
    for (uint32_t& vertex : mesh.faceVertices) vertex = mergedIndexOf[vertex];
    mesh.positions = std::move(merged);
}

}  // namespace conescope
