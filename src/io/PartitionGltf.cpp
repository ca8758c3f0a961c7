#include "io/PartitionGltf.h"

#include <cstring>

#include <nlohmann/json.hpp>

namespace conescope {

namespace {

std::string base64(const std::string& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t a = uint8_t(bytes[i]), b = i + 1 < bytes.size() ? uint8_t(bytes[i + 1]) : 0,
                       c = i + 2 < bytes.size() ? uint8_t(bytes[i + 2]) : 0;
        const uint32_t group = a << 16 | b << 8 | c;
        text += digits[group >> 18 & 63];
        text += digits[group >> 12 & 63];
        text += i + 1 < bytes.size() ? digits[group >> 6 & 63] : '=';
        text += i + 2 < bytes.size() ? digits[group & 63] : '=';
    }
    return text;
}

template <typename T>
void append(std::string& bytes, T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));  // glTF is little-endian, as x86-64 and ARM64 are
    bytes.append(raw, sizeof(T));
}

}  // namespace

std::string partitionGltf(const Mesh& mesh, const Partition& partition) {
    using Json = nlohmann::json;
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const Aabb box = computeAabb(world);
    std::string bytes;
    for (const glm::vec3& p : world) append(bytes, p.x), append(bytes, p.y), append(bytes, p.z);
    const size_t positionBytes = bytes.size();
    const ClusterFaces rows = facesByCluster(partition);
    Json accessors = Json::array(), primitives = Json::array();
    accessors.push_back({{"bufferView", 0}, {"componentType", 5126}, {"count", world.size()}, {"type", "VEC3"},
                         {"min", {box.min.x, box.min.y, box.min.z}}, {"max", {box.max.x, box.max.y, box.max.z}}});
    for (uint32_t c = 0; c < partition.clusterCount; ++c) {
        const size_t offset = bytes.size() - positionBytes;
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            const uint32_t* corners = mesh.faceBegin(rows.faces[i]);
            // A mirroring model matrix turns the winding; the positions are written in world space.
            const bool mirrored = glm::determinant(mesh.model) < 0.0;
            for (size_t k = 1; k + 1 < mesh.faceSize(rows.faces[i]); ++k) {
                append(bytes, corners[0]);
                append(bytes, corners[mirrored ? k + 1 : k]);
                append(bytes, corners[mirrored ? k : k + 1]);
            }
        }
        accessors.push_back({{"bufferView", 1}, {"byteOffset", offset}, {"componentType", 5125},
                             {"count", (bytes.size() - positionBytes - offset) / 4}, {"type", "SCALAR"}});
        primitives.push_back({{"attributes", {{"POSITION", 0}}}, {"indices", c + 1}, {"mode", 4}});
    }
    const Json document = {
        {"asset", {{"version", "2.0"}, {"generator", "ConeScope (a primitive per cluster)"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", primitives}}}},
        {"buffers", {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positionBytes}, {"target", 34962}},
          {{"buffer", 0}, {"byteOffset", positionBytes}, {"byteLength", bytes.size() - positionBytes}, {"target", 34963}}}},
        {"accessors", accessors}};
    return document.dump(1) + "\n";
}

}  // namespace conescope
