// Everything a cull test reads about a cluster, computed once per partition: its faces and
// vertices, a cone of normals (round, and eight-sided around the same axis), an AABB, a bounding
// sphere and the apex of meshoptimizer's apex test.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Cones.h"
#include "Mesh.h"
#include "OctagonCones.h"
#include "Partition.h"
#include "Spheres.h"

namespace conescope {

// The records a bounds holds (EngineRecords.h, which reads the bounds: declared here, so that
// ClusterBounds.h does not include it).
class EngineRecords;
std::shared_ptr<EngineRecords> makeEngineRecords();

// Chosen: per cluster, the offered cone whose octagon test culls from the most eyes (ChosenCones.h).
enum class ConeMethod { Average, SeedSphere, Minimal, Meshopt, Chosen };
enum class SphereMethod { Ritter, Minimal };
// The default cone and sphere (with kDefaultTest, CullTest.h): per cluster the offered cone that
// culls most, and the exact minimal sphere.
constexpr ConeMethod kDefaultCone = ConeMethod::Chosen;
constexpr SphereMethod kDefaultSphere = SphereMethod::Minimal;

struct ClusterBounds {
    ConeMethod coneMethod = ConeMethod::Minimal;
    SphereMethod sphereMethod = SphereMethod::Minimal;
    ClusterFaces faces;                  // faces of each cluster
    std::vector<uint32_t> vertexStarts;  // distinct vertices of each cluster, compressed rows
    std::vector<uint32_t> vertexIds;
    std::vector<uint32_t> triangles;     // fan triangles per cluster (degenerate faces included)
    std::vector<ConeOfNormals> cones;
    std::vector<Aabb> boxes;
    std::vector<Sphere> spheres;
    // Apex test: the cone's apex, placed on the back side of every face plane of the cluster.
    std::vector<glm::dvec3> apexes;
    // Octagon test: the eight-sided cone of normals around the cone's axis (same apex).
    std::vector<OctagonCone> octagons;
    // The share of view directions from which every face faces away (normalsCullShare), found from
    // the octagon's hull: the oracle's share in the cull map.
    std::vector<double> normalsShares;
    // The engine tests' and the compact octagon's records, made on first use (RecordTests.h); copies
    // of the bounds share them.
    std::shared_ptr<EngineRecords> records = makeEngineRecords();

    size_t count() const { return cones.size(); }
};

// World positions and face geometry must come from the same mesh (worldPositions, computeFaceGeometry).
// On all cores.
ClusterBounds computeClusterBounds(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                   const Partition& partition, ConeMethod coneMethod,
                                   SphereMethod sphereMethod = SphereMethod::Minimal);

// The same for some clusters, given as the faces of each (on the calling thread): a part of a
// partition bounded as soon as it is made. Faces of a cluster in ascending order give exactly the
// bounds computeClusterBounds gives that cluster. The chosen cone counts eyes around the whole
// object's box: pass it (the world box), or it is found from `world` on each call.
ClusterBounds boundsOfClusters(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                               ClusterFaces clusterRows, ConeMethod coneMethod, SphereMethod sphereMethod = SphereMethod::Minimal,
                               const Aabb* objectBox = nullptr);

// The clusters of a partition of some faces (partOfThem.clusterOfFace[k] for faceIds[k]) as rows of
// mesh faces, in ascending order when faceIds is.
ClusterFaces clusterRowsOf(const uint32_t* faceIds, const Partition& partOfThem);

// `more`'s clusters numbered after those of `bounds`.
void appendClusterBounds(ClusterBounds& bounds, ClusterBounds&& more);

// One cluster's cone by `method`, exactly as computeClusterBounds makes it with `sphereMethod`: the
// Gauss map compares every method's cone on the same cluster.
ConeOfNormals clusterCone(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                          const uint32_t* clusterFaces, size_t faceCount, ConeMethod method,
                          SphereMethod sphereMethod = SphereMethod::Minimal);

// The cone of the methods that read the normals alone (average, seed-sphere, minimal).
ConeOfNormals coneByMethod(ConeMethod method, const std::vector<glm::dvec3>& normals);

// The point behind every face plane along -axis (meshoptimizer's construction, in double):
// apex = centre - axis * max_f n_f.(centre - q_f) / n_f.axis over the faces' vertices q_f, and no
// further forward than the centre. With `forwardToo` also forward of the centre, onto the last
// plane: the pyramid of eyes an apex test culls from only grows as the apex moves along +axis.
glm::dvec3 coneApex(const ConeOfNormals& cone, const glm::dvec3& center, const Mesh& mesh,
                    const std::vector<glm::vec3>& world, const FaceGeometry& faces, const uint32_t* clusterFaces,
                    size_t faceCount, bool forwardToo = false);

}  // namespace conescope
