// Parts: a mesh is cut into parts that are optimised independently, at once on several cores, each
// part's data in cache: at median face centroids here, or along meshoptimizer's meshlets as they
// come (core/MeshletStream.h). No cluster crosses a cut.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Mesh.h"
#include "core/Partition.h"

namespace conescope::optimizer {

// Faces of each part in one array: part i is faces[starts[i], starts[i + 1]), in mesh order.
struct Parts {
    std::vector<uint32_t> faces, starts;
    size_t count() const { return starts.size() - 1; }
    size_t size(size_t i) const { return starts[i + 1] - starts[i]; }
    const uint32_t* begin(size_t i) const { return faces.data() + starts[i]; }
};

// Larger meshes are cut into parts of at most this many faces: one run of growth and annealing on
// this many takes about a second.
constexpr size_t kLargestPart = size_t(1) << 17;

// Halves of halves until the parts have about maxPartFaces faces at most (the number of halvings
// follows from the face count alone), as long as each part still gets a few clusters of the
// `target` budget. One part (the whole mesh) when it is small enough.
Parts splitIntoParts(const FaceGeometry& faces, size_t target, size_t maxPartFaces = kLargestPart);

// Each part's share of the `target` budget, by its triangles (at least 1 each); the shares add up
// to the budget.
std::vector<size_t> partTargets(const Mesh& mesh, const Parts& parts, size_t target);
// The same by the clusters each part holds: at most those, exactly those when `target` is their sum.
std::vector<size_t> partTargets(const std::vector<size_t>& clustersHeld, size_t target);

// Some faces of a mesh as a mesh of their own, vertices renumbered in order of first use (which
// also keeps a part's data close together in memory).
struct MeshPart {
    Mesh mesh;
    FaceGeometry faces;
};
// newIndex: one kNone per mesh vertex, left so again, reused from part to part.
MeshPart extractPart(const Mesh& mesh, const FaceGeometry& faces, const uint32_t* faceIds, size_t faceCount,
                     std::vector<uint32_t>& newIndex);

// The parts' partitions as one partition of the mesh: part i's clusters numbered after part i - 1's.
Partition joinParts(const Parts& parts, const std::vector<Partition>& results);

}  // namespace conescope::optimizer
