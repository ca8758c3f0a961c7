// glTF 2.0 (.gltf) and binary glTF (.glb) files as one world-space Mesh (internal to conescope_io).
//
// The default scene's node tree is walked by ConeScope (GltfDocument.h), assimp decodes the data of
// the primitives drawn (GltfDecoding.h), and every instance of a mesh is placed here with its node's
// world matrix: positions in world space, Mesh::model the identity. A node whose world matrix has a
// negative determinant mirrors its mesh; glTF then counts clockwise triangles as front faces, so their
// corner order is reversed to keep every face's outward normal under ConeScope's counter-clockwise
// convention. Vertices at exactly equal world positions are merged (glTF splits them at UV and
// normal seams, and non-indexed primitives share none), so components and clusters span whole
// surfaces. Each placed primitive (a primitive of each instance) is a group: the per-face array
// "group_id", a cluster per primitive for the file builder.
#pragma once

#include <string>
#include <vector>

#include "core/Mesh.h"
#include "core/Progress.h"

namespace conescope {

// Throws MeshReadError ("path: what"), or OperationCancelled when `progress` returns false.
// Parts that are not triangles (points, lines) are skipped and counted in `notes`.
Mesh readGltf(const std::string& path, std::vector<std::string>& notes, const ProgressCallback& progress);

}  // namespace conescope
