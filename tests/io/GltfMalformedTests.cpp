// glTF and GLB files that must be refused, each with a MeshReadError that starts with the path and
// says what is wrong. Each is a sample from tests/data/gltf changed in one place.
#include <cmath>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "GltfTestSupport.h"
#include "io/FileChecks.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using nlohmann::json;
using testing::changedGltf;
using testing::gltfSample;
using testing::putFloat;
using testing::putUint16;
using testing::putUint32;
using testing::ScratchDirectory;

// cube.bin: 24 positions (bytes 0-287), 24 normals (288-575), 36 16-bit indices (576-647).
constexpr size_t firstIndexByte = 576;

// cube.gltf with its buffer changed by `change`.
std::string cubeWithBuffer(const ScratchDirectory& scratch, const std::function<void(std::string&)>& change) {
    const std::string path = changedGltf(scratch, "cube.gltf", "cube.gltf", [](json&) {});
    std::string bytes = readFileBytes(scratch.file("cube.bin"));
    change(bytes);
    scratch.writeFile("cube.bin", bytes);
    return path;
}

std::string changedCube(const ScratchDirectory& scratch, const std::function<void(json&)>& change) {
    return changedGltf(scratch, "cube.gltf", "changed.gltf", change);
}

// cube.glb with its bytes changed by `change`.
std::string changedGlb(const ScratchDirectory& scratch, const std::function<void(std::string&)>& change) {
    std::string bytes = readFileBytes(gltfSample("cube.glb"));
    change(bytes);
    return scratch.writeFile("changed.glb", bytes);
}

TEST(GltfRefusal, IndexOutOfRange) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(cubeWithBuffer(scratch, [](std::string& b) { putUint16(b, firstIndexByte + 10, 24); }),
                      "meshes[0].primitives[0]: 1 of its 12 triangles use a vertex index out of range (24 vertices)");
}

TEST(GltfRefusal, EveryIndexOutOfRange) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(cubeWithBuffer(scratch, [](std::string& b) {
                          for (size_t i = 0; i < 36; ++i) putUint16(b, firstIndexByte + 2 * i, uint16_t(100 + i));
                      }),
                      "every triangle of a primitive uses a vertex index out of range");
}

TEST(GltfRefusal, NonFinitePositions) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(cubeWithBuffer(scratch, [](std::string& b) { putFloat(b, 4 * 12 + 4, std::nanf("")); }),
                      "meshes[0].primitives[0]: vertex 4 has a non-finite coordinate");
    EXPECT_READ_ERROR(cubeWithBuffer(scratch, [](std::string& b) { putFloat(b, 0, INFINITY); }),
                      "vertex 0 has a non-finite coordinate (inf");
}

TEST(GltfRefusal, MissingOrShortBufferFile) {
    ScratchDirectory scratch;
    const std::string path = changedCube(scratch, [](json& d) { d["buffers"][0]["uri"] = "elsewhere.bin"; });
    EXPECT_READ_ERROR(path, "buffers[0]: its file 'elsewhere.bin' does not exist");
    const std::string shortBin = cubeWithBuffer(scratch, [](std::string& b) { b.resize(600); });
    EXPECT_READ_ERROR(shortBin, "buffers[0]: byteLength 648, but its data holds 600 bytes");
}

TEST(GltfRefusal, AccessorsOutsideTheirBufferViews) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][0]["count"] = 25; }),
                      "accessors[0]: 25 elements of 12 bytes from byte 0 run past the end of bufferViews[0] (288 bytes)");
    // assimp 5.2.5 reads this one: it checks the count against the view but not the offset.
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][0]["byteOffset"] = 4; }),
                      "accessors[0]: 24 elements of 12 bytes from byte 4 run past the end of bufferViews[0]");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["bufferViews"][0]["byteStride"] = 16; }),
                      "accessors[0]: 24 elements of 12 bytes, 16 bytes apart, from byte 0 run past the end");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["bufferViews"][0]["byteStride"] = 8; }),
                      "bufferViews[0]: byteStride 8 is shorter than the 12 bytes of an element of accessors[0]");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][2]["count"] = 37; }),
                      "accessors[2]: 37 elements of 2 bytes from byte 0 run past the end of bufferViews[2] (72 bytes)");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["bufferViews"][2]["byteOffset"] = 600; }),
                      "bufferViews[2]: 72 bytes from byte 600 run past the end of buffers[0] (648 bytes)");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][0].erase("bufferView"); }),
                      "accessors[0]: holds no data (no bufferView)");
    EXPECT_READ_ERROR(changedGltf(scratch, "sparse.gltf", "sparse.gltf",
                                  [](json& d) { d["accessors"][0]["sparse"]["values"]["byteOffset"] = 4; }),
                      "accessors[0].sparse.values: 12 elements of 12 bytes from byte 4 run past the end of bufferViews[4] (144 bytes)");
    EXPECT_READ_ERROR(changedGltf(scratch, "sparse.gltf", "sparse.gltf",
                                  [](json& d) { d["accessors"][0]["sparse"]["count"] = 25; }),
                      "accessors[0].sparse.count: 25 replaced elements, more than the accessor's 24");
    // Without a count (or with 0) assimp 5.2.5 copies past its buffers: refused before it sees the file.
    EXPECT_READ_ERROR(changedGltf(scratch, "sparse.gltf", "sparse.gltf", [](json& d) { d["accessors"][0]["sparse"].erase("count"); }),
                      "accessors[0].sparse: has no count");
    EXPECT_READ_ERROR(changedGltf(scratch, "sparse.gltf", "sparse.gltf", [](json& d) { d["accessors"][0]["sparse"]["count"] = 0; }),
                      "accessors[0].sparse.count: must be at least 1");
}

