// A mesh file to the pipeline's first stage: read (src/io), then prepared (core/Pipeline.h), with
// what the user should be told about it.
#pragma once

#include <string>

#include "core/Pipeline.h"

namespace conescope {

// Reads the file (readMeshFile, throws MeshReadError) and prepares it; the reader's notes are kept.
PreparedMesh loadMesh(const std::string& path, bool fixWinding, const ProgressCallback& progress = {});

// What the user should know about a loaded mesh, in one line for the status bar: the reader's notes
// and the winding warning (with how to repair it, or what was repaired). Empty when nothing.
std::string loadMessage(const PreparedMesh& prepared);

}  // namespace conescope
