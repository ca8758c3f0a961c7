#include "io/GltfPrimitives.h"

#include <cctype>
#include <filesystem>
#include <initializer_list>
#include <optional>

#include "io/FileChecks.h"

namespace conescope {

using nlohmann::json;

namespace {

constexpr uint64_t unsignedByte = 5121, unsignedShort = 5123, unsignedInt = 5125, floatComponent = 5126;
enum Mode : uint64_t { points = 0, lineStrip = 3, triangles = 4, triangleStrip = 5, triangleFan = 6 };

uint64_t componentSize(uint64_t componentType) {
    switch (componentType) {
        case 5120: case 5121: return 1;
        case 5122: case 5123: return 2;
        case 5125: case 5126: return 4;
        default: return 0;
    }
}

uint64_t componentsOf(const json& type) {
    static const std::pair<const char*, uint64_t> types[] = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                            {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
    for (const auto& [name, components] : types)
        if (type == name) return components;
    return 0;
}

// Checks bufferViews[view] against its buffer and marks the buffer used; returns the view's length.
uint64_t checkView(const GltfJson& gltf, size_t view, GltfBufferUse& buffers) {
    const std::string name = elementName("bufferViews", view);
    const json& bufferView = gltf.array("bufferViews")[view];
    const json* bufferIndex = gltf.member(bufferView, "buffer", name);
    if (!bufferIndex) gltf.fail(name, "names no buffer");
    const size_t buffer = gltf.index(*bufferIndex, "buffers", name + ".buffer");
    const uint64_t offset = gltf.countOr(bufferView, "byteOffset", 0, name);
    const uint64_t length = gltf.countOr(bufferView, "byteLength", 0, name);
    const uint64_t bufferLength = gltf.countOr(gltf.array("buffers")[buffer], "byteLength", 0, elementName("buffers", buffer));
    if (length > bufferLength || offset > bufferLength - length)
        gltf.fail(name, std::to_string(length) + " bytes from byte " + std::to_string(offset) + " run past the end of " +
                            elementName("buffers", buffer) + " (" + std::to_string(bufferLength) + " bytes)");
    buffers[buffer] = true;
    return length;
}

// Fails unless `count` elements of `size` bytes, `stride` bytes apart from byte `offset`, lie in the view.
void checkInView(const GltfJson& gltf, const std::string& where, size_t view, uint64_t offset, uint64_t count,
                 uint64_t size, uint64_t stride, GltfBufferUse& buffers) {
    const uint64_t viewLength = checkView(gltf, view, buffers);
    if (count == 0) return;
    const bool fits = offset <= viewLength && size <= viewLength - offset &&
                      count - 1 <= (viewLength - offset - size) / stride;
    if (!fits)
        gltf.fail(where, std::to_string(count) + " elements of " + std::to_string(size) + " bytes" +
                             (stride != size ? ", " + std::to_string(stride) + " bytes apart," : "") + " from byte " +
                             std::to_string(offset) + " run past the end of " + elementName("bufferViews", view) + " (" +
                             std::to_string(viewLength) + " bytes)");
}

// Sparse accessors replace `count` elements of their base; their index and value lists must fit too.
void checkSparse(const GltfJson& gltf, const json& sparse, const std::string& where, uint64_t accessorCount,
                 uint64_t elementSize, GltfBufferUse& buffers) {
    // Required and at least 1 (glTF 2.0, 3.6.2.3): without it assimp 5.2.5 copies past its buffers
    // (found by fuzzing).
    if (!gltf.member(sparse, "count", where)) gltf.fail(where, "has no count");
    const uint64_t count = gltf.countOr(sparse, "count", 0, where);
    if (count == 0) gltf.fail(where + ".count", "must be at least 1");
    if (count > accessorCount)
        gltf.fail(where + ".count", std::to_string(count) + " replaced elements, more than the accessor's " +
                                        std::to_string(accessorCount));
    for (const char* part : {"indices", "values"}) {
        const std::string partWhere = where + "." + part;
        const json* list = gltf.member(sparse, part, where);
        const json* view = list ? gltf.member(*list, "bufferView", partWhere) : nullptr;
        if (!view) gltf.fail(partWhere, "missing or without a bufferView");
        uint64_t size = elementSize;
        if (part == std::string("indices")) {
            const uint64_t componentType = gltf.countOr(*list, "componentType", 0, partWhere);
            if (componentType != unsignedByte && componentType != unsignedShort && componentType != unsignedInt)
                gltf.fail(partWhere + ".componentType", "must be an unsigned byte, short or int type");
            size = componentSize(componentType);
        }
        checkInView(gltf, partWhere, gltf.index(*view, "bufferViews", partWhere + ".bufferView"),
                    gltf.countOr(*list, "byteOffset", 0, partWhere), count, size, size, buffers);
    }
}

// Checks the accessor `indexValue` names for a use `where` needs as `type` with one of the component
// types; returns its count. A Draco primitive's accessors hold no data of their own (assimp decodes
// the Draco buffer view and checks it).
uint64_t checkAccessor(const GltfJson& gltf, const json& indexValue, const std::string& where, const char* type,
                       std::initializer_list<uint64_t> componentTypes, const char* componentNames, bool draco,
                       GltfBufferUse& buffers) {
    const size_t index = gltf.index(indexValue, "accessors", where);
    const std::string name = elementName("accessors", index);
    const json& accessor = gltf.array("accessors")[index];
    const json* actualType = gltf.member(accessor, "type", name);
    if (!actualType || *actualType != type)
        gltf.fail(name, "type " + (actualType ? actualType->dump() : std::string("missing")) + ", but " + where +
                            " must be " + type);
    const uint64_t componentType = gltf.countOr(accessor, "componentType", 0, name);
    bool allowed = false;
    for (uint64_t candidate : componentTypes) allowed |= componentType == candidate;
    if (!allowed)
        gltf.fail(name, "componentType " + std::to_string(componentType) + ", but " + where + " must be " + componentNames);
    if (!gltf.member(accessor, "count", name)) gltf.fail(name, "has no count");
    const uint64_t count = gltf.countOr(accessor, "count", 0, name);
    if (draco) return count;
    const uint64_t elementSize = componentSize(componentType) * componentsOf(*actualType);
    const json* view = gltf.member(accessor, "bufferView", name);
    const json* sparse = gltf.member(accessor, "sparse", name);
    if (!view && !sparse) gltf.fail(name, "holds no data (no bufferView)");
    if (view) {
        const size_t viewIndex = gltf.index(*view, "bufferViews", name + ".bufferView");
        const std::string viewName = elementName("bufferViews", viewIndex);
        const uint64_t stride = gltf.countOr(gltf.array("bufferViews")[viewIndex], "byteStride", elementSize, viewName);
        if (stride < elementSize)
            gltf.fail(viewName, "byteStride " + std::to_string(stride) + " is shorter than the " +
                                    std::to_string(elementSize) + " bytes of an element of " + name);
        checkInView(gltf, name, viewIndex, gltf.countOr(accessor, "byteOffset", 0, name), count, elementSize, stride,
                    buffers);
    }
    if (sparse) checkSparse(gltf, *sparse, name + ".sparse", count, elementSize, buffers);
    return count;
}

// The primitive as triangles, or nothing when it makes none (points, lines, too few vertices).
std::optional<GltfPrimitive> checkPrimitive(const GltfJson& gltf, const json& primitive, size_t index,
                                            const std::string& where, GltfMeshCheck& check, GltfBufferUse& buffers) {
    const uint64_t mode = gltf.countOr(primitive, "mode", triangles, where);
    if (mode > triangleFan) gltf.fail(where + ".mode", std::to_string(mode) + " is not a glTF primitive mode");
    if (mode <= lineStrip) {
        ++check.pointOrLinePrimitives;
        return std::nullopt;
    }
    const json* attributes = gltf.member(primitive, "attributes", where);
    const json* position = attributes ? gltf.member(*attributes, "POSITION", where + ".attributes") : nullptr;
    if (!position) gltf.fail(where, "has no POSITION attribute");
    const json* extensions = gltf.member(primitive, "extensions", where);
    GltfPrimitive result;
    result.index = index;
    result.mode = int(mode);
    const json* draco = extensions ? gltf.member(*extensions, "KHR_draco_mesh_compression", where + ".extensions") : nullptr;
    result.draco = draco != nullptr;
    if (draco) {
        if (mode != triangles && mode != triangleStrip)
            gltf.fail(where, "Draco compression of a triangle fan; KHR_draco_mesh_compression holds lists and strips only");
        const std::string dracoWhere = where + ".extensions.KHR_draco_mesh_compression";
        const json* view = gltf.member(*draco, "bufferView", dracoWhere);
        if (!view) gltf.fail(dracoWhere, "names no bufferView");
        checkView(gltf, gltf.index(*view, "bufferViews", dracoWhere + ".bufferView"), buffers);
    }
    result.vertexCount = checkAccessor(gltf, *position, where + ".attributes.POSITION", "VEC3", {floatComponent},
                                       "float (5126) without an extension", result.draco, buffers);
    const json* indices = gltf.member(primitive, "indices", where);
    result.elementCount = indices ? checkAccessor(gltf, *indices, where + ".indices", "SCALAR",
                                                  {unsignedByte, unsignedShort, unsignedInt},
                                                  "unsigned byte, short or int (5121, 5123, 5125)", result.draco, buffers)
                                  : result.vertexCount;
    result.triangleCount = mode == triangles ? result.elementCount / 3 : result.elementCount < 3 ? 0 : result.elementCount - 2;
    check.morphTargets |= gltf.member(primitive, "targets", where) != nullptr;
    if (result.triangleCount == 0) {
        ++check.shortPrimitives;
        return std::nullopt;
    }
    if (result.vertexCount == 0) gltf.fail(where, std::to_string(result.elementCount) + " indices but no vertices");
    if (mode == triangles && result.elementCount % 3 != 0) ++check.unfinishedTriangles;
    return result;
}

bool isBase64Payload(const std::string& text) {
    if (text.size() % 4 != 0) return false;
    size_t padding = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const bool digit = std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/';
        if (c == '=' && i + 2 >= text.size())
            ++padding;
        else if (!digit || padding > 0)
            return false;
    }
    return true;
}

// Bytes a data URI's base64 payload decodes to; fails for any other data URI.
uint64_t dataUriLength(const GltfJson& gltf, const std::string& uri, const std::string& where) {
    const size_t comma = uri.find(',');
    const std::string header = uri.substr(0, comma);
    if (comma == std::string::npos || header.size() < 7 || header.compare(header.size() - 7, 7, ";base64") != 0)
        gltf.fail(where, "a data URI that is not base64");
    const std::string payload = uri.substr(comma + 1);
    if (!isBase64Payload(payload)) gltf.fail(where, "the data URI's base64 text is damaged");
    const size_t padding = payload.size() - payload.find_last_not_of('=') - 1;
    return payload.size() / 4 * 3 - (payload.empty() ? 0 : padding);
}

// A relative URI with its %XX escapes decoded: the file name it stands for.
std::string decodedFileUri(const GltfJson& gltf, const std::string& uri, const std::string& where) {
    if (uri.find("://") != std::string::npos || uri.rfind("file:", 0) == 0 || uri.rfind('/', 0) == 0)
        gltf.fail(where, quotedForMessage(uri, 60) + " is not a relative file name; only files beside the glTF are read");
    std::string name;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            name += uri[i];
            continue;
        }
        if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
            !std::isxdigit(static_cast<unsigned char>(uri[i + 2])))
            gltf.fail(where, quotedForMessage(uri, 60) + " has a broken %-escape");
        name += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
        i += 2;
    }
    if (name.find('\0') != std::string::npos) gltf.fail(where, "the file name holds a NUL byte");
    return name;
}

}  // namespace