TEST(GltfRefusal, AccessorsOfTheWrongType) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][0]["componentType"] = 5123; }),
                      "accessors[0]: componentType 5123, but meshes[0].primitives[0].attributes.POSITION must be float");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][0]["type"] = "VEC2"; }),
                      "accessors[0]: type \"VEC2\", but meshes[0].primitives[0].attributes.POSITION must be VEC3");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][2]["componentType"] = 5126; }),
                      "accessors[2]: componentType 5126, but meshes[0].primitives[0].indices must be unsigned byte");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["meshes"][0]["primitives"][0]["attributes"].erase("POSITION"); }),
                      "meshes[0].primitives[0]: has no POSITION attribute");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["meshes"][0]["primitives"][0]["mode"] = 7; }),
                      "meshes[0].primitives[0].mode: 7 is not a glTF primitive mode");
}

TEST(GltfRefusal, IndicesThatNameNothing) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["nodes"][0]["mesh"] = 3; }),
                      "nodes[0].mesh: 3 is out of range: the file has 1 meshes");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["nodes"][0]["mesh"] = -1; }),
                      "nodes[0].mesh: expected a non-negative integer, found '-1'");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 9; }),
                      "meshes[0].primitives[0].indices: 9 is out of range: the file has 3 accessors");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["scene"] = "hello"; }),
                      "scene: expected a non-negative integer, found '\"hello\"'");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["scene"] = 2; }), "scene: 2 is out of range: the file has 1 scenes");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["scenes"][0]["nodes"] = {5}; }),
                      "scenes[0].nodes[0]: 5 is out of range: the file has 1 nodes");
}

TEST(GltfRefusal, RecursiveNodeGraph) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) {
                          d["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {2}}}, {{"children", {1}}}});
                      }),
                      "the node graph is recursive: node 1 -> 2 -> 1");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["nodes"][0]["children"] = {0}; }),
                      "the node graph is recursive: node 0 -> 0");
}

// glTF nodes form trees; a node with two parents could draw a mesh exponentially many times.
TEST(GltfRefusal, NodeWithTwoParents) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) {
                          d["nodes"] = json::array({{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}});
                          d["scenes"][0]["nodes"] = {0, 1};
                      }),
                      "nodes[2]: drawn twice, as a child of node 0 and as a child of node 1");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["scenes"][0]["nodes"] = {0, 0}; }),
                      "nodes[0]: drawn twice, as a root of the scene and as a root of the scene");
}

TEST(GltfRefusal, BadTransforms) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) {
                          d["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
                          d["nodes"][0]["scale"] = {2, 2, 2};
                      }),
                      "nodes[0]: has both a matrix and translation/rotation/scale");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) {
                          d["nodes"][0]["matrix"] = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
                      }),
                      "nodes[0].matrix: not an affine transform");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["nodes"][0]["rotation"] = {0, 0, 0, 0}; }),
                      "nodes[0].rotation: a zero quaternion is no rotation");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["nodes"][0]["translation"] = {1, 2}; }),
                      "nodes[0].translation: expected 3 numbers");
    // A scale this large carries the cube beyond float range.
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["nodes"][0]["scale"] = {1e300, 1, 1}; }),
                      "nodes[0]: its world transform moves a vertex beyond the range of float coordinates");
}

TEST(GltfRefusal, RequiredExtensionsThatCannotBeDecoded) {
    ScratchDirectory scratch;
    for (const char* extension : {"EXT_meshopt_compression", "KHR_mesh_quantization", "EXT_mesh_gpu_instancing"}) {
        EXPECT_READ_ERROR(changedCube(scratch, [&](json& d) { d["extensionsUsed"] = d["extensionsRequired"] = {extension}; }),
                          std::string("requires the extension ") + extension + ", which ConeScope cannot decode");
    }
}

// assimp decodes Draco; data that is not Draco is refused with its message (and nothing printed),
// and Draco holds no fans.
TEST(GltfRefusal, BrokenDraco) {
    ScratchDirectory scratch;
    auto draco = [](json& d) {
        d["extensionsUsed"] = d["extensionsRequired"] = {"KHR_draco_mesh_compression"};
        d["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
            {"bufferView", 0}, {"attributes", {{"POSITION", 0}}}};
    };
    ::testing::internal::CaptureStderr();
    EXPECT_READ_ERROR(changedCube(scratch, draco), "Invalid Draco mesh compression in mesh: mesh 0 primitive: 0: Not a Draco file");
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_READ_ERROR(changedCube(scratch, [&](json& d) {
                          draco(d);
                          d["meshes"][0]["primitives"][0]["mode"] = 6;
                      }),
                      "meshes[0].primitives[0]: Draco compression of a triangle fan");
    EXPECT_READ_ERROR(changedCube(scratch, [&](json& d) {
                          draco(d);
                          d["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"].erase("bufferView");
                      }),
                      "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: names no bufferView");
}

