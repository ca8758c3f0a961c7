// The builder dispatch: the partition the settings ask for, from the builder they name (the greedy
// and k-means builders of Partition.h, meshoptimizer's in meshopt/Meshopt.h, the optimized one in
// ClusterOptimizer.h, or ids given per face).
#pragma once

#include "ClusterOptimizer.h"
#include "Mesh.h"
#include "Partition.h"
#include "Progress.h"
#include "Settings.h"

namespace conescope {

// Builds the partition the settings ask for. The optimized builder reports its progress through
// `progress` (stage "clusters") and can be cancelled there; the others report nothing.
// `meshlets`: meshoptimizer's meshlets when startsFromMeshoptMeshlets(settings), if already started.
// `partDone`: the optimized builder's parts as they are made (ClusterOptimizer.h); the other
// builders do not call it. The file builder takes a meshlet file's partition read with the mesh
// (FileBuilder.h), the ids of settings.clusterFile as io read them into settings.clusterIds (core
// reads no file), or the mesh's cluster_id array, else its groups. `choice`: what the best effort
// chose between its two searches (ran = false for every other builder and effort).
Partition buildPartition(const Mesh& mesh, const FaceGeometry& faces, const Settings& settings,
                         const ProgressCallback& progress = {}, MeshletStream* meshlets = nullptr,
                         const PartClusters& partDone = {}, BestEffortChoice* choice = nullptr);

// Whether the settings' builder starts from meshoptimizer's meshlets at cone weight 1 (the optimized
// builder at its fast levels): those can be built before the face geometry.
bool startsFromMeshoptMeshlets(const Settings& settings);

}  // namespace conescope
