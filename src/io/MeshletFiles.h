// meshoptimizer's meshlet arrays in files: JSON and a little-endian binary form of the same content,
// both holding meshopt_buildMeshlets's three arrays exactly as it fills them and, optionally, one
// meshopt_Bounds per meshlet. The layouts (JSON keys; binary header, arrays, padding, bounds) are
// in docs/user/engine-meshlets.md; the binary's size must be exactly its header's.
#pragma once

#include <stdexcept>
#include <string>

#include "core/MeshletArrays.h"
#include "core/lod/HierarchyRecords.h"

namespace conescope {

// Thrown for a file that is not a well-formed meshlet file; what() starts with the path and says
// where (the JSON member, or the byte offset) and what is wrong.
class MeshletFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Whether the file is meant as a meshlet file rather than a text of cluster ids: it starts as a JSON
// object or with the binary magic, holds bytes no text holds, or is named *.meshlets.
bool isMeshletFile(const std::string& path);

// Reads either form, told apart by the first bytes (a JSON object, else the binary form, whose
// magic a file without it is refused for, naming what it should be). Checks the structure only (types, counts, sizes);
// applyMeshlets (core/MeshletArrays.h) checks the arrays against a mesh. Throws MeshletFileError.
MeshletArrays readMeshletFile(const std::string& path);
MeshletArrays parseMeshletJson(const std::string& text, const std::string& sourceName);
MeshletArrays parseMeshletBinary(const std::string& bytes, const std::string& sourceName);

// The arrays as JSON text (bounds when the arrays hold them) and as the binary form.
std::string meshletJson(const MeshletArrays& arrays);
std::string meshletBinary(const MeshletArrays& arrays);

// A cluster LOD hierarchy's records as JSON: {"format": "conescope-cluster-lod", "version": 1, the
// meshlet arrays of every level as above, "clusters": [{"level", "group", "refined", "center",
// "radius", "error"}], "groups": [{"level", "center", "radius", "error"}]}. Reading checks the
// structure (types, ranges); hierarchyFromRecords checks the rest. Throws MeshletFileError.
// The binary form holds the same records, little-endian: a 32-byte header ('CLUSTLOD', version 1,
// flags 0, the cluster, meshlet_vertices, triangle-byte and group counts), the three arrays, zero
// bytes to a multiple of 8, then 56 bytes per cluster and 48 per group; its size must be exactly
// what the header promises. readHierarchyFile tells the two apart by the first bytes.
HierarchyRecords readHierarchyFile(const std::string& path);
HierarchyRecords parseHierarchyJson(const std::string& text, const std::string& sourceName);
HierarchyRecords parseHierarchyBinary(const std::string& bytes, const std::string& sourceName);
std::string hierarchyJson(const HierarchyRecords& records);
std::string hierarchyBinary(const HierarchyRecords& records);

// Whether a hierarchy written to `path` takes the binary form: a name ending in .lod or .bin.
bool isHierarchyBinaryPath(const std::string& path);

}  // namespace conescope
