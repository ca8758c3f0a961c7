#include "io/ClusterFiles.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>

#include "core/MeshletArrays.h"
#include "core/meshopt/Meshopt.h"
#include "io/FileChecks.h"
#include "io/MeshWriter.h"
#include "io/MeshletFiles.h"
#include "io/PartitionGltf.h"

namespace conescope {

namespace {

// The partition as meshlet arrays with meshoptimizer's bounds, indexing the file's vertices.
MeshletArrays meshletsToWrite(const Mesh& mesh, const Partition& partition, const std::string& path) {
    MeshletArrays arrays;
    try {
        arrays = meshletsOfPartition(mesh, partition);
    } catch (const std::invalid_argument& error) {
        throw MeshWriteError(path + ": " + error.what());
    }
    arrays.bounds = meshoptBoundsOfMeshlets(arrays, mesh.positions);
    const std::vector<uint32_t> first = firstFileVertices(mesh);
    for (uint32_t& vertex : arrays.vertices) vertex = first[vertex];
    return arrays;
}

// The mesh's vertices, then an `o` object per cluster holding its faces (meshoptimizer's demo dumps
// meshlets the same way); positions in model space, as OFF is written.
std::string objGroups(const Mesh& mesh, const Partition& partition) {
    std::string text = "# written by ConeScope: an object (o) per cluster, read back with --builder file\n";
    for (const glm::vec3& p : mesh.positions) {
        text += "v ";
        appendPointLine(text, p);
    }
    const ClusterFaces rows = facesByCluster(partition);
    for (uint32_t c = 0; c < partition.clusterCount; ++c) {
        text += "o cluster_" + std::to_string(c) + "\n";
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            text += 'f';
            for (size_t k = 0; k < mesh.faceSize(rows.faces[i]); ++k) text += ' ' + std::to_string(mesh.faceBegin(rows.faces[i])[k] + 1);
            text += '\n';
        }
    }
    return text;
}

std::string idText(const Partition& partition) {
    std::string text = "# a cluster id per face, in face order (ConeScope)\n";
    for (uint32_t id : partition.clusterOfFace) text += std::to_string(id) + '\n';
    return text;
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw MeshWriteError(path + ": cannot open for writing (" + std::strerror(errno) + ")");
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out) throw MeshWriteError(path + ": write failed (disk full?)");
}

}  // namespace

std::vector<uint32_t> firstFileVertices(const Mesh& mesh) {
    std::vector<uint32_t> first(mesh.positions.size());
    for (uint32_t v = 0; v < first.size(); ++v) first[v] = v;
    if (mesh.fileVertices.empty()) return first;
    std::vector<uint8_t> seen(first.size(), 0);
    for (uint32_t fileVertex = 0; fileVertex < mesh.fileVertices.size(); ++fileVertex) {
        const uint32_t v = mesh.fileVertices[fileVertex];
        if (!seen[v]) seen[v] = 1, first[v] = fileVertex;
    }
    return first;
}

void readClusterFile(Mesh& mesh, const std::string& path, std::vector<std::string>& notes) {
    try {
        const MeshletArrays arrays = readMeshletFile(path);
        if (!arrays.bounds.empty() && mesh.model != glm::dmat4(1.0))
            throw ClusterFileError(path + ": its bounds are in the mesh file's space, and the mesh has a model matrix: "
                                          "write the mesh without one");
        Mesh applied = mesh;
        AppliedMeshlets meshlets = applyMeshlets(applied, arrays);
        // Without stored bounds, the engine's: meshoptimizer's of the file's own meshlets.
        if (meshlets.clusters.bounds.empty()) meshlets.clusters.bounds = meshoptBoundsOfFileMeshlets(arrays, applied);
        applied.fileClusters[path] = std::move(meshlets.clusters);
        mesh = std::move(applied);
        if (meshlets.cutPolygons > 0)
            notes.push_back(std::to_string(meshlets.cutPolygons) + " polygon" + (meshlets.cutPolygons == 1 ? " was" : "s were") +
                            " cut into the triangles " + path + " splits between meshlets");
    } catch (const ClusterFileError&) {
        throw;
    } catch (const MeshletError& error) {
        throw ClusterFileError(path + ": " + error.what());
    } catch (const std::exception& error) {
        // The readers' own errors start with the path already.
        const std::string what = error.what();
        throw ClusterFileError(what.rfind(path, 0) == 0 ? what : path + ": " + what);
    }
}

void readClusterFileOf(Mesh& mesh, const Settings& settings, std::vector<std::string>& notes) {
    if (settings.builder != Builder::File || settings.clusterFile.empty() || mesh.fileClusters.count(settings.clusterFile)) return;
    if (!isMeshletFile(settings.clusterFile)) return;  // ids per face: withClusterIds (ClusterIdFile.h) reads those
    readClusterFile(mesh, settings.clusterFile, notes);
}

std::vector<std::string> partitionFileExtensions() { return {".json", ".meshlets", ".obj", ".gltf", ".txt"}; }

void writePartitionFile(const Mesh& mesh, const Partition& partition, const std::string& path) {
    const std::string extension = lowerCaseExtension(path);
    if (extension == ".json") return writeBytes(path, meshletJson(meshletsToWrite(mesh, partition, path)));
    if (extension == ".meshlets") return writeBytes(path, meshletBinary(meshletsToWrite(mesh, partition, path)));
    if (extension == ".obj") return writeBytes(path, objGroups(mesh, partition));
    if (extension == ".gltf") return writeBytes(path, partitionGltf(mesh, partition));
    if (extension == ".txt") return writeBytes(path, idText(partition));
    const std::vector<std::string> meshes = writableMeshExtensions();
    if (std::find(meshes.begin(), meshes.end(), extension) == meshes.end())
        throw MeshWriteError(path + ": cannot write a partition as " + quotedForMessage(extension) +
                             "; supported: .json .meshlets .obj .gltf .txt .vtp .vtk .ply .off");
    const std::vector<double> ids(partition.clusterOfFace.begin(), partition.clusterOfFace.end());
    writePolyData(mesh, path, {{"cluster_id", ids}});
}

}  // namespace conescope
