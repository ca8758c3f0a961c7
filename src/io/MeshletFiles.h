// meshoptimizer's meshlet arrays in files: JSON and a little-endian binary form of the same content
// (README "Debugging your engine's meshlets"). Both hold meshopt_buildMeshlets's three arrays exactly
// as it fills them and, optionally, one meshopt_Bounds per meshlet.
//
// JSON: {"format": "meshoptimizer-meshlets",
//        "meshlets": [[vertex_offset, triangle_offset, vertex_count, triangle_count], ...],
//        "meshlet_vertices": [...], "meshlet_triangles": [...],
//        "bounds": [{"center": [x, y, z], "radius": r, "cone_apex": [...], "cone_axis": [...],
//                    "cone_cutoff": c, "cone_axis_s8": [i, j, k], "cone_cutoff_s8": n}, ...]}  (optional)
//
// Binary (.meshlets), every number little-endian:
//   offset 0   8 bytes  "MESHLETS"
//          8   u32      version, 1
//         12   u32      flags: bit 0 set when bounds follow
//         16   u32      meshlet count M
//         20   u32      meshlet_vertices count V
//         24   u32      meshlet_triangles byte count T
//         28   u32      0 (reserved)
//         32   M x 16   meshopt_Meshlet: vertex_offset, triangle_offset, vertex_count, triangle_count (u32 each)
//              V x 4    meshlet_vertices (u32)
//              T        meshlet_triangles (u8), then zero bytes to a multiple of 4
//              M x 48   with bit 0: meshopt_Bounds as the library lays it out: center (3 f32), radius (f32),
//                       cone_apex (3 f32), cone_axis (3 f32), cone_cutoff (f32), cone_axis_s8 (3 i8),
//                       cone_cutoff_s8 (i8)
// The file ends there; its size must be exactly that.
#pragma once

#include <stdexcept>
#include <string>

#include "core/MeshletArrays.h"

namespace conescope {

// Thrown for a file that is not a well-formed meshlet file; what() starts with the path and says
// where (the JSON member, or the byte offset) and what is wrong.
class MeshletFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Whether the file starts like a meshlet file (JSON object or the binary magic), by its content.
bool isMeshletFile(const std::string& path);

// Reads either form, told apart by the first bytes. Checks the structure only (types, counts, sizes);
// applyMeshlets (core/MeshletArrays.h) checks the arrays against a mesh. Throws MeshletFileError.
MeshletArrays readMeshletFile(const std::string& path);
MeshletArrays parseMeshletJson(const std::string& text, const std::string& sourceName);
MeshletArrays parseMeshletBinary(const std::string& bytes, const std::string& sourceName);

// The arrays as JSON text (bounds when the arrays hold them) and as the binary form.
std::string meshletJson(const MeshletArrays& arrays);
std::string meshletBinary(const MeshletArrays& arrays);

}  // namespace conescope
