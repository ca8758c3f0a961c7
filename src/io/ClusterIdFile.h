// Cluster id files, the file builder's input besides a mesh's own cluster_id array: core reads no
// file, so every front end reads the settings' cluster file here before it builds clusters.
#pragma once

#include <string>
#include <vector>

#include "core/Settings.h"

namespace conescope {

// One id per face, whitespace separated; '#' starts a comment. Throws std::runtime_error starting
// with the path (and the line of a word that is not a number).
std::vector<double> readClusterIdFile(const std::string& path);

// The settings with settings.clusterIds read from settings.clusterFile when the file builder uses
// one that is not a meshlet file (else unchanged: readClusterFileOf, ClusterFiles.h, reads those). A file that cannot be read keeps the reader's message, which buildPartition
// throws where it would have read the file.
Settings withClusterIds(Settings settings);

}  // namespace conescope
