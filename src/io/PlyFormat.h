// The PLY format (Turk's polygon file format), ASCII and binary of either byte order, parsed by hand
// in one pass that checks and reads at once. Read: the vertex element's x, y, z (the mesh's
// positions, as the file numbers them), the face element's vertex_indices (or vertex_index) list
// (polygons stay polygons) and a scalar face property cluster_id (into Mesh::faceArrays, for the
// file builder). Every other element and property is checked for shape and skipped.
// Header lines: ply; format; element; property; comment and obj_info anywhere. A line without a PLY
// keyword (Blender 2.4 writes "Created by Blender3D 247 - ..." after the format line) is read as a
// comment, with a note, where assimp 5.2.5 skips it too: after the format line and not among an
// element's property lines. Before the format line, or followed by more properties of the element
// above it (assimp would drop those properties), it is an error. A UTF-8 byte order mark is
// skipped; UTF-16 text is converted, with a note, when the format is ascii.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/Mesh.h"
#include "core/Progress.h"

namespace conescope {

// Throws MeshReadError ("path:line: what" for the header and ASCII data) on any malformed,
// truncated or inconsistent input: counts the data does not fill, data beyond the declared counts,
// indices of vertices the file does not have, coordinates that are not finite floats, a face of
// fewer than 3 vertices, no face element. Never allocates from a count in the header. What was
// read but is worth knowing goes to `notes`. Reports progress through `progress` (OperationCancelled
// when it says stop). Does not run validateMesh (readMesh does). `exactKeys`, when given, gets each
// position as read before rounding to float (PositionMerging.h).
Mesh readPly(const std::string& path, std::vector<std::string>& notes, const ProgressCallback& progress = {},
             std::vector<uint64_t>* exactKeys = nullptr);

}  // namespace conescope