bool hasNonZeroWeights(const json& object) {
    auto weights = object.is_object() ? object.find("weights") : object.end();
    if (!object.is_object() || weights == object.end() || !weights->is_array()) return false;
    for (const json& weight : *weights)
        if (weight.is_number() && weight.get<double>() != 0) return true;
    return false;
}

GltfMeshCheck checkGltfMesh(const GltfJson& gltf, size_t mesh, GltfBufferUse& buffers) {
    const std::string where = elementName("meshes", mesh);
    const json& meshJson = gltf.array("meshes")[mesh];
    const json* primitives = gltf.member(meshJson, "primitives", where);
    if (!primitives || !primitives->is_array() || primitives->empty())
        gltf.fail(where + ".primitives", "expected a non-empty array of primitives");
    GltfMeshCheck check;
    check.mesh.index = mesh;
    for (size_t i = 0; i < primitives->size(); ++i) {
        const std::string primitiveWhere = where + ".primitives[" + std::to_string(i) + "]";
        if (auto primitive = checkPrimitive(gltf, (*primitives)[i], i, primitiveWhere, check, buffers))
            check.mesh.primitives.push_back(*primitive);
    }
    check.morphWeights = hasNonZeroWeights(meshJson);
    return check;
}

void checkGltfBuffers(const GltfJson& gltf, const GltfBufferUse& buffers, GltfScene& scene) {
    scene.bufferFileNames.assign(buffers.size(), std::string());
    const std::filesystem::path folder = std::filesystem::path(gltf.path).parent_path();
    for (size_t i = 0; i < buffers.size(); ++i) {
        if (!buffers[i]) continue;
        const std::string name = elementName("buffers", i);
        const json& buffer = gltf.array("buffers")[i];
        const uint64_t length = gltf.countOr(buffer, "byteLength", 0, name);
        const json* uri = gltf.member(buffer, "uri", name);
        scene.bufferBytes += length;
        // assimp reads a .glb's first buffer from the BIN chunk whatever its uri says.
        if (uri && scene.binary && i == 0)
            gltf.fail(name, "the first buffer of a .glb names a file; it is read only from the BIN chunk");
        if (!uri) {
            if (!scene.binary || i != 0) gltf.fail(name, "has no uri; only the first buffer of a .glb is its BIN chunk");
            if (scene.binChunkOffset == 0) gltf.fail(name, "is the .glb's BIN chunk, and the file has none");
            if (scene.binChunkLength < length)
                gltf.fail(name, "byteLength " + std::to_string(length) + ", but the BIN chunk holds " +
                                    std::to_string(scene.binChunkLength) + " bytes");
            continue;
        }
        if (!uri->is_string()) gltf.fail(name + ".uri", "expected a string");
        const std::string text = uri->get<std::string>();
        uint64_t available = 0;
        if (text.rfind("data:", 0) == 0) {
            available = dataUriLength(gltf, text, name + ".uri");
        } else {
            const std::string fileName = decodedFileUri(gltf, text, name + ".uri");
            const std::filesystem::path file = folder / fileName;
            std::error_code error;
            if (!std::filesystem::is_regular_file(file, error))
                gltf.fail(name, "its file " + quotedForMessage(text, 60) + " does not exist (looked for " + file.string() + ")");
            available = std::filesystem::file_size(file, error);
            scene.bufferFileNames[i] = fileName;
        }
        if (available < length)
            gltf.fail(name, "byteLength " + std::to_string(length) + ", but its data holds " + std::to_string(available) +
                                " bytes");
    }
}

}  // namespace conescope
