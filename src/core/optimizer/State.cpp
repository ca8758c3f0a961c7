#include "State.h"

#include <algorithm>

namespace conescope::optimizer {

State::State(const Mesh& mesh, const FaceGeometry& geometry, const MeshletLimits& limits)
    : mesh(mesh), geometry(geometry), limits(limits), faceCount(mesh.faceCount()) {
    aroundVertex = facesAroundVertices(mesh);
    acrossEdge = facesAcrossEdges(mesh);
    clusterOf.assign(faceCount, kNone);
    slotOf.assign(faceCount, 0);
    faceStamp.assign(faceCount, 0);
    faceMark.assign(faceCount, 0);
    ringStamp.assign(faceCount, 0);
    ringSlot.assign(faceCount, 0);
    vertexStamp.assign(mesh.positions.size(), 0);
    faceTriangles.resize(faceCount);
    usable.resize(faceCount);
    for (size_t f = 0; f < faceCount; ++f) {
        faceTriangles[f] = uint32_t(mesh.faceSize(f) - 2);
        usable[f] = !geometry.degenerate[f];
    }
}

// ---------------------------------------------------------------------------------------------
// Membership.

void attach(State& state, uint32_t face, uint32_t cluster) {
    Cluster& target = state.clusters[cluster];
    target.vertices += newVertices(state, face, cluster);
    target.triangles += state.faceTriangles[face];
    state.clusterOf[face] = cluster;
    state.slotOf[face] = uint32_t(target.faces.size());
    target.faces.push_back(face);
}

namespace {

// The last face of the cluster takes the leaving face's slot: O(1) whatever the cluster's size.
void detach(State& state, uint32_t face) {
    Cluster& source = state.clusters[state.clusterOf[face]];
    source.vertices -= ownVertices(state, face);
    source.triangles -= state.faceTriangles[face];
    const uint32_t slot = state.slotOf[face];
    source.faces[slot] = source.faces.back();
    state.slotOf[source.faces[slot]] = slot;
    source.faces.pop_back();
    state.clusterOf[face] = kNone;
}

}  // namespace

void move(State& state, uint32_t face, uint32_t to) {
    detach(state, face);
    attach(state, face, to);
}

void moveRecorded(State& state, uint32_t face, uint32_t to) {
    state.undo.push_back({face, state.clusterOf[face], state.slotOf[face]});
    move(state, face, to);
}

void undoMoves(State& state) {
    for (size_t i = state.undo.size(); i-- > 0;) {
        const State::Moved& moved = state.undo[i];
        Cluster& holder = state.clusters[state.clusterOf[moved.face]];
        if (holder.faces.back() != moved.face) {  // not last in (cannot happen when undone last first): a plain move
            move(state, moved.face, moved.from);
            continue;
        }
        // attach and detach backwards: off the end of its holder, into its old place in `from`.
        holder.vertices -= ownVertices(state, moved.face);
        holder.triangles -= state.faceTriangles[moved.face];
        holder.faces.pop_back();
        Cluster& source = state.clusters[moved.from];
        source.vertices += newVertices(state, moved.face, moved.from);
        source.triangles += state.faceTriangles[moved.face];
        if (moved.slot < source.faces.size()) {
            const uint32_t displaced = source.faces[moved.slot];
            state.slotOf[displaced] = uint32_t(source.faces.size());
            source.faces.push_back(displaced);
            source.faces[moved.slot] = moved.face;
        } else {
            source.faces.push_back(moved.face);
        }
        state.slotOf[moved.face] = moved.slot;
        state.clusterOf[moved.face] = moved.from;
    }
    state.undo.clear();
}

void clustersAround(const State& state, uint32_t cluster, size_t limit, std::vector<uint32_t>& out) {
    out.clear();
    for (uint32_t f : state.clusters[cluster].faces) {
        uint32_t around[8];
        const size_t count = neighbourClusters(state, f, around);
        for (size_t i = 0; i < count; ++i)
            if (out.size() < limit && std::find(out.begin(), out.end(), around[i]) == out.end()) out.push_back(around[i]);
    }
    std::sort(out.begin(), out.end());
}

// ---------------------------------------------------------------------------------------------
// Caps.

size_t gatherNormals(State& state, uint32_t cluster, uint32_t exceptFace) {
    state.gathered.clear();
    for (uint32_t f : state.clusters[cluster].faces)
        if (f != exceptFace && state.usable[f]) state.gathered.push_back(state.geometry.normals[f]);
    return state.gathered.size();
}

Cap exactCap(State& state, uint32_t cluster) {
    const size_t count = gatherNormals(state, cluster, kNone);
    return count == 0 ? Cap{} : minimalCapFromSubset(state.gathered.data(), count, capThrough(state.gathered[0]));
}

Cap capAdding(State& state, uint32_t cluster, uint32_t face) {
    const Cap& current = state.clusters[cluster].cap;
    const glm::dvec3& normal = state.geometry.normals[face];
    if (!state.usable[face] || contains(current, normal)) return current;
    if (current.cosRadius > 1.0) return capThrough(normal);
    if (!(current.cosRadius > 0.0)) return current;  // already no cone
    const size_t count = gatherNormals(state, cluster, kNone);
    const Cap grown = minimalCapFromSubset(state.gathered.data(), count, supportCapAdding(current, normal));
    return grown.cosRadius <= 1.0 && grown.cosRadius > 0.0 && contains(grown, normal) ? grown : noCone(grown.axis);
}

bool bindsCap(const State& state, uint32_t face) {
    const Cap& current = state.clusters[state.clusterOf[face]].cap;
    return state.usable[face] &&
           !(current.cosRadius > 0.0 && glm::dot(state.geometry.normals[face], current.axis) > current.cosRadius + 1e-9);
}

Cap capRemoving(State& state, uint32_t face) {
    const uint32_t cluster = state.clusterOf[face];
    if (!bindsCap(state, face)) return state.clusters[cluster].cap;
    const size_t count = gatherNormals(state, cluster, face);
    if (count == 0) return Cap{};
    const Cap& current = state.clusters[cluster].cap;
    const glm::dvec3& removed = state.geometry.normals[face];
    bool supportLeft = false;
    for (uint32_t i = 0; i < current.supportCount; ++i) supportLeft |= current.support[i] != removed;
    return minimalCapFromSubset(state.gathered.data(), count, supportLeft ? supportCapRemoving(current, removed) : capThrough(state.gathered[0]));
}

// ---------------------------------------------------------------------------------------------
// Connectivity.

namespace {

constexpr size_t kRingSize = 48;

// Usually the cluster's faces around the corners of `face` already join its edge neighbours: a
// walk over that ring (at most kRingSize faces, on the stack) answers without the whole cluster.
// True when it reaches all neighboursInCluster from `first`; false when it does not or the ring
// is too large to tell. Each ring face is stamped with its place in the ring, so the walk finds it
// at once: searching the ring (linearly, then by bisection) took a quarter of the run on props of
// many faces per edge (docs/benchmarks.md).
bool ringJoinsNeighbours(State& state, uint32_t face, uint32_t first, uint32_t neighboursInCluster) {
    const uint32_t cluster = state.clusterOf[face];
    if (++state.ringStampNow == 0) std::fill(state.ringStamp.begin(), state.ringStamp.end(), 0), state.ringStampNow = 1;
    const uint32_t inRing = state.ringStampNow;
    uint32_t ringFace[kRingSize];
    size_t ringCount = 0;
    for (size_t k = 0; k < state.mesh.faceSize(face); ++k) {
        const uint32_t v = state.mesh.faceBegin(face)[k];
        for (const uint32_t* g = state.aroundVertex.begin(v); g != state.aroundVertex.end(v); ++g)
            if (*g != face && state.clusterOf[*g] == cluster && state.ringStamp[*g] != inRing) {
                if (ringCount + 1 == kRingSize) return false;
                state.ringStamp[*g] = inRing;
                state.ringSlot[*g] = uint8_t(ringCount);
                ringFace[ringCount++] = *g;
            }
    }
    auto indexOf = [&](uint32_t g) { return state.ringStamp[g] == inRing ? size_t(state.ringSlot[g]) : ringCount; };
    bool reachedRing[kRingSize] = {}, edgeNeighbour[kRingSize] = {};
    for (const uint32_t* h = state.acrossEdge.begin(face); h != state.acrossEdge.end(face); ++h)
        if (state.clusterOf[*h] == cluster && indexOf(*h) < ringCount) edgeNeighbour[indexOf(*h)] = true;
    size_t stack[kRingSize], top = 0, reachedNeighbours = 1;
    const size_t start = indexOf(first);
    reachedRing[start] = true;
    stack[top++] = start;
    while (top > 0) {
        const uint32_t f = ringFace[stack[--top]];
        for (const uint32_t* g = state.acrossEdge.begin(f); g != state.acrossEdge.end(f); ++g) {
            if (state.clusterOf[*g] != cluster) continue;
            const size_t i = indexOf(*g);
            if (i == ringCount || reachedRing[i]) continue;
            reachedRing[i] = true;
            stack[top++] = i;
            reachedNeighbours += edgeNeighbour[i];
        }
    }
    return reachedNeighbours == neighboursInCluster;
}

}  // namespace

bool staysConnectedWithout(State& state, uint32_t face) {
    const uint32_t cluster = state.clusterOf[face];
    uint32_t first = kNone, neighboursInCluster = 0;
    for (const uint32_t* g = state.acrossEdge.begin(face); g != state.acrossEdge.end(face); ++g)
        if (state.clusterOf[*g] == cluster) {
            ++neighboursInCluster;
            if (first == kNone) first = *g;
        }
    if (neighboursInCluster <= 1) return true;
    if (ringJoinsNeighbours(state, face, first, neighboursInCluster)) return true;
    // Walk the cluster from one neighbour without crossing `face`; every face must be reached.
    ++state.stamp;
    state.faceStamp[face] = state.stamp;
    state.faceStamp[first] = state.stamp;
    state.walk.assign(1, first);
    size_t reached = 1;
    while (!state.walk.empty()) {
        const uint32_t f = state.walk.back();
        state.walk.pop_back();
        for (const uint32_t* g = state.acrossEdge.begin(f); g != state.acrossEdge.end(f); ++g)
            if (state.clusterOf[*g] == cluster && state.faceStamp[*g] != state.stamp) {
                state.faceStamp[*g] = state.stamp;
                state.walk.push_back(*g);
                ++reached;
            }
    }
    return reached + 1 == state.clusters[cluster].faces.size();
}

// ---------------------------------------------------------------------------------------------
// The whole.

void clear(State& state) {
    state.clusters.clear();
    std::fill(state.clusterOf.begin(), state.clusterOf.end(), kNone);
    state.liveClusters = 0;
}

void assign(State& state, const Partition& partition) {
    clear(state);
    state.clusters.resize(partition.clusterCount);
    for (uint32_t f = 0; f < state.faceCount; ++f) {
        Cluster& target = state.clusters[partition.clusterOfFace[f]];
        target.triangles += state.faceTriangles[f];
        state.clusterOf[f] = partition.clusterOfFace[f];
        state.slotOf[f] = uint32_t(target.faces.size());
        target.faces.push_back(f);
    }
    // Vertices counted cluster by cluster with one stamp each, rather than face by face around corners.
    for (uint32_t c = 0; c < state.clusters.size(); ++c) {
        Cluster& cluster = state.clusters[c];
        if (cluster.faces.empty()) continue;
        ++state.stamp;
        for (uint32_t f : cluster.faces)
            for (size_t k = 0; k < state.mesh.faceSize(f); ++k) {
                uint32_t& stamp = state.vertexStamp[state.mesh.faceBegin(f)[k]];
                cluster.vertices += stamp != state.stamp;
                stamp = state.stamp;
            }
        cluster.cap = exactCap(state, c);
        ++state.liveClusters;
    }
}

Partition result(const State& state) {
    std::vector<uint32_t> renumber(state.clusters.size(), kNone);
    Partition partition;
    partition.clusterOfFace.resize(state.faceCount);
    for (size_t f = 0; f < state.faceCount; ++f) {
        uint32_t& id = renumber[state.clusterOf[f]];
        if (id == kNone) id = partition.clusterCount++;
        partition.clusterOfFace[f] = id;
    }
    return partition;
}

}  // namespace conescope::optimizer
