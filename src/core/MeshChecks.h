// Mesh problems that make culling wrong: a face wound against its neighbours points its normal
// inwards, so its cluster's cone is wrong for it. These checks find them; fixWinding repairs what
// can be repaired.
#pragma once

#include <cstddef>

#include "Mesh.h"

namespace conescope {

struct MeshReport {
    size_t openEdges = 0;            // edges with one face
    size_t nonManifoldEdges = 0;     // edges with three or more faces
    size_t inconsistentEdges = 0;    // edges whose two faces run them in the same direction
    size_t duplicateFaces = 0;       // faces with the same vertex set as an earlier face
    size_t degenerateFaces = 0;
    size_t components = 0;           // edge-connected pieces
    bool orientable = true;          // winding can be made consistent on every component
};

MeshReport checkMesh(const Mesh& mesh, const FaceGeometry& faces);

// Flips faces so neighbours across manifold edges agree; in each component the winding most faces
// already have wins. Returns how many faces were flipped. Non-orientable components are left with
// the fewest conflicts a breadth-first walk finds.
size_t fixWinding(Mesh& mesh);

}  // namespace conescope
