// Every call into meshoptimizer itself, and the one check of which version is linked. The only
// file of ConeScope that includes <meshoptimizer.h>.
#include "Meshopt.h"
#include "Reproduction.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <limits>

#include "core/Adjacency.h"
#include "core/Parallel.h"

namespace conescope {

int linkedMeshoptVersion() { return MESHOPTIMIZER_VERSION; }

bool reproducesLinkedMeshopt() { return linkedMeshoptVersion() == kReproducedMeshoptVersion; }

std::string meshoptFallbackNote() {
    if (reproducesLinkedMeshopt()) return {};
    return "meshoptimizer " + std::to_string(linkedMeshoptVersion()) + " is linked, and src/core/meshopt/ reproduces version " +
           std::to_string(kReproducedMeshoptVersion) + ": its builder runs the library instead of the reproduction";
}

namespace {

constexpr uint32_t kUnplaced = std::numeric_limits<uint32_t>::max();

// meshopt_buildMeshlets' output, sized by the library's own bound.
struct LibraryMeshlets {
    std::vector<meshopt_Meshlet> meshlets;
    std::vector<unsigned int> vertices;
    std::vector<unsigned char> triangles;
    size_t count = 0;
};

LibraryMeshlets libraryMeshlets(const Mesh& mesh, const std::vector<uint32_t>& indices, const MeshletLimits& limits, float coneWeight) {
    LibraryMeshlets out;
    const size_t maxMeshlets = meshopt_buildMeshletsBound(indices.size(), limits.maxVertices, limits.maxTriangles);
    out.meshlets.resize(maxMeshlets);
    out.vertices.resize(maxMeshlets * limits.maxVertices);
    out.triangles.resize(maxMeshlets * limits.maxTriangles * 3);
    out.count = meshopt_buildMeshlets(out.meshlets.data(), out.vertices.data(), out.triangles.data(), indices.data(), indices.size(),
                                      &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3), limits.maxVertices,
                                      limits.maxTriangles, coneWeight);
    return out;
}

}  // namespace

size_t meshoptLibraryMeshletCount(const Mesh& mesh, const MeshletLimits& limits, float coneWeight) {
    requireMeshoptLimits(limits);
    const std::vector<uint32_t> indices = fanTriangles(mesh);
    if (indices.empty()) return 0;
    if (indices.size() != 3 * mesh.faceCount()) return meshoptLibraryMeshlets(mesh, limits, coneWeight).clusterCount;
    return libraryMeshlets(mesh, indices, limits, coneWeight).count;
}

