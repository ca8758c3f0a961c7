// assimp's part of reading a glTF (internal to conescope_io): the binary data of the primitives the
// scene draws. assimp loads the buffers (files, base64 data URIs, the .glb BIN chunk), decodes the
// accessors (strides, sparse accessors, Draco) and expands triangle strips and fans in the glTF
// order; it is given a reduced document (GltfDecoding.cpp says which) so that its output maps
// one-to-one onto the checked primitives, and every decoded primitive is checked against the counts
// the document promises.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/Progress.h"
#include "io/GltfDocument.h"

struct aiMesh;
namespace Assimp {
class Importer;
}

namespace conescope {

struct GltfDecoded {
    // primitives[m][p]: GltfScene::meshes[m].primitives[p] as triangles, with exactly the document's
    // vertex count and triangle count (GltfPrimitive::vertexCount, triangleCount).
    std::vector<std::vector<const aiMesh*>> primitives;
    std::shared_ptr<Assimp::Importer> importer;  // owns the decoded data
};

// Reports progress in [0, 1] by bytes read; stops with OperationCancelled when `progress` returns
// false. Throws MeshReadError.
GltfDecoded decodeGltfPrimitives(const std::string& path, const GltfScene& scene, const ProgressCallback& progress);

}  // namespace conescope
