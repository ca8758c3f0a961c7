// The Wavefront OBJ format, parsed by hand in one pass. The mesh's vertices are the file's `v`
// entries (positions only), shared by the faces that index them, so a surface stays connected
// however many texture coordinates and normals its corners carry. Read:
//   v x y z [w | r g b]; f with corners v, v/vt, v//vn or v/vt/vn (also v/, v// and v/vt/: a
//   trailing slash names nothing), any number of corners (polygons stay polygons), negative
//   indices counting back from the elements defined so far, positive ones also referring forward;
//   '#' comments to the end of a line, blank lines, CRLF line ends.
// Accepted and ignored for geometry: vt, vn, vp, s, usemtl (also empty), mtllib and the other
// display statements. The g and o groups become the per-face array "group_id" when the file has any
// (a cluster per group for the file builder: meshoptimizer's demo dumps meshlets as `o` objects).
// Skipped with a note: l and p (lines and points are not faces), faces of one or two corners
// (`f a b`, an edge some exporters write among the faces) and statements with other keywords.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/Mesh.h"
#include "core/Progress.h"

namespace conescope {

// Parses OBJ text held in memory (ASCII or UTF-8 without a byte order mark). sourceName only labels
// messages ("sourceName:line: what"). What was skipped is described in `notes`, one sentence each.
// Throws MeshReadError on a malformed vertex or corner, an index of an element the file does not
// have, a face without corners, and no faces; OperationCancelled when `progress` says stop.
// Does not run validateMesh (readMesh does). `exactKeys`, when given, gets each position as read
// before rounding to float (PositionMerging.h).
Mesh parseObj(std::string_view text, const std::string& sourceName, std::vector<std::string>& notes,
              const ProgressCallback& progress = {}, std::vector<uint64_t>* exactKeys = nullptr);

// Reads a whole file and parses it with parseObj, after dropping a UTF-8 byte order mark or
// converting UTF-16 text (with a note naming the encoding). Throws MeshReadError.
Mesh readObj(const std::string& path, std::vector<std::string>& notes, const ProgressCallback& progress = {},
             std::vector<uint64_t>* exactKeys = nullptr);

}  // namespace conescope
