// Merging vertices at equal positions, for formats that repeat a corner per face or split vertices at
// attribute seams (internal to conescope_io).
#pragma once

#include <cstddef>

#include "core/Mesh.h"

namespace conescope {

// Replaces vertices at exactly equal positions (equal floats, -0 equal to +0) by one, numbered in
// the order first seen, and renumbers faceVertices. Every face is kept: one whose corners merge
// stays a face with a repeated vertex, so computeFaceGeometry and checkMesh count it as degenerate.
// Clusters never cross components, so a format whose faces share no vertex indices (STL, glTF
// seams and non-indexed primitives) must be merged before clustering. Mesh::fileVertices then says
// where each vertex as read went. Returns how many vertices were merged into an earlier one (0: the
// mesh is unchanged).
size_t mergeEqualPositions(Mesh& mesh);

}  // namespace conescope
