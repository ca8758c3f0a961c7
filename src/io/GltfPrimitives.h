// Checks of a glTF mesh's primitives, the accessors they read and the buffers behind them
// (internal to conescope_io). Each accessor a triangle primitive reads must have the type the
// glTF spec requires and lie inside its buffer view, each view inside its buffer, each buffer's data
// must exist (its file, the .glb's BIN chunk, or a valid base64 data URI): then assimp decodes data
// that is really there, and a byte offset past the end is refused instead of read (assimp 5.2.5
// reads it).
#pragma once

#include <cstddef>
#include <vector>

#include "io/GltfDocument.h"
#include "io/GltfJson.h"

namespace conescope {

// Per document buffer: whether a drawn primitive reads from it.
using GltfBufferUse = std::vector<bool>;

struct GltfMeshCheck {
    GltfMesh mesh;                     // the primitives that make triangles
    size_t pointOrLinePrimitives = 0;  // skipped: not faces
    size_t shortPrimitives = 0;        // skipped: fewer than 3 vertices
    size_t unfinishedTriangles = 0;    // triangle lists with 1 or 2 vertices left over
    bool morphTargets = false;         // a primitive has morph targets
    bool morphWeights = false;         // the mesh's default weights are not all 0
};

// Checks meshes[mesh] and every accessor and buffer view its triangle primitives read, marking the
// buffers they use. Throws MeshReadError.
GltfMeshCheck checkGltfMesh(const GltfJson& gltf, size_t mesh, GltfBufferUse& buffers);

// Checks that every used buffer's data exists and is long enough; fills scene.bufferFileNames and
// scene.bufferBytes.
// Throws MeshReadError.
void checkGltfBuffers(const GltfJson& gltf, const GltfBufferUse& buffers, GltfScene& scene);

// True when object's "weights" (morph target weights) holds a number other than 0.
bool hasNonZeroWeights(const nlohmann::json& object);

}  // namespace conescope
