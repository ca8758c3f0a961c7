// What the file builder takes from the mesh: a meshlet file's partition read with it (io's
// ClusterFiles.h puts it in Mesh::fileClusters, since a meshlet file may cut the mesh's polygons),
// or the mesh's own clusters: its cluster_id array, else its groups (OBJ g/o, glTF primitives).
// Id files are read into the settings instead (io/ClusterIdFile.h; BuildPartition.h joins them).
#pragma once

#include <string>
#include <vector>

#include "Mesh.h"
#include "Partition.h"

namespace conescope {

// The partition a meshlet file `clusterFile` gave the mesh, numbered as the file numbers it (meshlet
// m is cluster m); null when none was read with it.
const FileClusters* meshletClusters(const Mesh& mesh, const std::string& clusterFile);

// The mesh's cluster_id array, else its group_id array, renumbered in order of first use. Throws
// std::runtime_error saying what is missing when it has neither.
Partition ownClusters(const Mesh& mesh);

// Whether the mesh gives the file builder clusters without a cluster file.
bool meshHasOwnClusters(const Mesh& mesh);

// The bounds of this meshlet file (meshopt_Bounds per cluster: stored, or computed on its own
// meshlets when it stored none), or null.
const std::vector<MeshletBounds>* storedMeshletBounds(const Mesh& mesh, const std::string& clusterFile);

}  // namespace conescope
