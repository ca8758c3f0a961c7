#include "io/GltfDocument.h"

#include <fstream>
#include <map>

#include <glm/gtc/quaternion.hpp>

#include "io/FileChecks.h"
#include "io/GltfJson.h"
#include "io/GltfPrimitives.h"
#include "io/MeshReader.h"

namespace conescope {

using nlohmann::json;

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& what) { throw MeshReadError(path + ": " + what); }

uint32_t littleEndian32(const char* bytes) {
    return uint32_t(uint8_t(bytes[0])) | uint32_t(uint8_t(bytes[1])) << 8 | uint32_t(uint8_t(bytes[2])) << 16 |
           uint32_t(uint8_t(bytes[3])) << 24;
}

constexpr uint32_t glbMagic = 0x46546c67;      // "glTF"
constexpr uint32_t jsonChunkType = 0x4e4f534a;  // "JSON"
constexpr uint32_t binChunkType = 0x004e4942;   // "BIN\0"

// The JSON chunk of a .glb, after checking the 12-byte header and the chunk table against the
// file's real size; records where the BIN chunk is. Reads only the header and the JSON, not the
// binary data, which can be large.
std::string readGlbJson(const std::string& path, GltfScene& scene) {
    const uint64_t fileSize = fileSizeOrThrow(path);
    std::ifstream input(path, std::ios::binary);
    char header[20] = {};
    if (fileSize < 20 || !input.read(header, 20))
        refuse(path, "binary glTF: the file is " + std::to_string(fileSize) + " bytes, shorter than the 20-byte header");
    if (littleEndian32(header) != glbMagic)
        refuse(path, "not a binary glTF (.glb) file: it starts with " + quotedForMessage(std::string(header, 4)) +
                         ", not 'glTF'");
    if (littleEndian32(header + 4) != 2)
        refuse(path, "binary glTF version " + std::to_string(littleEndian32(header + 4)) + "; only version 2 is read");
    if (littleEndian32(header + 8) != fileSize)
        refuse(path, "binary glTF: the header gives a length of " + std::to_string(littleEndian32(header + 8)) +
                         " bytes, the file has " + std::to_string(fileSize) + " (cut short or extended?)");
    const uint64_t jsonLength = littleEndian32(header + 12);
    if (littleEndian32(header + 16) != jsonChunkType) refuse(path, "binary glTF: the first chunk is not JSON");
    if (jsonLength > fileSize - 20)
        refuse(path, "binary glTF: the JSON chunk's " + std::to_string(jsonLength) + " bytes run past the end of the file");
    std::string text(size_t(jsonLength), '\0');
    if (!input.read(text.data(), std::streamsize(jsonLength))) refuse(path, "read error");
    // Chunks start on 4-byte boundaries; a BIN chunk, when there is one, comes right after the JSON.
    const uint64_t binStart = 20 + (jsonLength + 3) / 4 * 4;
    char chunk[8] = {};
    if (binStart + 8 <= fileSize && input.seekg(std::streamoff(binStart)) && input.read(chunk, 8) &&
        littleEndian32(chunk + 4) == binChunkType) {
        scene.binChunkOffset = binStart;
        scene.binChunkLength = littleEndian32(chunk);
        if (scene.binChunkLength > fileSize - binStart - 8)
            refuse(path, "binary glTF: the BIN chunk's " + std::to_string(scene.binChunkLength) +
                             " bytes run past the end of the file");
    }
    return text;
}

// Nesting deeper than any glTF needs: refused before a recursive JSON reader (assimp's) sees it.
bool nestedDeeperThan(const json& value, int levels) {
    if (!value.is_structured()) return false;
    if (levels == 0) return true;
    for (const json& child : value)
        if (nestedDeeperThan(child, levels - 1)) return true;
    return false;
}

