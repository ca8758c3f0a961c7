// The JSON side of a glTF 2.0 file (internal to conescope_io): the document of a .gltf or the JSON
// chunk of a .glb, checked, and its default scene walked into mesh instances with world matrices.
//
// assimp decodes the binary data (GltfDecoding.h); everything that decides which triangles exist and
// where they are is done here, because measurement showed assimp 5.2.5 silently wrong there: it
// drops triangles with out-of-range indices, reads accessors whose byteOffset runs past their
// buffer view, reads non-float positions as floats, ignores required extensions and refuses files
// without a scene list. docs/dev/architecture.md ("Why this glTF library") has the measurements.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace conescope {

// A primitive ConeScope turns into triangles: a triangle list, strip or fan with at least one triangle.
struct GltfPrimitive {
    size_t index = 0;         // in the mesh's "primitives"
    int mode = 4;             // 4 triangles, 5 strip, 6 fan
    size_t vertexCount = 0;   // the POSITION accessor's count
    size_t elementCount = 0;  // indices' count, or vertexCount without indices
    size_t triangleCount = 0; // what mode makes of elementCount
    bool draco = false;       // compressed by KHR_draco_mesh_compression
};

// A mesh the scene draws, with the primitives that make triangles.
struct GltfMesh {
    size_t index = 0;  // in the document's "meshes"
    std::vector<GltfPrimitive> primitives;
};

// One node's use of a mesh.
struct GltfInstance {
    size_t node = 0;  // in the document's "nodes"
    size_t mesh = 0;  // in GltfScene::meshes
    glm::dmat4 world{1.0};
};

// What the reader tells the user about parts it did not turn into triangles. Counted per instance.
struct GltfSkipped {
    size_t pointOrLinePrimitives = 0;
    size_t shortPrimitives = 0;      // strips, fans and lists with fewer than 3 vertices
    size_t unfinishedTriangles = 0;  // lists whose count is not a multiple of 3: 1 or 2 vertices left over
    size_t skinnedOrMorphed = 0;     // instances whose skin or morph weights are not applied
    bool gpuInstancing = false;      // EXT_mesh_gpu_instancing used, not applied
};

struct GltfScene {
    nlohmann::json document;
    bool binary = false;
    uint64_t binChunkOffset = 0;  // .glb: where the BIN chunk's 8-byte header starts; 0 without one
    uint64_t binChunkLength = 0;  // its data length
    std::vector<GltfMesh> meshes;
    std::vector<GltfInstance> instances;
    GltfSkipped skipped;
    // Per buffer: the file name its URI stands for, %-escapes decoded, relative to the glTF's folder
    // ("" for data URIs, the BIN chunk and buffers nothing drawn reads).
    std::vector<std::string> bufferFileNames;
    uint64_t bufferBytes = 0;  // the byteLength of every buffer read
    bool usesDraco = false;
};

// Reads and checks the document, walks the default scene ("scene", else scene 0, else every root
// node) and checks every accessor a drawn triangle primitive reads. Throws MeshReadError
// ("path: where: what").
GltfScene loadGltfScene(const std::string& path);

}  // namespace conescope
