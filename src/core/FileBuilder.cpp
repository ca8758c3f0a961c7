#include "FileBuilder.h"

#include <stdexcept>

namespace conescope {

Partition filePartition(const Mesh& mesh, const std::string& clusterFile) {
    if (!clusterFile.empty()) {
        const auto file = mesh.fileClusters.find(clusterFile);
        if (file == mesh.fileClusters.end())
            throw std::runtime_error(clusterFile + ": this cluster file was not read with the mesh (io's readClusterFile reads it)");
        return {file->second.clusterOfFace, file->second.clusterCount};
    }
    for (const char* name : {"cluster_id", "group_id"}) {
        const auto ids = mesh.faceArrays.find(name);
        if (ids != mesh.faceArrays.end()) return partitionFromIds(ids->second, mesh.faceCount(), std::string(name) + " array");
    }
    throw std::runtime_error(
        "the file builder needs a cluster file, a per-face 'cluster_id' array in the mesh, or groups in it (OBJ g/o groups, glTF primitives)");
}

const std::vector<MeshletBounds>* storedMeshletBounds(const Mesh& mesh, const std::string& clusterFile) {
    const auto file = mesh.fileClusters.find(clusterFile);
    return file == mesh.fileClusters.end() || file->second.bounds.empty() ? nullptr : &file->second.bounds;
}

bool meshHasOwnClusters(const Mesh& mesh) { return mesh.faceArrays.count("cluster_id") || mesh.faceArrays.count("group_id"); }

}  // namespace conescope
