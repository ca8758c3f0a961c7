// Mesh problems that make culling wrong: a face wound against its neighbours points its normal
// inwards, so its cluster's cone is wrong for it. These checks find them; fixWinding repairs what
// can be repaired.
#pragma once

#include <cstddef>
#include <string>

#include "Mesh.h"

namespace conescope {

struct MeshReport {
    size_t openEdges = 0;            // edges with one face
    size_t nonManifoldEdges = 0;     // edges with three or more faces
    size_t inconsistentEdges = 0;    // edges whose two faces run them in the same direction
    size_t duplicateFaces = 0;       // faces with the same vertex set as an earlier face
    size_t doubleSidedFaces = 0;     // of those, faces wound against such a face: back to back with it
    size_t degenerateFaces = 0;
    size_t components = 0;           // edge-connected pieces
    bool orientable = true;          // winding can be made consistent on every component
    size_t insideOutComponents = 0;  // closed, consistently wound components enclosing negative volume
};

MeshReport checkMesh(const Mesh& mesh, const FaceGeometry& faces);

// Flips faces so neighbours across manifold edges agree; in each component the winding most faces
// already have wins. Then every closed component that encloses negative volume (inside out: its
// normals point in) is turned over whole. Returns how many faces were flipped. Non-orientable
// components are left with the fewest conflicts a breadth-first walk finds.
size_t fixWinding(Mesh& mesh);

// True when fixWinding would change something the report found.
bool windingNeedsFixing(const MeshReport& report);

// One sentence for the user when the mesh has double-sided geometry (a face and the same face wound
// the other way), naming the count: from any eye one of each pair faces it, so back-face culling can
// remove neither, nor any cluster holding both; empty when there is none.
std::string doubleSidedWarning(const MeshReport& report);

// One sentence for the user when the report finds what makes culling wrong (inconsistent winding,
// inside-out components), naming the counts; empty when there is none. Callers add how to repair.
std::string windingWarning(const MeshReport& report);

}  // namespace conescope