Partition meshoptLibraryMeshlets(const Mesh& mesh, const MeshletLimits& limits, float coneWeight) {
    requireMeshoptLimits(limits);
    // Fan triangulation; which face each triangle came from is found again below, among the faces
    // around its corners, which another core lists while meshoptimizer works.
    const std::vector<uint32_t> indices = fanTriangles(mesh);
    std::future<Rows> around = std::async(std::launch::async, [&mesh] { return facesAroundVertices(mesh); });
    const LibraryMeshlets built = libraryMeshlets(mesh, indices, limits, coneWeight);
    const size_t count = built.count;
    const Rows facesAround = around.get();
    // meshoptimizer reorders triangles inside meshlets, so each output triangle's face is found
    // again among the faces around its first corner: the face with a fan triangle of the same three
    // corners not yet matched (so duplicate faces each get one). A polygon goes with its first match.
    std::vector<uint32_t> firstTriangle(mesh.faceCount() + 1, 0), faceOfTriangle;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        firstTriangle[f + 1] = firstTriangle[f] + uint32_t(mesh.faceSize(f) >= 2 ? mesh.faceSize(f) - 2 : 0);
        faceOfTriangle.insert(faceOfTriangle.end(), firstTriangle[f + 1] - firstTriangle[f], uint32_t(f));
    }
    std::vector<uint8_t> matched(firstTriangle.back(), 0);
    // The first fan triangle with the corners of an output triangle, matched or not (kUnplaced: none).
    auto firstMatch = [&](const std::array<uint32_t, 3>& key, bool skipMatched) {
        for (const uint32_t* f = facesAround.begin(key[0]); f != facesAround.end(key[0]); ++f) {
            const uint32_t* face = mesh.faceBegin(*f);
            for (size_t k = 1; k + 1 < mesh.faceSize(*f); ++k) {
                const uint32_t triangle = firstTriangle[*f] + uint32_t(k - 1);
                if ((!skipMatched || !matched[triangle]) && sortedCorners(face[0], face[k], face[k + 1]) == key) return triangle;
            }
        }
        return kUnplaced;
    };
    auto keyOf = [&](const meshopt_Meshlet& meshlet, size_t t) {
        const unsigned char* local = &built.triangles[meshlet.triangle_offset + 3 * t];
        const uint32_t* vertices = &built.vertices[meshlet.vertex_offset];
        return sortedCorners(vertices[local[0]], vertices[local[1]], vertices[local[2]]);
    };
    // The search on all cores, meshlet by meshlet; then, in order, each output triangle takes its
    // match, or the next unmatched one when a duplicate face took it: the result is the one-pass
    // search's, whatever the number of cores.
    const std::vector<meshopt_Meshlet>& meshlets = built.meshlets;
    std::vector<uint32_t> outputStart(count + 1, 0);
    for (size_t m = 0; m < count; ++m) outputStart[m + 1] = outputStart[m] + meshlets[m].triangle_count;
    std::vector<uint32_t> candidate(outputStart.back());
    forRangesInParallel(count, 256, [&](size_t begin, size_t end) {
        for (size_t m = begin; m < end; ++m)
            for (size_t t = 0; t < meshlets[m].triangle_count; ++t) candidate[outputStart[m] + t] = firstMatch(keyOf(meshlets[m], t), false);
    });
    std::vector<uint32_t> clusterOfFace(mesh.faceCount(), kUnplaced);
    for (size_t m = 0; m < count; ++m)
        for (size_t t = 0; t < meshlets[m].triangle_count; ++t) {
            uint32_t triangle = candidate[outputStart[m] + t];
            if (triangle != kUnplaced && matched[triangle]) triangle = firstMatch(keyOf(meshlets[m], t), true);
            if (triangle == kUnplaced) continue;
            matched[triangle] = 1;
            uint32_t& cluster = clusterOfFace[faceOfTriangle[triangle]];
            if (cluster == kUnplaced) cluster = uint32_t(m);
        }
    return meshletsAsPartition(std::move(clusterOfFace));
}

