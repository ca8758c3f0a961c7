#include "ForCones.h"

#include <algorithm>
#include <string>

#include "core/Adjacency.h"
#include "core/MultiCones.h"
#include "core/Parallel.h"

namespace conescope {

namespace {

constexpr double kGainAtLeast = 1e-9;

uint32_t fanTriangles(const Mesh& mesh, uint32_t face) { return uint32_t(mesh.faceSize(face) - 2); }

// The normals of one sub-group of a split, with `extra` added and `except` left out.
std::vector<glm::dvec3>& groupNormals(const FaceGeometry& faces, const ConeGroupSplit& split, uint32_t group, uint32_t except,
                                      const glm::dvec3* extra, std::vector<glm::dvec3>& out) {
    out.clear();
    for (size_t i = 0; i < split.faces.size(); ++i)
        if (split.group[i] == group && split.faces[i] != except && !faces.degenerate[split.faces[i]]) out.push_back(faces.normals[split.faces[i]]);
    if (extra) out.push_back(*extra);
    return out;
}

bool holdsDegenerate(const FaceGeometry& faces, const ConeGroupSplit& split, uint32_t group) {
    for (size_t i = 0; i < split.faces.size(); ++i)
        if (split.group[i] == group && faces.degenerate[split.faces[i]]) return true;
    return false;
}

double groupValue(const ConeOfNormals& cone, size_t triangles) { return expectedCulledTriangles(cone, triangles); }

// What taking `face` out of its sub-group does to the split's value, the sub-groups kept as they are.
double leavingGain(const Mesh& mesh, const FaceGeometry& faces, const ConeGroupSplit& split, uint32_t face, std::vector<glm::dvec3>& scratch) {
    const size_t at = size_t(std::lower_bound(split.faces.begin(), split.faces.end(), face) - split.faces.begin());
    const uint32_t g = split.group[at];
    const ConeOfNormals& cone = split.cones[g];
    if (!cone.cullable) {
        if (holdsDegenerate(faces, split, g)) return 0.0;
        const std::vector<glm::dvec3>& rest = groupNormals(faces, split, g, face, nullptr, scratch);
        return rest.empty() ? 0.0 : groupValue(minimalCone(rest.data(), rest.size()), split.triangles[g] - fanTriangles(mesh, face));
    }
    const double before = groupValue(cone, split.triangles[g]);
    if (glm::dot(faces.normals[face], cone.axis) > cone.cosHalfAngle + 1e-6)  // inside: the cone stays
        return groupValue(cone, split.triangles[g] - fanTriangles(mesh, face)) - before;
    const std::vector<glm::dvec3>& rest = groupNormals(faces, split, g, face, nullptr, scratch);
    return (rest.empty() ? 0.0 : groupValue(minimalCone(rest.data(), rest.size()), split.triangles[g] - fanTriangles(mesh, face))) - before;
}

// The most adding `face` to one of the split's sub-groups gains, the sub-groups kept as they are.
double joiningGain(const Mesh& mesh, const FaceGeometry& faces, const ConeGroupSplit& split, uint32_t face, std::vector<glm::dvec3>& scratch) {
    const uint32_t t = fanTriangles(mesh, face);
    double best = -1e300;
    for (uint32_t g = 0; g < split.cones.size(); ++g) {
        if (holdsDegenerate(faces, split, g)) continue;  // never culls, with or without the face
        const ConeOfNormals& cone = split.cones[g];
        const double before = groupValue(cone, split.triangles[g]);
        if (cone.cullable && glm::dot(faces.normals[face], cone.axis) > cone.cosHalfAngle + 1e-6) {
            best = std::max(best, groupValue(cone, split.triangles[g] + t) - before);
            continue;
        }
        const std::vector<glm::dvec3>& with = groupNormals(faces, split, g, UINT32_MAX, &faces.normals[face], scratch);
        best = std::max(best, groupValue(minimalCone(with.data(), with.size()), split.triangles[g] + t) - before);
    }
    return best;
}

struct Clusters {
    std::vector<ConeGroupSplit> splits;
    std::vector<uint32_t> vertices, triangles;
};

// Whether some face of `cluster` other than `except` uses `vertex`.
bool usesVertex(const Rows& around, const std::vector<uint32_t>& clusterOf, uint32_t cluster, uint32_t vertex, uint32_t except) {
    for (const uint32_t* g = around.begin(vertex); g != around.end(vertex); ++g)
        if (*g != except && clusterOf[*g] == cluster) return true;
    return false;
}

// Distinct vertices of `face` that `cluster` uses (other than through `face`) or not.
uint32_t verticesOutside(const Mesh& mesh, const Rows& around, const std::vector<uint32_t>& clusterOf, uint32_t face, uint32_t cluster) {
    uint32_t count = 0;
    const uint32_t* v = mesh.faceBegin(face);
    for (size_t k = 0; k < mesh.faceSize(face); ++k)
        count += std::find(v, v + k, v[k]) == v + k && !usesVertex(around, clusterOf, cluster, v[k], face);
    return count;
}

// Whether the faces of `face`'s cluster stay edge-connected without it.
bool staysConnected(const Rows& across, const std::vector<uint32_t>& clusterOf, const ConeGroupSplit& split, uint32_t face,
                    std::vector<uint32_t>& queue, std::vector<uint8_t>& seen) {
    const uint32_t cluster = clusterOf[face];
    seen.assign(split.faces.size(), 0);
    auto slot = [&](uint32_t f) { return size_t(std::lower_bound(split.faces.begin(), split.faces.end(), f) - split.faces.begin()); };
    queue.clear();
    for (uint32_t f : split.faces)
        if (f != face) { queue.push_back(f), seen[slot(f)] = 1; break; }
    for (size_t i = 0; i < queue.size(); ++i)
        for (const uint32_t* g = across.begin(queue[i]); g != across.end(queue[i]); ++g)
            if (*g != face && clusterOf[*g] == cluster && !seen[slot(*g)]) seen[slot(*g)] = 1, queue.push_back(*g);
    return queue.size() + 1 == split.faces.size();
}

}  // namespace

ConeGroupSplit splitClusterForCones(const Mesh& mesh, const FaceGeometry& faces, std::vector<uint32_t> clusterFaces, uint32_t conesPerCluster) {
    ConeGroupSplit split;
    std::sort(clusterFaces.begin(), clusterFaces.end());
    split.faces = std::move(clusterFaces);
    std::vector<glm::dvec3> normals;
    std::vector<uint32_t> triangles;
    for (uint32_t f : split.faces)
        if (!faces.degenerate[f]) normals.push_back(faces.normals[f]), triangles.push_back(fanTriangles(mesh, f));
    std::vector<ConeOfNormals> cones;  // the split's own minimal cones: not made twice
    const std::vector<uint8_t> groupOfNormal =
        normals.empty() ? std::vector<uint8_t>{} : splitForCones(normals.data(), triangles.data(), normals.size(), conesPerCluster, &cones);
    split.group.assign(split.faces.size(), 0);
    for (size_t i = 0, n = 0; i < split.faces.size(); ++i)
        if (!faces.degenerate[split.faces[i]]) split.group[i] = groupOfNormal[n++];
    split.cones.assign(conesPerCluster, ConeOfNormals{});
    split.triangles.assign(conesPerCluster, 0);
    for (uint32_t g = 0; g < conesPerCluster; ++g) {
        for (size_t i = 0; i < split.faces.size(); ++i)
            if (split.group[i] == g) split.triangles[g] += fanTriangles(mesh, split.faces[i]);
        if (g < cones.size() && !holdsDegenerate(faces, split, g)) split.cones[g] = cones[g];
        split.value += groupValue(split.cones[g], split.triangles[g]);
    }
    return split;
}

size_t refineForCones(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, uint32_t conesPerCluster,
                      Partition& partition, int passes, double tryBelow, const ProgressCallback& progress) {
    std::vector<uint32_t>& clusterOf = partition.clusterOfFace;
    std::vector<std::vector<uint32_t>> members(partition.clusterCount);
    for (uint32_t f = 0; f < clusterOf.size(); ++f) members[clusterOf[f]].push_back(f);
    const Rows across = facesAcrossEdges(mesh), around = facesAroundVertices(mesh);
    Clusters clusters;
    clusters.vertices.assign(partition.clusterCount, 0);
    clusters.triangles.assign(partition.clusterCount, 0);
    clusters.splits.resize(partition.clusterCount);
    forEachInParallel(partition.clusterCount,
                      [&](size_t c, size_t) { clusters.splits[c] = splitClusterForCones(mesh, faces, members[c], conesPerCluster); });
    double total = 0.0;
    for (const ConeGroupSplit& split : clusters.splits) total += split.value;
    for (uint32_t f = 0; f < clusterOf.size(); ++f) {
        clusters.triangles[clusterOf[f]] += fanTriangles(mesh, f);
        const uint32_t* v = mesh.faceBegin(f);
        for (size_t k = 0; k < mesh.faceSize(f); ++k)  // counted by its first face in the cluster
            if (std::find(v, v + k, v[k]) == v + k) {
                bool earlier = false;
                for (const uint32_t* g = around.begin(v[k]); g != around.end(v[k]) && *g < f; ++g) earlier |= clusterOf[*g] == clusterOf[f];
                clusters.vertices[clusterOf[f]] += !earlier;
            }
    }
    std::vector<glm::dvec3> scratch;
    std::vector<uint32_t> queue;
    std::vector<uint8_t> seen;
    size_t moves = 0;
    for (int pass = 0; pass < passes; ++pass) {
        double passGain = 0.0;
        for (uint32_t f = 0; f < clusterOf.size(); ++f) {
            if (f % 4096 == 0)
                reportProgress(progress, (pass + double(f) / double(clusterOf.size())) / passes,
                               "clusters for " + std::to_string(conesPerCluster) + " cones");
            const uint32_t from = clusterOf[f];
            if (faces.degenerate[f] || clusters.splits[from].faces.size() < 2) continue;
            uint32_t best = UINT32_MAX;
            double bestGain = std::min(kGainAtLeast, -tryBelow), leaving = 0.0;
            bool leavingKnown = false;
            for (const uint32_t* g = across.begin(f); g != across.end(f); ++g) {
                const uint32_t to = clusterOf[*g];
                if (to == from || to == best) continue;
                if (clusters.triangles[to] + fanTriangles(mesh, f) > limits.maxTriangles ||
                    clusters.vertices[to] + verticesOutside(mesh, around, clusterOf, f, to) > limits.maxVertices)
                    continue;
                if (!leavingKnown) leaving = leavingGain(mesh, faces, clusters.splits[from], f, scratch), leavingKnown = true;
                const double gain = leaving + joiningGain(mesh, faces, clusters.splits[to], f, scratch);
                if (gain > bestGain) bestGain = gain, best = to;
            }
            if (best == UINT32_MAX) continue;
            // Weighed with the sub-groups as they are; made when both clusters split again still gain.
            std::vector<uint32_t> rest, with = clusters.splits[best].faces;
            for (uint32_t face : clusters.splits[from].faces)
                if (face != f) rest.push_back(face);
            with.push_back(f);
            ConeGroupSplit left = splitClusterForCones(mesh, faces, std::move(rest), conesPerCluster);
            ConeGroupSplit joined = splitClusterForCones(mesh, faces, std::move(with), conesPerCluster);
            const double gain = left.value + joined.value - clusters.splits[from].value - clusters.splits[best].value;
            if (!(gain > kGainAtLeast) || !staysConnected(across, clusterOf, clusters.splits[from], f, queue, seen)) continue;
            clusters.vertices[from] -= verticesOutside(mesh, around, clusterOf, f, from);
            clusters.vertices[best] += verticesOutside(mesh, around, clusterOf, f, best);
            clusters.triangles[from] -= fanTriangles(mesh, f);
            clusters.triangles[best] += fanTriangles(mesh, f);
            clusterOf[f] = best;
            clusters.splits[from] = std::move(left);
            clusters.splits[best] = std::move(joined);
            passGain += gain;
            ++moves;
        }
        total += passGain;
        if (passGain < 1e-4 * total) break;
    }
    return moves;
}

}  // namespace conescope
