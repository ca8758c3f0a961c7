#include "ClusterBounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ChosenCones.h"
#include "Parallel.h"
#include "meshopt/Meshopt.h"

namespace conescope {

glm::dvec3 coneApex(const ConeOfNormals& cone, const glm::dvec3& center, const Mesh& mesh,
                    const std::vector<glm::vec3>& world, const FaceGeometry& faces, const uint32_t* clusterFaces,
                    size_t faceCount, bool forwardToo) {
    if (!cone.cullable) return center;
    // Move back along -axis until the point is on the back side of every face plane: then any eye
    // that sees the apex from inside the back cone sees every face's back (meshoptimizer's argument).
    double farthest = forwardToo ? -std::numeric_limits<double>::infinity() : 0.0;
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
    if (!std::isfinite(farthest)) return center;  // no face with a side: nothing to be behind
    return center - cone.axis * (farthest + std::abs(farthest) * 1e-12 + 1e-300);
}

ConeOfNormals coneByMethod(ConeMethod method, const std::vector<glm::dvec3>& normals) {
    switch (method) {
        case ConeMethod::Average: return averageCone(normals.data(), normals.size());
        case ConeMethod::SeedSphere: return seedSphereCone(normals.data(), normals.size());
        case ConeMethod::Minimal:
        case ConeMethod::Meshopt:
        case ConeMethod::Chosen: return minimalCone(normals.data(), normals.size());
    }
    return {};
}

namespace {

// The chosen cone: the other four, each with its apex on the line its method places it on
// (meshoptimizer's through its own apex, the others through the cluster's sphere) but as far
// forward as the face planes allow, the minimal cone first.
ChosenCone chooseAmongOffered(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                              const uint32_t* clusterFaces, size_t faceCount, const std::vector<glm::dvec3>& normals,
                              const glm::dvec3& center, const ChoiceEyes& eyes) {
    std::vector<OfferedCone> offered;
    for (const ConeMethod method : {ConeMethod::Minimal, ConeMethod::Meshopt, ConeMethod::Average, ConeMethod::SeedSphere}) {
        if (method == ConeMethod::Meshopt) {
            const MeshoptClusterBounds meshopt = meshoptClusterBounds(mesh, world, clusterFaces, faceCount, normals);
            if (meshopt.usable)
                offered.push_back({method, meshopt.cone, coneApex(meshopt.cone, meshopt.apex, mesh, world, faces, clusterFaces, faceCount, true)});
            continue;
        }
        const ConeOfNormals cone = coneByMethod(method, normals);
        offered.push_back({method, cone, coneApex(cone, center, mesh, world, faces, clusterFaces, faceCount, true)});
    }
    return chooseCone(offered.data(), offered.size(), normals, eyes);
}

}  // namespace

ConeOfNormals clusterCone(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                          const uint32_t* clusterFaces, size_t faceCount, ConeMethod method, SphereMethod sphereMethod) {
    if (method == ConeMethod::Chosen) {  // its apex, from the sphere, takes part in the choice
        ClusterFaces one;
        one.starts = {0, uint32_t(faceCount)};
        one.faces.assign(clusterFaces, clusterFaces + faceCount);
        return boundsOfClusters(mesh, world, faces, std::move(one), method, sphereMethod).cones.front();
    }
    std::vector<glm::dvec3> normals;
    for (size_t i = 0; i < faceCount; ++i) normals.push_back(faces.normals[clusterFaces[i]]);
    if (method == ConeMethod::Meshopt) return meshoptClusterBounds(mesh, world, clusterFaces, faceCount, normals).cone;
    return coneByMethod(method, normals);
}

ClusterBounds boundsOfClusters(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                               ClusterFaces clusterRows, ConeMethod coneMethod, SphereMethod sphereMethod, const Aabb* objectBox) {
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
    const ChoiceEyes eyes = coneMethod == ConeMethod::Chosen && clusterCount > 0 ? choiceEyes(objectBox ? *objectBox : computeAabb(world))
                                                                                : ChoiceEyes{};
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
            const MeshoptClusterBounds meshopt = meshoptClusterBounds(mesh, world, clusterFaces, faceCount, normals);
            bounds.cones[c] = meshopt.cone;  // not cullable unless meshoptimizer gave a cone
            if (meshopt.usable) {
                bounds.spheres[c] = sphereAround(meshopt.center, points.data(), points.size());
                bounds.apexes[c] = coneApex(meshopt.cone, meshopt.apex, mesh, world, faces, clusterFaces, faceCount);
            } else {
                bounds.apexes[c] = bounds.spheres[c].center;
            }
        } else if (coneMethod == ConeMethod::Chosen) {
            const ChosenCone chosen = chooseAmongOffered(mesh, world, faces, clusterFaces, faceCount, normals, bounds.spheres[c].center, eyes);
            bounds.cones[c] = chosen.cone;
            bounds.apexes[c] = chosen.apex;
            bounds.octagons[c] = chosen.octagon;
            bounds.normalsShares[c] = normalsCullShare(normals.data(), normals.size(), &chosen.cone);
            continue;
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
    bounds.records = makeEngineRecords();  // records are made for whole bounds only
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
    // The chosen cone's eyes are around the whole object: its box found once, not per piece.
    const Aabb objectBox = coneMethod == ConeMethod::Chosen ? computeAabb(world) : Aabb{};
    std::vector<ClusterBounds> pieceBounds(pieces);
    forEachInParallel(pieces, [&](size_t piece, size_t) {
        const size_t begin = pieceBegin(clusterCount, pieces, piece), end = pieceBegin(clusterCount, pieces, piece + 1);
        ClusterFaces rows;
        rows.starts.assign(1, 0);
        for (size_t c = begin; c < end; ++c) rows.starts.push_back(all.starts[c + 1] - all.starts[begin]);
        rows.faces.assign(all.faces.begin() + all.starts[begin], all.faces.begin() + all.starts[end]);
        pieceBounds[piece] = boundsOfClusters(mesh, world, faces, std::move(rows), coneMethod, sphereMethod, &objectBox);
    });
    ClusterBounds bounds;
    bounds.coneMethod = coneMethod;
    bounds.sphereMethod = sphereMethod;
    for (ClusterBounds& piece : pieceBounds) appendClusterBounds(bounds, std::move(piece));
    if (pieces == 0) bounds.faces.starts.assign(1, 0), bounds.vertexStarts.assign(1, 0);
    return bounds;
}

}  // namespace conescope
