// Merging vertices at equal positions, for formats that repeat a corner per face or split vertices at
// attribute seams (internal to conescope_io).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Mesh.h"

namespace conescope {

// A reader of positions wider than float (text, float64 or integer fields, Python's float64 arrays)
// keeps one key per vertex of the position as read, beside the mesh's float positions: a hash of
// the three doubles (-0 as +0), equal exactly when the positions are (but for a 2^-64 chance). It is
// what tells positions equal in the file from positions that only rounding to float made equal.
uint64_t exactPositionKey(const glm::dvec3& position);
void addExactPosition(std::vector<uint64_t>* keys, const glm::dvec3& position);  // nothing when null

struct MergedPositions {
    size_t merged = 0;         // vertices merged into an earlier one (0: the mesh is unchanged)
    size_t lostPositions = 0;  // distinct positions of the file among them, lost to rounding to float
};

// Replaces vertices at exactly equal positions (equal floats, -0 equal to +0) by one, numbered in
// the order first seen, and renumbers faceVertices. Every face is kept: one whose corners merge
// stays a face with a repeated vertex, so computeFaceGeometry and checkMesh count it as degenerate.
// Clusters never cross components, so a format whose faces share no vertex indices (STL, glTF
// seams and non-indexed primitives) must be merged before clustering. Mesh::fileVertices then says
// where each vertex as read went. `exactKeys`, when the reader kept them (one per vertex), count
// the positions that differed before rounding.
MergedPositions mergeEqualPositions(Mesh& mesh, const std::vector<uint64_t>& exactKeys = {});

// What a user must hear when rounding lost positions (lostPositions > 0): how many, and why, with
// the float step at the mesh's largest coordinate (`vertices`: the count before the merge).
std::string lostPositionsWarning(const Mesh& merged, size_t vertices, const MergedPositions& merge);

}  // namespace conescope