json parseDocument(const std::string& path, const std::string& text) {
    json document;
    try {
        document = json::parse(text);
    } catch (const json::parse_error& error) {
        // nlohmann's message after its "[json.exception.parse_error.101] " tag gives the byte position.
        std::string what = error.what();
        const size_t tagEnd = what.find("] ");
        if (tagEnd != std::string::npos) what = what.substr(tagEnd + 2);
        if (what.rfind("parse error ", 0) == 0) refuse(path, "not valid JSON " + what.substr(12));
        refuse(path, "not valid JSON: " + what);
    }
    if (!document.is_object()) refuse(path, "not a glTF document: the JSON is not an object");
    if (nestedDeeperThan(document, 64)) refuse(path, "JSON nested more than 64 levels deep");
    return document;
}

void checkVersion(const GltfJson& gltf) {
    const json* asset = gltf.member(gltf.root, "asset", "");
    const json* version = asset ? gltf.member(*asset, "version", "asset") : nullptr;
    if (!version || !version->is_string()) gltf.fail("asset.version", "missing: not a glTF 2.0 document");
    const std::string text = version->get<std::string>();
    if (text.rfind("2.", 0) != 0) gltf.fail("asset.version", "glTF " + quotedForMessage(text) + "; only glTF 2.x is read");
}

// Extensions that change how a mesh looks (materials, techniques, textures, lights), never its
// triangles: a file that requires them is still read right for its geometry. Every other required
// extension may change the triangles (compressed or quantised data, instancing) and is refused,
// except Draco, which assimp decodes.
bool requiredExtensionIsReadable(const std::string& name) {
    const std::string withoutVendor = name.substr(name.find('_') == std::string::npos ? 0 : name.find('_') + 1);
    for (const char* prefix : {"materials_", "technique", "texture_", "lights_"})
        if (withoutVendor.rfind(prefix, 0) == 0) return true;
    return name == "KHR_draco_mesh_compression";
}

void checkExtensions(const GltfJson& gltf, GltfSkipped& skipped) {
    const json& required = gltf.array("extensionsRequired");
    for (size_t i = 0; i < required.size(); ++i) {
        if (!required[i].is_string()) gltf.fail(elementName("extensionsRequired", i), "expected an extension name");
        const std::string name = required[i].get<std::string>();
        if (!requiredExtensionIsReadable(name))
            gltf.fail("", "requires the extension " + name + ", which ConeScope cannot decode");
    }
    const json& used = gltf.array("extensionsUsed");
    for (const json& name : used) skipped.gpuInstancing |= name == "EXT_mesh_gpu_instancing";
}

std::vector<double> numbers(const GltfJson& gltf, const json& node, const char* key, size_t size,
                            const std::string& where) {
    const json* value = gltf.member(node, key, where);
    if (!value) return {};
    if (!value->is_array() || value->size() != size)
        gltf.fail(where + "." + key, "expected " + std::to_string(size) + " numbers");
    std::vector<double> result;
    for (size_t i = 0; i < size; ++i) result.push_back(gltf.number((*value)[i], where + "." + key));
    return result;
}

// The node's transform relative to its parent: its column-major "matrix", or T * R * S.
glm::dmat4 localMatrix(const GltfJson& gltf, const json& node, const std::string& where) {
    const std::vector<double> matrix = numbers(gltf, node, "matrix", 16, where);
    const std::vector<double> t = numbers(gltf, node, "translation", 3, where);
    const std::vector<double> r = numbers(gltf, node, "rotation", 4, where);
    const std::vector<double> s = numbers(gltf, node, "scale", 3, where);
    if (!matrix.empty()) {
        if (!t.empty() || !r.empty() || !s.empty())
            gltf.fail(where, "has both a matrix and translation/rotation/scale; glTF allows one or the other");
        // A projective matrix would need a division per vertex and cannot come from TRS, which glTF requires.
        if (matrix[3] != 0 || matrix[7] != 0 || matrix[11] != 0 || matrix[15] != 1)
            gltf.fail(where + ".matrix", "not an affine transform (its last row is not 0 0 0 1)");
        glm::dmat4 result;
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) result[column][row] = matrix[size_t(column * 4 + row)];
        return result;
    }
    glm::dmat4 result(1.0);
    if (!t.empty()) result[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
    if (!r.empty()) {
        // glTF stores x, y, z, w; a rotation must be a unit quaternion, which exporters round.
        const glm::dquat q(r[3], r[0], r[1], r[2]);
        if (glm::length(q) < 1e-6) gltf.fail(where + ".rotation", "a zero quaternion is no rotation");
        result = result * glm::mat4_cast(glm::normalize(q));
    }
    if (!s.empty()) result = result * glm::dmat4(glm::dvec4(s[0], 0, 0, 0), glm::dvec4(0, s[1], 0, 0),
                                                 glm::dvec4(0, 0, s[2], 0), glm::dvec4(0, 0, 0, 1));
    return result;
}

