// Several cones per cluster: each cluster's faces split into K sub-groups stored contiguously (so a
// record needs only K - 1 offsets), each sub-group with its own minimal cone and the cluster's
// bounding sphere. A sub-group is culled when its cone and the shared sphere say every face in it
// faces away: narrower cones cull more back faces of the same partition.
#pragma once

#include <cstdint>
#include <vector>

#include "BatchCulling.h"
#include "ClusterBounds.h"
#include "Culling.h"
#include "Views.h"

namespace conescope {

struct MultiCones {
    uint32_t conesPerCluster = 1;        // K
    std::vector<uint32_t> faces;         // each cluster's faces, sub-group after sub-group
    std::vector<uint32_t> groupStarts;   // into faces: clusterCount * K + 1 entries (sub-groups may be empty)
    std::vector<ConeOfNormals> cones;    // clusterCount * K, minimalCone of each sub-group
    std::vector<uint32_t> groupTriangles;  // fan triangles of each sub-group

    size_t groupCount() const { return cones.size(); }
};

// The expected culled share of one sub-group's cone over view directions, weighted by its
// triangles: T (1 - sin alpha) / 2; zero for a cone that never culls.
double expectedCulledTriangles(const ConeOfNormals& cone, size_t triangles);

// Splits `count` faces (their unit normals, their triangles) into at most `groups` sub-groups
// aiming at a large sum of expectedCulledTriangles: triangle-weighted Lloyd iterations on the normals
// from farthest-point seeds, kept only when they beat one group. Returns each face's group.
std::vector<uint8_t> splitForCones(const glm::dvec3* normals, const uint32_t* triangles, size_t count, uint32_t groups);

// K sub-groups and their cones for every cluster of `bounds` (K = 1 gives the cluster's own faces).
MultiCones computeMultiCones(const Mesh& mesh, const FaceGeometry& faces, const ClusterBounds& bounds, uint32_t conesPerCluster);

// One sub-group from one eye: seed 000's sphere test on its cone and the cluster's sphere, or the
// view direction alone for an orthographic eye. Conservative like every cluster test.
bool subGroupSeesBack(const ConeOfNormals& cone, const Sphere& sphere, const Eye& eye);

// Every sub-group from one eye: 1 = culled.
std::vector<uint8_t> cullSubGroups(const ClusterBounds& bounds, const MultiCones& multi, const Eye& eye);

// Triangles in culled sub-groups.
size_t culledTriangles(const MultiCones& multi, const std::vector<uint8_t>& culledGroups);

// Bytes of one cluster's record as a renderer would store it (layouts in docs/statistics-schema.md,
// bytes_per_cluster), padded to 4 bytes. Float: sphere (4 floats), per cone its axis and sin(alpha)
// (4 floats), K - 1 sub-group offsets. Compact: sphere in 4 x 16 bits within the mesh's box, per cone
// an 8-bit axis and an 8-bit sin(alpha), the offsets. An offset takes 1 byte when no cluster holds
// more than 255 triangles (meshoptimizer's limits), else 2.
size_t multiConeRecordBytes(uint32_t conesPerCluster, size_t maxClusterTriangles, bool compact);

// The compact record decoded, one per sub-group and cluster, for the same sphere test. Every
// rounding goes the safe way: each sphere grows by its centre's rounding and rounds its radius up,
// each cone is rebuilt around its rounded axis (holding every normal of its sub-group) and its
// sin(alpha) rounded up to 1/254; a sub-group whose cone reaches a hemisphere stores "never".
struct CompactMultiCones {
    std::vector<ConeOfNormals> cones;  // as multi.cones
    std::vector<Sphere> spheres;       // per cluster
};
CompactMultiCones compactMultiCones(const FaceGeometry& faces, const ClusterBounds& bounds, const MultiCones& multi,
                                    const Aabb& meshBox);

// Every sub-group from one eye with the given cones and spheres (the float record's or the compact
// one's), by the exact test: 1 = culled.
std::vector<uint8_t> cullSubGroups(const std::vector<ConeOfNormals>& cones, const std::vector<Sphere>& spheres,
                                   uint32_t conesPerCluster, const Eye& eye);

// The sub-groups as clusters of the batched sphere test (BatchCulling.h): each its own cone and its
// cluster's sphere.
ClusterBatch subGroupBatch(const std::vector<ConeOfNormals>& cones, const std::vector<Sphere>& spheres, uint32_t conesPerCluster);

// What the product runs: the batched sphere test for a perspective eye (culling only what the exact
// test culls, minus a sliver at its threshold), the exact test for an orthographic one.
std::vector<uint8_t> cullSubGroupsBatched(const ClusterBatch& batch, const std::vector<ConeOfNormals>& cones,
                                          const std::vector<Sphere>& spheres, uint32_t conesPerCluster, const Eye& eye);

// One K-cone record (the float cones and the clusters' spheres, or the compact record's) ready to be
// tested from many eyes as the product tests it, batched. `multi` and `spheres` must outlive it.
struct SubGroupRecord {
    const MultiCones* multi = nullptr;
    std::vector<ConeOfNormals> cones;
    const std::vector<Sphere>* spheres = nullptr;
    ClusterBatch batch;
};
SubGroupRecord subGroupRecord(const MultiCones& multi, std::vector<ConeOfNormals> cones, const std::vector<Sphere>& spheres);

// What one eye's test does to a record: triangles in culled sub-groups, and culled sub-groups holding
// a face that is not back-facing (`facing` from classifyFaces). Only the sub-groups of clusters
// whose entry in `clusters` is 1 count (empty: every cluster), as for the clusters a LOD cut draws.
struct SubGroupCulling {
    size_t trianglesCulled = 0;
    size_t falseCulls = 0;
};
SubGroupCulling countSubGroupCulling(const SubGroupRecord& record, const std::vector<Facing>& facing, const Eye& eye,
                                     const std::vector<uint8_t>& clusters = {});

}  // namespace conescope
