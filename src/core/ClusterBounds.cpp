#include "ClusterBounds.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "Parallel.h"

namespace conescope {

glm::dvec3 coneApex(const ConeOfNormals& cone, const glm::dvec3& center, const Mesh& mesh,
                    const std::vector<glm::vec3>& world, const FaceGeometry& faces, const uint32_t* clusterFaces,
                    size_t faceCount) {
    if (!cone.cullable) return center;
    // Move back along -axis until the point is on the back side of every face plane: then any eye
    // that sees the apex from inside the back cone sees every face's back (meshoptimizer's argument).
    double farthest = 0.0;
    for (size_t i = 0; i < faceCount; ++i) {
        const uint32_t f = clusterFaces[i];
        const glm::dvec3& n = faces.normals[f];
        const double along = glm::dot(n, cone.axis);
        if (faces.degenerate[f] || !(along > 0.0)) continue;
        for (size_t k = 0; k < mesh.faceSize(f); ++k) {
            const glm::dvec3 q(world[mesh.faceBegin(f)[k]]);
            farthest = std::max(farthest, glm::dot(n, center - q) / along);
        }
    }
    return center - cone.axis * (farthest * (1.0 + 1e-12) + 1e-300);
}

namespace {

ConeOfNormals coneByMethod(ConeMethod method, const std::vector<glm::dvec3>& normals) {
    switch (method) {
        case ConeMethod::Average: return averageCone(normals.data(), normals.size());
        case ConeMethod::SeedSphere: return seedSphereCone(normals.data(), normals.size());
        case ConeMethod::Minimal:
        case ConeMethod::Meshopt: return minimalCone(normals.data(), normals.size());
    }
    return {};
}

// meshoptimizer's bounds for one cluster (fan triangles). Its float cone is widened to the exact
// cone around the same axis when rounding made it too narrow, and its apex is pushed behind any
// face plane it is in front of, so the tests built on it stay conservative.
struct MeshoptCluster {
    ConeOfNormals cone;
    glm::dvec3 center{0.0};
    glm::dvec3 apex{0.0};
    bool usable = false;
};

MeshoptCluster meshoptBounds(const Mesh& mesh, const std::vector<glm::vec3>& world, const uint32_t* clusterFaces,
                             size_t faceCount, const std::vector<glm::dvec3>& normals) {
    std::vector<uint32_t> indices;
    for (size_t i = 0; i < faceCount; ++i) {
        const uint32_t* face = mesh.faceBegin(clusterFaces[i]);
        for (size_t k = 1; k + 1 < mesh.faceSize(clusterFaces[i]); ++k)
            indices.insert(indices.end(), {face[0], face[k], face[k + 1]});
    }
    MeshoptCluster result;
    if (indices.empty() || indices.size() / 3 > 512) return result;  // meshoptimizer's own limit
    // meshoptimizer squares coordinates in float: at 1e19 and beyond that overflows to a NaN normal
    // and trips its internal assertion (found by fuzzing). It gets the cluster's own vertices moved
    // to their box centre and scaled by a power of two to unit size instead; centre and apex are
    // mapped back. Normals and the cone do not change under this similarity.
    std::vector<uint32_t> local(indices);
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    glm::dvec3 low(world[local.front()]), high(low);
    for (uint32_t v : local) low = glm::min(low, glm::dvec3(world[v])), high = glm::max(high, glm::dvec3(world[v]));
    const glm::dvec3 middle = 0.5 * (low + high);
    const double extent = std::max({high.x - low.x, high.y - low.y, high.z - low.z});
    int exponent = 0;
    if (extent > 0.0) std::frexp(extent, &exponent);
    const double scale = std::ldexp(1.0, -exponent);
    std::vector<glm::vec3> scaled(local.size());
    for (size_t i = 0; i < local.size(); ++i) scaled[i] = glm::vec3((glm::dvec3(world[local[i]]) - middle) * scale);
    for (uint32_t& index : indices)
        index = uint32_t(std::lower_bound(local.begin(), local.end(), index) - local.begin());
    const meshopt_Bounds bounds =
        meshopt_computeClusterBounds(indices.data(), indices.size(), &scaled[0].x, scaled.size(), sizeof(glm::vec3));
    result.center = middle + glm::dvec3(bounds.center[0], bounds.center[1], bounds.center[2]) / scale;
    result.apex = middle + glm::dvec3(bounds.cone_apex[0], bounds.cone_apex[1], bounds.cone_apex[2]) / scale;
    if (bounds.cone_cutoff >= 1.0f) return result;  // meshoptimizer: wider than a hemisphere
    const glm::dvec3 axis(bounds.cone_axis[0], bounds.cone_axis[1], bounds.cone_axis[2]);
    ConeOfNormals cone = coneAroundAxis(axis, normals.data(), normals.size());
    if (!cone.cullable) return result;
    cone.sinHalfAngle = std::max(cone.sinHalfAngle, double(bounds.cone_cutoff));
    cone.cosHalfAngle = std::min(cone.cosHalfAngle, std::sqrt(std::max(0.0, 1.0 - cone.sinHalfAngle * cone.sinHalfAngle)));
    result.cone = cone;
    result.usable = true;
    return result;
}

}  // namespace

ConeOfNormals clusterCone(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                          const uint32_t* clusterFaces, size_t faceCount, ConeMethod method) {
    std::vector<glm::dvec3> normals;
    for (size_t i = 0; i < faceCount; ++i) normals.push_back(faces.normals[clusterFaces[i]]);
    if (method == ConeMethod::Meshopt) return meshoptBounds(mesh, world, clusterFaces, faceCount, normals).cone;
    return coneByMethod(method, normals);
}

ClusterBounds boundsOfClusters(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                               ClusterFaces clusterRows, ConeMethod coneMethod, SphereMethod sphereMethod) {
    ClusterBounds bounds;
    bounds.coneMethod = coneMethod;
    bounds.sphereMethod = sphereMethod;
    bounds.faces = std::move(clusterRows);
    const size_t clusterCount = bounds.faces.starts.size() - 1;
    bounds.vertexStarts.assign(clusterCount + 1, 0);
    bounds.triangles.assign(clusterCount, 0);
    bounds.cones.resize(clusterCount);
    bounds.boxes.resize(clusterCount);
    bounds.spheres.resize(clusterCount);
    bounds.apexes.resize(clusterCount);
    bounds.octagons.resize(clusterCount);
    bounds.normalsShares.resize(clusterCount);
    // Which vertices the cluster already listed: a mark per mesh vertex, kept by the thread from
    // call to call (a part's clusters are bounded in many small calls), a new mark per cluster.
    thread_local std::vector<uint32_t> seen;
    thread_local uint32_t mark = 0;
    if (seen.size() < world.size() || mark > std::numeric_limits<uint32_t>::max() - clusterCount - 1)
        seen.assign(world.size(), 0), mark = 0;
    std::vector<glm::dvec3> normals, points;
    for (uint32_t c = 0; c < clusterCount; ++c) {
        ++mark;
        const uint32_t* clusterFaces = bounds.faces.faces.data() + bounds.faces.starts[c];
        const size_t faceCount = bounds.faces.starts[c + 1] - bounds.faces.starts[c];
        normals.clear();
        points.clear();
        Aabb box;
        box.min = glm::vec3(std::numeric_limits<float>::max());
        box.max = glm::vec3(-std::numeric_limits<float>::max());
        for (size_t i = 0; i < faceCount; ++i) {
            const uint32_t f = clusterFaces[i];
            normals.push_back(faces.normals[f]);
            bounds.triangles[c] += uint32_t(mesh.faceSize(f) - 2);
            for (size_t k = 0; k < mesh.faceSize(f); ++k) {
                const uint32_t v = mesh.faceBegin(f)[k];
                if (seen[v] == mark) continue;
                seen[v] = mark;
                bounds.vertexIds.push_back(v);
                points.emplace_back(world[v]);
                box.min = glm::min(box.min, world[v]);
                box.max = glm::max(box.max, world[v]);
            }
        }
        bounds.vertexStarts[c + 1] = uint32_t(bounds.vertexIds.size());
        bounds.boxes[c] = box;
        bounds.spheres[c] = sphereMethod == SphereMethod::Minimal ? minimalSphere(points.data(), points.size())
                                                                  : ritterSphere(points.data(), points.size());
        if (coneMethod == ConeMethod::Meshopt) {
            const MeshoptCluster meshopt = meshoptBounds(mesh, world, clusterFaces, faceCount, normals);
            bounds.cones[c] = meshopt.cone;  // not cullable unless meshoptimizer gave a cone
            if (meshopt.usable) {
                bounds.spheres[c] = sphereAround(meshopt.center, points.data(), points.size());
                bounds.apexes[c] = coneApex(meshopt.cone, meshopt.apex, mesh, world, faces, clusterFaces, faceCount);
            } else {
                bounds.apexes[c] = bounds.spheres[c].center;
            }
        } else {
            bounds.cones[c] = coneByMethod(coneMethod, normals);
            bounds.apexes[c] = coneApex(bounds.cones[c], bounds.spheres[c].center, mesh, world, faces, clusterFaces, faceCount);
        }
        const OctagonAndShare octagon = octagonAndNormalsShare(bounds.cones[c], normals.data(), normals.size());
        bounds.octagons[c] = octagon.octagon;
        bounds.normalsShares[c] = octagon.normalsShare;
    }
    return bounds;
}

namespace {

template <typename T>
void append(std::vector<T>& to, std::vector<T>&& from) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

// Rows (starts with a leading 0) of `from` after those of `to`, their items too.
void appendRows(std::vector<uint32_t>& toStarts, std::vector<uint32_t>& toItems, const std::vector<uint32_t>& fromStarts,
                std::vector<uint32_t>&& fromItems) {
    const uint32_t offset = toStarts.back();
    for (size_t i = 1; i < fromStarts.size(); ++i) toStarts.push_back(offset + fromStarts[i]);
    append(toItems, std::move(fromItems));
}

}  // namespace

void appendClusterBounds(ClusterBounds& bounds, ClusterBounds&& more) {
    if (bounds.faces.starts.empty()) bounds.faces.starts.assign(1, 0);
    if (bounds.vertexStarts.empty()) bounds.vertexStarts.assign(1, 0);
    appendRows(bounds.faces.starts, bounds.faces.faces, more.faces.starts, std::move(more.faces.faces));
    appendRows(bounds.vertexStarts, bounds.vertexIds, more.vertexStarts, std::move(more.vertexIds));
    append(bounds.triangles, std::move(more.triangles));
    append(bounds.cones, std::move(more.cones));
    append(bounds.boxes, std::move(more.boxes));
    append(bounds.spheres, std::move(more.spheres));
    append(bounds.apexes, std::move(more.apexes));
    append(bounds.octagons, std::move(more.octagons));
    append(bounds.normalsShares, std::move(more.normalsShares));
    bounds.records = std::make_shared<EngineRecords>();  // records are made for whole bounds only
}

ClusterFaces clusterRowsOf(const uint32_t* faceIds, const Partition& partOfThem) {
    ClusterFaces rows = facesByCluster(partOfThem);
    for (uint32_t& face : rows.faces) face = faceIds[face];
    return rows;
}

ClusterBounds computeClusterBounds(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                   const Partition& partition, ConeMethod coneMethod, SphereMethod sphereMethod) {
    const ClusterFaces all = facesByCluster(partition);
    const size_t clusterCount = partition.clusterCount;
    // Clusters are bounded independently, in consecutive pieces on all cores, joined in order.
    const size_t pieces = piecesFor(clusterCount, 64);
    std::vector<ClusterBounds> pieceBounds(pieces);
    forEachInParallel(pieces, [&](size_t piece, size_t) {
        const size_t begin = pieceBegin(clusterCount, pieces, piece), end = pieceBegin(clusterCount, pieces, piece + 1);
        ClusterFaces rows;
        rows.starts.assign(1, 0);
        for (size_t c = begin; c < end; ++c) rows.starts.push_back(all.starts[c + 1] - all.starts[begin]);
        rows.faces.assign(all.faces.begin() + all.starts[begin], all.faces.begin() + all.starts[end]);
        pieceBounds[piece] = boundsOfClusters(mesh, world, faces, std::move(rows), coneMethod, sphereMethod);
    });
    ClusterBounds bounds;
    bounds.coneMethod = coneMethod;
    bounds.sphereMethod = sphereMethod;
    for (ClusterBounds& piece : pieceBounds) appendClusterBounds(bounds, std::move(piece));
    if (pieces == 0) bounds.faces.starts.assign(1, 0), bounds.vertexStarts.assign(1, 0);
    return bounds;
}

}  // namespace conescope
