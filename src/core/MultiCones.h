// Several cones per cluster: each cluster's faces split into K sub-groups stored contiguously (so a
// record needs only K - 1 offsets), each sub-group with its own minimal cone and its own apex, a point
// behind every face plane of the sub-group on its axis through the cluster's sphere centre (one
// number per sub-group). A sub-group is culled by meshoptimizer's apex test on its cone and apex:
// narrower cones cull more back faces of the same partition, and an apex on a narrow cone's axis
// sits close to the surface where the sphere test's would sit a radius behind it.
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
    std::vector<glm::dvec3> apexes;      // clusterCount * K, coneApex of each sub-group from its cluster's sphere centre
    std::vector<uint32_t> groupTriangles;  // fan triangles of each sub-group

    size_t groupCount() const { return cones.size(); }
};

// The expected culled share of one sub-group's cone over view directions, weighted by its
// triangles: T (1 - sin alpha) / 2; zero for a cone that never culls.
double expectedCulledTriangles(const ConeOfNormals& cone, size_t triangles);

// Splits `count` faces (their unit normals, their triangles) into at most `groups` sub-groups
// aiming at a large sum of expectedCulledTriangles: triangle-weighted Lloyd iterations on the normals
// from farthest-point seeds, kept only when they beat one group; every split tried, the best kept, for
// clusters of up to 12 faces (2 groups) or 8 (4 and 8 groups). Returns each face's group, and in
// `cones` (when given) each group's minimal cone (`groups` entries, empty groups never cull).
std::vector<uint8_t> splitForCones(const glm::dvec3* normals, const uint32_t* triangles, size_t count, uint32_t groups,
                                   std::vector<ConeOfNormals>* cones = nullptr);

// K sub-groups, their cones and apexes for every cluster of `bounds` (K = 1 gives the cluster's own
// faces, its minimal cone and apex). `world`: the mesh's world positions (made here when empty).
MultiCones computeMultiCones(const Mesh& mesh, const FaceGeometry& faces, const ClusterBounds& bounds, uint32_t conesPerCluster,
                             const std::vector<glm::vec3>& world = {});

// One sub-group from one eye: meshoptimizer's apex test on its cone and apex, or the view direction
// alone for an orthographic eye. Conservative like every cluster test (the apex's rounding slack).
// The apex on the axis at most r / cos(alpha) behind the sphere's centre culls wherever seed 000's
// sphere test does: the sphere test is the apex test from that point.
bool subGroupSeesBack(const ConeOfNormals& cone, const glm::dvec3& apex, const Eye& eye);

// Every sub-group from one eye: 1 = culled.
std::vector<uint8_t> cullSubGroups(const ClusterBounds& bounds, const MultiCones& multi, const Eye& eye);

// Triangles in culled sub-groups.
size_t culledTriangles(const MultiCones& multi, const std::vector<uint8_t>& culledGroups);

// Bytes of one cluster's record as a renderer would store it (layouts in docs/statistics-schema.md,
// bytes_per_cluster), padded to 4 bytes. Float: sphere (4 floats), per cone its axis, sin(alpha) and
// the apex's distance behind the centre (5 floats), K - 1 sub-group offsets. Compact: sphere in
// 4 x 16 bits within the mesh's box, per cone a 3 x 8-bit axis, an 8-bit sin(alpha) and an 8-bit apex
// distance, the offsets. The K - 1 offsets are packed bit fields as wide as the largest cluster's
// triangle count needs: 8 bits up to 255 triangles (meshoptimizer's limits), 10 up to 1023, so the
// compact 4-cone record stays 32 bytes for clusters of up to 1023 triangles.
size_t multiConeRecordBytes(uint32_t conesPerCluster, size_t maxClusterTriangles, bool compact);

// The compact record decoded, one per sub-group and cluster, for the same apex test. Every
// rounding goes the safe way: each sphere grows by its centre's rounding and rounds its radius up,
// each cone is rebuilt around its rounded axis (holding every normal of its sub-group) and its
// sin(alpha) rounded up to 1/254; a sub-group whose cone reaches a hemisphere stores "never". The
// apex's distance t behind the decoded centre, along the decoded axis, is stored as
// s = t cos(alpha) / r in 1/255 steps rounded up: s = 1 (the sphere test's apex) is always behind
// every face plane, so the compact apex test culls at least what the compact sphere test would.
struct CompactMultiCones {
    std::vector<ConeOfNormals> cones;  // as multi.cones
    std::vector<Sphere> spheres;       // per cluster
    std::vector<glm::dvec3> apexes;    // as multi.apexes
};
CompactMultiCones compactMultiCones(const FaceGeometry& faces, const ClusterBounds& bounds, const MultiCones& multi,
                                    const Aabb& meshBox);

// Every sub-group from one eye with the given cones and apexes (the float record's or the compact
// one's), by the exact test: 1 = culled.
std::vector<uint8_t> cullSubGroups(const std::vector<ConeOfNormals>& cones, const std::vector<glm::dvec3>& apexes, const Eye& eye);

// The sub-groups as clusters of the batched apex test (BatchCulling.h): each its own cone and apex.
ClusterBatch subGroupBatch(const std::vector<ConeOfNormals>& cones, const std::vector<glm::dvec3>& apexes);

// What the product runs: the batched apex test for a perspective eye (culling only what the exact
// test culls, minus a sliver at its threshold), the exact test for an orthographic one.
std::vector<uint8_t> cullSubGroupsBatched(const ClusterBatch& batch, const std::vector<ConeOfNormals>& cones,
                                          const std::vector<glm::dvec3>& apexes, const Eye& eye);

// One K-cone record (the float cones and apexes with the clusters' spheres, or the compact record's)
// ready to be tested from many eyes as the product tests it, batched. `apexes` null: the float
// record's, multi.apexes. `multi` and `spheres` must outlive it.
struct SubGroupRecord {
    const MultiCones* multi = nullptr;
    std::vector<ConeOfNormals> cones;
    std::vector<glm::dvec3> apexes;
    const std::vector<Sphere>* spheres = nullptr;
    ClusterBatch batch;
};
SubGroupRecord subGroupRecord(const MultiCones& multi, std::vector<ConeOfNormals> cones, const std::vector<Sphere>& spheres,
                              const std::vector<glm::dvec3>* apexes = nullptr);

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
