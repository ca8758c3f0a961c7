// Partitions in files of their own, read onto the mesh they partition and written from it.
//
// Read (the file builder's --cluster-file): meshoptimizer's meshlet arrays, JSON or binary
// (MeshletFiles.h), told apart from id files by content. Each triangle is matched to a face by its
// corners after the readers' vertex merge; cluster m is meshlet m. The partition is put on the mesh
// (Mesh::fileClusters, under the path as given), where the file builder finds it, because a meshlet
// file that splits a polygon cuts it into the meshlets' triangles. Text files of one id per face
// change no face: ClusterIdFile.h reads those into the settings.
// A mesh's own groups need no cluster file: OBJ g/o groups and glTF primitives are the per-face
// "group_id" array, and a "cluster_id" array comes with VTP, VTK and PLY files.
//
// Written (partition -o), by extension: .json and .meshlets (meshlet arrays with meshoptimizer's
// bounds, vertex ids of the mesh file as read), .obj (an `o` object per cluster), .gltf (a primitive
// per cluster), .txt (ids), and .vtp, .vtk, .ply, .off through writePolyData with a cluster_id array.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/Mesh.h"
#include "core/Partition.h"
#include "core/Settings.h"

namespace conescope {

// what() starts with the cluster file's path, then says what is wrong (for a meshlet file, which
// meshlet and which fault).
class ClusterFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads the meshlet file `path` and puts its partition on `mesh` (Mesh::fileClusters[path]);
// `notes` hears of cut polygons. The mesh is unchanged when it throws ClusterFileError.
void readClusterFile(Mesh& mesh, const std::string& path, std::vector<std::string>& notes);

// The cluster file of the file builder in `settings`, when it is a meshlet file not read yet.
void readClusterFileOf(Mesh& mesh, const Settings& settings, std::vector<std::string>& notes);

// Lower-case extensions writePartitionFile writes beside writePolyData's: {".json", ".meshlets", ".obj", ".gltf", ".txt"}.
std::vector<std::string> partitionFileExtensions();

// Writes the partition of `mesh` by the extension of `path` (above). Throws MeshWriteError.
void writePartitionFile(const Mesh& mesh, const Partition& partition, const std::string& path);

// The first vertex of the file at each of the mesh's vertices: what a meshlet or hierarchy file
// written for the mesh file indexes.
std::vector<uint32_t> firstFileVertices(const Mesh& mesh);

}  // namespace conescope
