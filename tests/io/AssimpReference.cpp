#include "AssimpReference.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace conescope::testing {

namespace {

// Triangles under `node`, its own meshes and every child's, so a mesh used by two nodes counts twice.
size_t trianglesUnder(const aiScene& scene, const aiNode& node) {
    size_t triangles = 0;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f)
            if (mesh.mFaces[f].mNumIndices == 3) ++triangles;
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) triangles += trianglesUnder(scene, *node.mChildren[i]);
    return triangles;
}

}  // namespace

std::optional<size_t> assimpTriangleCount(const std::string& path, std::string* error) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        if (error) *error = importer.GetErrorString();
        return std::nullopt;
    }
    return trianglesUnder(*scene, *scene->mRootNode);
}

}  // namespace conescope::testing