std::vector<size_t> childrenOf(const GltfJson& gltf, size_t node) {
    const std::string where = elementName("nodes", node);
    const json* children = gltf.member(gltf.array("nodes")[node], "children", where);
    std::vector<size_t> result;
    if (!children) return result;
    if (!children->is_array()) gltf.fail(where + ".children", "expected an array of node indices");
    for (size_t i = 0; i < children->size(); ++i)
        result.push_back(gltf.index((*children)[i], "nodes", where + ".children[" + std::to_string(i) + "]"));
    return result;
}

// The root nodes drawn: the scene "scene" names, else the first scene, else (no scene list) every
// node that is no node's child.
std::vector<size_t> sceneRoots(const GltfJson& gltf) {
    const json& scenes = gltf.array("scenes");
    const json* chosen = gltf.member(gltf.root, "scene", "");
    if (chosen || !scenes.empty()) {
        const size_t scene = chosen ? gltf.index(*chosen, "scenes", "scene") : 0;
        const std::string where = elementName("scenes", scene);
        const json* nodes = gltf.member(scenes[scene], "nodes", where);
        std::vector<size_t> roots;
        if (nodes && !nodes->is_array()) gltf.fail(where + ".nodes", "expected an array of node indices");
        for (size_t i = 0; nodes && i < nodes->size(); ++i)
            roots.push_back(gltf.index((*nodes)[i], "nodes", where + ".nodes[" + std::to_string(i) + "]"));
        return roots;
    }
    std::vector<bool> isChild(gltf.array("nodes").size(), false);
    for (size_t node = 0; node < isChild.size(); ++node)
        for (size_t child : childrenOf(gltf, node)) isChild[child] = true;
    std::vector<size_t> roots;
    for (size_t node = 0; node < isChild.size(); ++node)
        if (!isChild[node]) roots.push_back(node);
    return roots;
}

struct WalkStep {
    size_t node;
    glm::dmat4 world;
    std::vector<size_t> children;
    size_t nextChild = 0;
};

std::string pathThrough(const std::vector<WalkStep>& stack, size_t repeated) {
    std::string text;
    bool onCycle = false;
    for (const WalkStep& step : stack) {
        onCycle |= step.node == repeated;
        if (onCycle) text += std::to_string(step.node) + " -> ";
    }
    return text + std::to_string(repeated);
}

struct NodeUse {
    size_t node;
    glm::dmat4 world;
};

