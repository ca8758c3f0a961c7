// The view-independent measure of a partition that the optimized builder maximises and the
// statistics report: the expected fraction of back-facing triangles that cluster culling removes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "Cones.h"
#include "Mesh.h"
#include "Partition.h"

namespace conescope {

// Seen from a uniformly random far direction, a cluster whose normal cone has half-angle alpha is
// culled with probability (1 - sin alpha) / 2, and half of all triangles face away, so a cluster
// of T triangles contributes T (1 - sin alpha) to sum_c T_c (1 - sin alpha_c) / T, the estimate of
// the fraction of back-facing triangles culled.
// A cone at the hemisphere (sin alpha rounded a hair above 1) counts 0, never a sliver below.
inline double expectedCulledTriangles(double triangles, double sinHalfAngle) { return triangles * std::max(0.0, 1.0 - sinHalfAngle); }

// The share of far view directions from which such a cone is culled: (1 - sin alpha) / 2, the area
// of the cap of half-angle 90 - alpha (CullMap.h: every cluster's cull_fraction).
inline double coneCullShare(double sinHalfAngle) { return 0.5 * (1.0 - std::clamp(sinHalfAngle, -1.0, 1.0)); }

// sum_c T_c (1 - sin alpha_c) / T over clusters with these cones and triangle counts; a cone that
// is not cullable counts 0. 0 when there are no triangles.
double expectedCullRate(const ConeOfNormals* cones, const uint32_t* triangles, size_t clusterCount);

// The same with each cluster's exact minimal cone (minimalCone).
double expectedCullRate(const Mesh& mesh, const FaceGeometry& faces, const Partition& partition);

}  // namespace conescope