TEST(GltfRefusal, NoTriangles) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(changedGltf(scratch, "lines-points.gltf", "lines.gltf",
                                  [](json& d) { d["meshes"][0]["primitives"].erase(0); }),
                      "no triangles in the scene (it holds 3 primitives of points or lines)");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["scenes"][0]["nodes"] = json::array(); }), "no triangles in the scene");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["accessors"][2]["count"] = 2; }),
                      "no triangles in the scene (its triangle primitives have fewer than 3 vertices)");
}

TEST(GltfRefusal, NotAGltfDocument) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("text.gltf", "{\"asset\": {\"version\": \"2.0\"},"), "not valid JSON at line 1, column 30: syntax error");
    EXPECT_READ_ERROR(scratch.writeFile("array.gltf", "[1, 2]"), "not a glTF document: the JSON is not an object");
    EXPECT_READ_ERROR(scratch.writeFile("deep.gltf", "{\"a\":" + std::string(100, '[') + std::string(100, ']') + "}"),
                      "JSON nested more than 64 levels deep");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d["asset"]["version"] = "1.0"; }),
                      "asset.version: glTF '1.0'; only glTF 2.x is read");
    EXPECT_READ_ERROR(changedCube(scratch, [](json& d) { d.erase("asset"); }), "asset.version: missing");
    EXPECT_READ_ERROR(scratch.writeFile("binary.gltf", readFileBytes(gltfSample("cube.glb"))),
                      "binary glTF (it starts with 'glTF'): name it .glb to read it");
}

TEST(GltfRefusal, BrokenDataUris) {
    ScratchDirectory scratch;
    auto changedUri = [&](const std::function<std::string(const std::string&)>& change) {
        return changedGltf(scratch, "cube-embedded.gltf", "uri.gltf",
                           [&](json& d) { d["buffers"][0]["uri"] = change(d["buffers"][0]["uri"].get<std::string>()); });
    };
    EXPECT_READ_ERROR(changedUri([](const std::string& uri) { return uri.substr(0, 100) + "!" + uri.substr(101); }),
                      "buffers[0].uri: the data URI's base64 text is damaged");
    EXPECT_READ_ERROR(changedUri([](const std::string& uri) { return uri.substr(0, uri.size() - 8); }),
                      "buffers[0]: byteLength 648, but its data holds 642 bytes");
    EXPECT_READ_ERROR(changedUri([](const std::string&) { return "data:text/plain,cube"; }),
                      "buffers[0].uri: a data URI that is not base64");
    EXPECT_READ_ERROR(changedUri([](const std::string&) { return "https://example.com/cube.bin"; }),
                      "is not a relative file name; only files beside the glTF are read");
    EXPECT_READ_ERROR(changedUri([](const std::string&) { return "cube%2.bin"; }), "has a broken %-escape");
}

TEST(GltfRefusal, BrokenGlbContainers) {
    ScratchDirectory scratch;
    const size_t size = readFileBytes(gltfSample("cube.glb")).size();
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) { b[0] = 'g'; b[1] = 'L'; }),
                      "not a binary glTF (.glb) file: it starts with 'gLTF'");
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) { putUint32(b, 4, 1); }),
                      "binary glTF version 1; only version 2 is read");
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) { b.resize(b.size() - 100); }),
                      "binary glTF: the header gives a length of " + std::to_string(size) + " bytes, the file has " +
                          std::to_string(size - 100));
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) { putUint32(b, 12, 99999); }),
                      "binary glTF: the JSON chunk's 99999 bytes run past the end of the file");
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) { b.resize(10); }), "shorter than the 20-byte header");
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) { putUint32(b, 16, 0x12345678); }),
                      "binary glTF: the first chunk is not JSON");
    // The BIN chunk cut to 600 bytes (header length adjusted): buffer 0 declares 648.
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) {
                          const size_t binStart = b.size() - 648 - 8;
                          putUint32(b, binStart, 600);
                          b.resize(binStart + 8 + 600);
                          putUint32(b, 8, uint32_t(b.size()));
                      }),
                      "buffers[0]: byteLength 648, but the BIN chunk holds 600 bytes");
    // Without its BIN chunk the first buffer has no data.
    EXPECT_READ_ERROR(changedGlb(scratch, [](std::string& b) {
                          b.resize(b.size() - 648 - 8);
                          putUint32(b, 8, uint32_t(b.size()));
                      }),
                      "buffers[0]: is the .glb's BIN chunk, and the file has none");
}

}  // namespace
}  // namespace conescope