// Every node under the roots with its world matrix, depth first with an explicit stack (a long
// chain of nodes cannot overflow the call stack). A node met again on the current path makes the
// graph recursive; met again elsewhere, it has two parents, which glTF forbids and which would let
// a few nodes draw a mesh exponentially many times.
std::vector<NodeUse> walkNodes(const GltfJson& gltf, const std::vector<size_t>& roots) {
    enum : uint8_t { unseen, onPath, done };
    std::vector<uint8_t> state(gltf.array("nodes").size(), unseen);
    std::vector<size_t> parent(state.size(), SIZE_MAX);
    std::vector<NodeUse> uses;
    std::vector<WalkStep> stack;
    auto enter = [&](size_t node, const glm::dmat4& parentWorld, size_t from) {
        if (state[node] == onPath)
            gltf.fail("", "the node graph is recursive: node " + pathThrough(stack, node));
        if (state[node] == done) {
            auto role = [](size_t parentNode) {
                return parentNode == SIZE_MAX ? std::string("a root of the scene") : "a child of node " + std::to_string(parentNode);
            };
            gltf.fail(elementName("nodes", node), "drawn twice, as " + role(parent[node]) + " and as " + role(from) +
                                                      "; a glTF node has one parent at most");
        }
        state[node] = onPath;
        parent[node] = from;
        const glm::dmat4 world = parentWorld * localMatrix(gltf, gltf.array("nodes")[node], elementName("nodes", node));
        uses.push_back({node, world});
        stack.push_back({node, world, childrenOf(gltf, node)});
    };
    for (size_t root : roots) {
        enter(root, glm::dmat4(1.0), SIZE_MAX);
        while (!stack.empty()) {
            WalkStep& top = stack.back();
            if (top.nextChild == top.children.size()) {
                state[top.node] = done;
                stack.pop_back();
                continue;
            }
            const size_t child = top.children[top.nextChild++];
            const size_t from = top.node;
            const glm::dmat4 world = top.world;
            enter(child, world, from);
        }
    }
    return uses;
}

}  // namespace

GltfScene loadGltfScene(const std::string& path) {
    GltfScene scene;
    scene.binary = lowerCaseExtension(path) == ".glb";
    std::string text = scene.binary ? readGlbJson(path, scene) : readFileBytes(path);
    if (!scene.binary && text.compare(0, 4, "glTF") == 0)
        refuse(path, "binary glTF (it starts with 'glTF'): name it .glb to read it");
    scene.document = parseDocument(path, text);
    text = std::string();
    const GltfJson gltf{path, scene.document};
    checkVersion(gltf);
    checkExtensions(gltf, scene.skipped);

    // Each mesh is checked once; what it skips counts once per instance.
    std::map<size_t, GltfMeshCheck> checks;
    std::map<size_t, size_t> slotOfMesh;  // document mesh -> index in scene.meshes
    GltfBufferUse buffers(gltf.array("buffers").size());
    for (const NodeUse& use : walkNodes(gltf, sceneRoots(gltf))) {
        const std::string where = elementName("nodes", use.node);
        const json& node = gltf.array("nodes")[use.node];
        const json* meshValue = gltf.member(node, "mesh", where);
        if (!meshValue) continue;
        const size_t mesh = gltf.index(*meshValue, "meshes", where + ".mesh");
        auto [found, isNew] = checks.try_emplace(mesh);
        const GltfMeshCheck& check = found->second;
        if (isNew) {
            found->second = checkGltfMesh(gltf, mesh, buffers);
            if (!check.mesh.primitives.empty()) {
                slotOfMesh[mesh] = scene.meshes.size();
                scene.meshes.push_back(check.mesh);
            }
        }
        scene.skipped.pointOrLinePrimitives += check.pointOrLinePrimitives;
        scene.skipped.shortPrimitives += check.shortPrimitives;
        scene.skipped.unfinishedTriangles += check.unfinishedTriangles;
        if (gltf.member(node, "skin", where) || (check.morphTargets && (check.morphWeights || hasNonZeroWeights(node))))
            ++scene.skipped.skinnedOrMorphed;
        if (!check.mesh.primitives.empty()) scene.instances.push_back({use.node, slotOfMesh[mesh], use.world});
    }
    checkGltfBuffers(gltf, buffers, scene);
    for (const GltfMesh& mesh : scene.meshes)
        for (const GltfPrimitive& primitive : mesh.primitives) scene.usesDraco |= primitive.draco;
    return scene;
}

}  // namespace conescope