MeshoptClusterBounds meshoptClusterBounds(const Mesh& mesh, const std::vector<glm::vec3>& world, const uint32_t* clusterFaces,
                                          size_t faceCount, const std::vector<glm::dvec3>& normals) {
    std::vector<uint32_t> indices;
    for (size_t i = 0; i < faceCount; ++i) {
        const uint32_t* face = mesh.faceBegin(clusterFaces[i]);
        for (size_t k = 1; k + 1 < mesh.faceSize(clusterFaces[i]); ++k)
            indices.insert(indices.end(), {face[0], face[k], face[k + 1]});
    }
    MeshoptClusterBounds result;
    if (indices.empty() || indices.size() / 3 > 512) return result;  // meshoptimizer's own limit
    // meshoptimizer squares coordinates in float: at 1e19 and beyond that overflows to a NaN normal
    // and trips its internal assertion (found by fuzzing). It gets the cluster's own vertices moved
    // to their box centre and scaled by a power of two to unit size instead; centre and apex are
    // mapped back. Normals and the cone do not change under this similarity.
    // The cluster's own vertices numbered as first met, through a map kept per thread: sorting them
    // cost more than meshoptimizer's bounds themselves (the chosen cone asks for every cluster).
    constexpr uint32_t kUnmet = std::numeric_limits<uint32_t>::max();
    thread_local std::vector<uint32_t> localOf;
    if (localOf.size() < world.size()) localOf.resize(world.size(), kUnmet);
    std::vector<uint32_t> local;
    for (uint32_t& index : indices) {
        if (localOf[index] == kUnmet) localOf[index] = uint32_t(local.size()), local.push_back(index);
        index = localOf[index];
    }
    for (uint32_t v : local) localOf[v] = kUnmet;
    glm::dvec3 low(world[local.front()]), high(low);
    for (uint32_t v : local) low = glm::min(low, glm::dvec3(world[v])), high = glm::max(high, glm::dvec3(world[v]));
    const glm::dvec3 middle = 0.5 * (low + high);
    const double extent = std::max({high.x - low.x, high.y - low.y, high.z - low.z});
    int exponent = 0;
    if (extent > 0.0) std::frexp(extent, &exponent);
    const double scale = std::ldexp(1.0, -exponent);
    std::vector<glm::vec3> scaled(local.size());
    for (size_t i = 0; i < local.size(); ++i) scaled[i] = glm::vec3((glm::dvec3(world[local[i]]) - middle) * scale);
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

// --- Engine records: meshopt_Bounds as the library makes them ------------------------------------

namespace {

// meshoptimizer asserts on more (kMeshletMaxTriangles in clusterizer.cpp, 0.18).
constexpr size_t kLibraryMaxTriangles = 512;
// It squares coordinates in float: from about 1e19 on that overflows and trips its assertion.
constexpr float kLibraryLargestCoordinate = 1e18f;

MeshletBounds fromLibrary(const meshopt_Bounds& b) {
    MeshletBounds bounds;
    std::copy(b.center, b.center + 3, bounds.center.begin());
    bounds.radius = b.radius;
    std::copy(b.cone_apex, b.cone_apex + 3, bounds.coneApex.begin());
    std::copy(b.cone_axis, b.cone_axis + 3, bounds.coneAxis.begin());
    bounds.coneCutoff = b.cone_cutoff;
    std::copy(b.cone_axis_s8, b.cone_axis_s8 + 3, bounds.coneAxisS8.begin());
    bounds.coneCutoffS8 = b.cone_cutoff_s8;
    return bounds;
}

bool libraryTakes(const uint32_t* vertices, size_t count, size_t triangles, const std::vector<glm::vec3>& positions) {
    if (triangles == 0 || triangles > kLibraryMaxTriangles || positions.empty()) return false;
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 p = glm::abs(positions[vertices[i]]);
        if (!(std::max({p.x, p.y, p.z}) <= kLibraryLargestCoordinate)) return false;
    }
    return true;
}

}  // namespace

MeshletBounds meshoptMeshletBounds(const MeshletArrays& arrays, size_t meshlet, const std::vector<glm::vec3>& positions) {
    const auto [vertexOffset, triangleOffset, vertexCount, triangleCount] = arrays.meshlets[meshlet];
    if (!libraryTakes(&arrays.vertices[vertexOffset], vertexCount, triangleCount, positions)) return MeshletBounds{};
    return fromLibrary(meshopt_computeMeshletBounds(&arrays.vertices[vertexOffset], &arrays.triangles[triangleOffset], triangleCount,
                                                    &positions[0].x, positions.size(), sizeof(glm::vec3)));
}

MeshletBounds meshoptEngineBounds(const std::vector<uint32_t>& indices, const std::vector<glm::vec3>& positions) {
    if (!libraryTakes(indices.data(), indices.size(), indices.size() / 3, positions)) return MeshletBounds{};
    return fromLibrary(meshopt_computeClusterBounds(indices.data(), indices.size(), &positions[0].x, positions.size(), sizeof(glm::vec3)));
}

SimplifiedTriangles simplifyWithLockedBorder(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                                             size_t targetTriangles) {
    SimplifiedTriangles simplified;
    if (indices.empty() || positions.empty()) return simplified;
    simplified.indices.resize(indices.size());
    float relativeError = 0.0f;
    const size_t count = meshopt_simplify(simplified.indices.data(), indices.data(), indices.size(), &positions[0].x, positions.size(),
                                          sizeof(glm::vec3), targetTriangles * 3, std::numeric_limits<float>::max(),
                                          meshopt_SimplifyLockBorder, &relativeError);
    simplified.indices.resize(count);
    simplified.error = double(relativeError) * double(meshopt_simplifyScale(&positions[0].x, positions.size(), sizeof(glm::vec3)));
    return simplified;
}

}  // namespace conescope
