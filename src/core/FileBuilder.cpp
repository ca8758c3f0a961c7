#include "FileBuilder.h"

#include <stdexcept>

namespace conescope {

const FileClusters* meshletClusters(const Mesh& mesh, const std::string& clusterFile) {
    const auto file = mesh.fileClusters.find(clusterFile);
    return file == mesh.fileClusters.end() ? nullptr : &file->second;
}

Partition ownClusters(const Mesh& mesh) {
    for (const char* name : {"cluster_id", "group_id"}) {
        const auto ids = mesh.faceArrays.find(name);
        if (ids != mesh.faceArrays.end()) return partitionFromIds(ids->second, mesh.faceCount(), std::string(name) + " array");
    }
    throw std::runtime_error(
        "the file builder needs a cluster file, a per-face 'cluster_id' array in the mesh, or groups in it (OBJ g/o groups, glTF primitives)");
}

bool meshHasOwnClusters(const Mesh& mesh) { return mesh.faceArrays.count("cluster_id") || mesh.faceArrays.count("group_id"); }

const std::vector<MeshletBounds>* storedMeshletBounds(const Mesh& mesh, const std::string& clusterFile) {
    const FileClusters* file = meshletClusters(mesh, clusterFile);
    return file && !file->bounds.empty() ? &file->bounds : nullptr;
}

}  // namespace conescope
