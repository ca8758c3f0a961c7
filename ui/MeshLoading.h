// A mesh file to the pipeline's first stage: read (src/io), then prepared (core/Pipeline.h), with
// what the user should be told about it; and the file builder's cluster id files, read through io
// before clusters are built (withClusterIds).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/Pipeline.h"
#include "io/ClusterIdFile.h"

namespace conescope {

// Reads the file (readMeshFile, throws MeshReadError) with the file builder's cluster file (a
// cluster file that cannot be used leaves its error in the notes) and prepares it with
// settings.fixWinding; the reader's notes are kept. With `meshlets`, when the builder the mesh will be shown with
// (builderForMesh) starts from meshoptimizer's meshlets, those are started on another core before
// the mesh is prepared, for buildClusters.
PreparedMesh loadMesh(const std::string& path, const Settings& settings, const ProgressCallback& progress = {},
                      std::shared_ptr<MeshletStream>* meshlets = nullptr);

// Whether `settings` use a meshlet file the prepared mesh was not read with.
bool needsClusterFile(const PreparedMesh& prepared, const Settings& settings);

// The mesh prepared again for `settings`: the winding repair asked for, and a cluster file it was
// not read with read onto it. Throws ClusterFileError (io/ClusterFiles.h) for a file it cannot use.
PreparedMesh reprepareMesh(const PreparedMesh& prepared, const Settings& settings, const ProgressCallback& progress = {});

// What the user should know about a loaded mesh, in one line for the status bar: the reader's notes
// and the winding warning (with how to repair it, or what was repaired), as sentences. Empty when
// nothing.
std::string loadMessage(const PreparedMesh& prepared);

// Pieces of text as sentences on one line: each capitalised and ended with a full stop (unless it
// ends with one already, or ! or ?), separated by spaces; empty pieces left out.
std::string joinSentences(const std::vector<std::string>& pieces);

}  // namespace conescope
