// The file builder: the partition the mesh's files give it. Reads nothing itself: a cluster file is
// read with the mesh (io's ClusterFiles.h puts it in Mesh::fileClusters), so the partition and the
// faces it partitions come from the same read, polygons cut where meshlets split them.
#pragma once

#include <string>

#include "Mesh.h"
#include "Partition.h"

namespace conescope {

// With a cluster file: its partition, numbered as the file numbers it (meshlet m is cluster m).
// Without: the mesh's per-face cluster_id array, else its groups (group_id: OBJ g/o groups, glTF
// primitives), renumbered in order of first use. Throws std::runtime_error saying what is missing.
Partition filePartition(const Mesh& mesh, const std::string& clusterFile);

// The bounds a meshlet file stored for this cluster file (meshopt_Bounds per cluster), or null.
const std::vector<MeshletBounds>* storedMeshletBounds(const Mesh& mesh, const std::string& clusterFile);

// Whether the mesh gives the file builder clusters without a cluster file.
bool meshHasOwnClusters(const Mesh& mesh);

}  // namespace conescope
