// The geometry of a cull test, for drawing it: the region of eye positions from which a test culls a
// cluster, and the cluster's Gauss map (its face normals on the unit sphere with the cone of every
// method). The debugger draws these; the numbers come from the same bounds the tests use.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "Culling.h"
#include "Pipeline.h"

namespace conescope {

// The eyes a test culls a cluster from, as a solid of revolution around the ray from `origin` along
// `direction` (= -V1: behind the faces): an eye at distance d from the origin is culled iff its angle
// from `direction` is below angles[i] at d = distances[i] (strictly, less kCullMargin's sliver).
//   apex: origin = apex, angle = B = 90 deg - alpha at every distance (a cone);
//   sphere: origin = centre, angle = B - asin(r/d) from d = r / sin B on;
//   meshopt-sphere: origin = centre, angle = acos(sin alpha + r/d) from d = r / (1 - sin alpha) on;
//   orthographic eyes: the directions, angle = B around -V1 (drawn at the centre).
// The octagon test's region is no solid of revolution but a pyramid: `edges` holds its eight edge
// directions from the origin (the apex, or the centre for orthographic eyes), `distances` how far
// along them it is described, and the angles are 0.
// Empty (no distances) for the oracle, for a cluster without a cone and for the vertex and box tests,
// whose region is an intersection of one such cone per point (their points carry the verdicts).
struct CullRegion {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0};
    std::vector<double> distances;
    std::vector<double> angles;      // radians, in (0, pi/2)
    std::vector<glm::dvec3> edges;   // the octagon test's pyramid; empty for the solids of revolution
    bool empty() const { return distances.empty(); }
    bool pyramid() const { return !edges.empty(); }
};
// `reach`: how far from the origin to describe it; `samples`: how many distances (at least 2).
CullRegion cullRegion(const ClusterBounds& bounds, uint32_t cluster, CullTest test, bool orthographic, double reach,
                      size_t samples = 48);

// One cluster's normals on the unit sphere with the cone of every method around them.
struct GaussMap {
    std::vector<glm::dvec3> normals;                          // unit face normals (degenerate faces left out)
    std::vector<std::pair<ConeMethod, ConeOfNormals>> cones;  // allConeMethods(), in that order
    OctagonCone octagon;                                      // around the displayed method's axis
    glm::dvec3 view{0.0};  // the test's unit view vector: a face is back-facing when n.v > 0 for every point
};
GaussMap gaussMapOf(const PreparedMesh& prepared, const ClusterSet& clusters, uint32_t cluster, const CullExplanation& why);

}  // namespace conescope
