// The view-independent quality of a partition and of a test: for each cluster, the share of view
// directions (eye at infinity, directions uniform on the sphere) from which it is culled.
//
// At infinity every conservative cone test (vertices, aabb, sphere, apex, meshopt-sphere) reduces to
// the cone test v.axis > sin(alpha), culled from a cap of half-angle 90 - alpha: a share
// (1 - sin alpha)/2 of the directions, exactly. The octagon test culls from the cross-section of its
// pyramid, a spherical octagon whose area is known exactly too (octagonCullShare). The oracle culls
// from every direction u with n.u < 0 for each non-degenerate face normal n: the polar of the
// normals' convex hull on the sphere, of area 2 pi - the hull's perimeter, also exact
// (normalsCullShare). Each region holds the ones before it, and so does each share.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ClusterBounds.h"
#include "Culling.h"
#include "ExpectedCull.h"

namespace conescope {

struct CullMap {
    std::vector<double> coneFraction;     // per cluster: (1 - sin alpha)/2, 0 when not cullable
    std::vector<double> octagonFraction;  // per cluster: octagonCullShare, 0 when not cullable
    std::vector<double> oracleFraction;   // per cluster: share of directions with every face back-facing
};

// From the cones, octagons and normals' shares of `bounds` (world space): a few operations per
// cluster, the hulls having been found with the bounds.
CullMap computeCullMap(const ClusterBounds& bounds);

// The share for `test`: the oracle's own for CullTest::Oracle, the octagon's for CullTest::Octagon,
// the round cone's for every other test.
double cullFraction(const CullMap& map, uint32_t cluster, CullTest test);

// Any test's share: a record of its own's (ownRecordCullShare, RecordTests.h) for the tests that
// read one, the cull map's for the others.
double testCullFraction(const CullMap& map, const CullingInput& input, uint32_t cluster, CullTest test);

}  // namespace conescope
