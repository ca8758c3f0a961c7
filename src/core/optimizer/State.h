// The clustering the optimized builder works on (ClusterOptimizer.h) and the small operations all
// of its steps share: which cluster holds a face, the clusters' vertex and triangle counts kept
// up to date as faces move, their caps of normals, and whether a cluster stays in one piece.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/Adjacency.h"
#include "core/ExpectedCull.h"
#include "core/Mesh.h"
#include "core/Partition.h"
#include "core/SphericalCaps.h"

namespace conescope::optimizer {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

struct Cluster {
    std::vector<uint32_t> faces;  // in no order; slotOf finds a face's place
    uint32_t vertices = 0;
    uint32_t triangles = 0;
    Cap cap;
    // Above the limits: the size a meshlet of meshoptimizer's had once whole polygons filled it,
    // which it may keep (shedOverLimits); 0 below them.
    uint32_t keptVertices = 0, keptTriangles = 0;
};

struct State {
    State(const Mesh& mesh, const FaceGeometry& geometry, const MeshletLimits& limits);

    const Mesh& mesh;
    const FaceGeometry& geometry;
    MeshletLimits limits;
    size_t faceCount;
    Rows aroundVertex, acrossEdge;
    std::vector<uint32_t> clusterOf, slotOf;  // per face: its cluster (kNone: none yet), its place there
    std::vector<uint32_t> faceTriangles;      // per face: triangles of its fan
    std::vector<uint8_t> usable;              // per face: has a normal (degenerate faces do not)
    std::vector<Cluster> clusters;            // emptied clusters stay, without faces
    size_t liveClusters = 0;

    // Scratch, reused to keep the inner loops free of allocations. A stamp is fresh after
    // ++stamp, so marking a face or vertex needs no clearing.
    std::vector<uint32_t> faceStamp, vertexStamp, faceMark;
    uint32_t stamp = 0;
    // Per face: the ring walk's stamp (its own, so callers' marks survive) and place in the ring.
    std::vector<uint32_t> ringStamp;
    std::vector<uint8_t> ringSlot;
    uint32_t ringStampNow = 0;
    std::vector<glm::dvec3> gathered;  // normals for a cap (gatherNormals)
    std::vector<uint32_t> walk, queue, members, neighbours, pool, bestPool, bestHalf;
    struct Moved {
        uint32_t face, from, slot;  // the cluster it came from and its place there
    };
    std::vector<Moved> undo;
    struct Corner {
        uint32_t users = 0;  // faces of a cluster using a corner: 0, 1 or 2 (two or more)
        uint32_t soleUser = kNone;
    };
    std::vector<Corner> corners;
};

// The objective's share of one cluster.
inline double valueOf(double triangles, const Cap& cap) { return expectedCulledTriangles(triangles, sinOf(cap)); }

// --- membership ------------------------------------------------------------------------------

// Corner k of a face repeats an earlier corner: counted once among the face's vertices.
inline bool repeatsEarlierVertex(const Mesh& mesh, uint32_t face, size_t k) {
    const uint32_t* vertices = mesh.faceBegin(face);
    for (size_t j = 0; j < k; ++j)
        if (vertices[j] == vertices[k]) return true;
    return false;
}

// Some face of the cluster other than exceptFace uses the vertex.
inline bool clusterUsesVertex(const State& state, uint32_t cluster, uint32_t vertex, uint32_t exceptFace = kNone) {
    for (const uint32_t* g = state.aroundVertex.begin(vertex); g != state.aroundVertex.end(vertex); ++g)
        if (*g != exceptFace && state.clusterOf[*g] == cluster) return true;
    return false;
}

// Vertices of `face` the cluster does not use yet.
inline uint32_t newVertices(const State& state, uint32_t face, uint32_t cluster) {
    uint32_t added = 0;
    for (size_t k = 0; k < state.mesh.faceSize(face); ++k)
        added += !repeatsEarlierVertex(state.mesh, face, k) && !clusterUsesVertex(state, cluster, state.mesh.faceBegin(face)[k]);
    return added;
}

// Vertices only `face` uses in its cluster.
inline uint32_t ownVertices(const State& state, uint32_t face) {
    uint32_t own = 0;
    for (size_t k = 0; k < state.mesh.faceSize(face); ++k)
        own += !repeatsEarlierVertex(state.mesh, face, k) &&
               !clusterUsesVertex(state, state.clusterOf[face], state.mesh.faceBegin(face)[k], face);
    return own;
}

// Whether `face` can join `cluster` within both limits.
inline bool fits(const State& state, uint32_t face, uint32_t cluster) {
    const Cluster& target = state.clusters[cluster];
    return target.triangles + state.faceTriangles[face] <= std::max<size_t>(state.limits.maxTriangles, target.keptTriangles) &&
           target.vertices + newVertices(state, face, cluster) <= std::max<size_t>(state.limits.maxVertices, target.keptVertices);
}

// A face of no cluster joins one, keeping its counts (not its cap) up to date.
void attach(State& state, uint32_t face, uint32_t cluster);
// Moves a face to another cluster, keeping both clusters' counts (not their caps) up to date.
void move(State& state, uint32_t face, uint32_t to);
// The same, recorded in state.undo so that undoMoves can put every face back in its place.
void moveRecorded(State& state, uint32_t face, uint32_t to);
// Undoes the moves in state.undo, last first, leaving each cluster's faces in their order before.
void undoMoves(State& state);
// Different clusters across the edges of `face`, at most 8.
inline size_t neighbourClusters(const State& state, uint32_t face, uint32_t* out) {
    size_t count = 0;
    const uint32_t own = state.clusterOf[face];
    for (const uint32_t* g = state.acrossEdge.begin(face); g != state.acrossEdge.end(face); ++g) {
        const uint32_t c = state.clusterOf[*g];
        if (c != own && c != kNone && count < 8 && std::find(out, out + count, c) == out + count) out[count++] = c;
    }
    return count;
}
// Different clusters bordering `cluster`, sorted: at most `limit`, the first found.
void clustersAround(const State& state, uint32_t cluster, size_t limit, std::vector<uint32_t>& out);

// --- caps ------------------------------------------------------------------------------------

// The cluster's normals but exceptFace's into state.gathered (its data() is valid only after
// this call); returns how many.
size_t gatherNormals(State& state, uint32_t cluster, uint32_t exceptFace);
// The exact minimal cap of a cluster's normals.
Cap exactCap(State& state, uint32_t cluster);
// The cap once `face` joins `cluster`.
Cap capAdding(State& state, uint32_t cluster, uint32_t face);
// Whether removing `face` can change its cluster's cap (its normal bounds the cap).
bool bindsCap(const State& state, uint32_t face);
// The cap once `face` leaves its cluster.
Cap capRemoving(State& state, uint32_t face);

// --- connectivity ----------------------------------------------------------------------------

// True when the cluster of `face` stays edge-connected without it.
bool staysConnectedWithout(State& state, uint32_t face);

// --- the whole ---------------------------------------------------------------------------------

// No clusters: every face unassigned again.
void clear(State& state);
// The clusters of `partition` (covering every face), with their counts and exact caps.
void assign(State& state, const Partition& partition);
// The clusters as a partition, numbered in order of first use.
Partition result(const State& state);

}  // namespace conescope::optimizer
