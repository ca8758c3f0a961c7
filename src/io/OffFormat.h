// The OFF format (Geomview; what CGAL reads and writes), parsed by hand because VTK 9.1 has no
// OFF reader. Accepted:
//   [ST][C][N][4][n]OFF header keyword (counts may follow on the same line),
//   '#' comments anywhere, blank lines, CRLF line ends, a UTF-8 byte order mark,
//   a counts line "vertices faces [edges]",
//   one vertex per line: x y z (x y z w for 4OFF), anything after that on the line (normals,
//   colours, texture coordinates) is ignored,
//   one face per line: n i_1 .. i_n, anything after that on the line (a colour) is ignored.
// Not accepted: "OFF BINARY", nOFF with a dimension other than 3.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/Mesh.h"

namespace conescope {

// Parses OFF text held in memory. sourceName only labels messages ("sourceName:line: what").
// Throws MeshReadError on any malformed, truncated or inconsistent input, and on zero faces.
// Counts in the header are never trusted for allocation: a forged count cannot reserve more
// than the text could possibly hold. Does not run validateMesh (readMesh does). `exactKeys`, when
// given, gets each position as read before rounding to float (PositionMerging.h).
Mesh parseOff(std::string_view text, const std::string& sourceName, std::vector<uint64_t>* exactKeys = nullptr);

// Reads a whole file and parses it with parseOff. Throws MeshReadError.
Mesh readOff(const std::string& path, std::vector<uint64_t>* exactKeys = nullptr);

}  // namespace conescope
