// Cull tests over all clusters at once: the bounds a test reads, stored as float arrays (structure
// of arrays), tested 8 clusters per step with AVX2 or 4 with SSE2, chosen at run time.
//
// Float is only an encoding: every stored threshold is rounded in the conservative direction and a
// rounding slack is added to every comparison, so a batched test culls a cluster only when the same
// test on the exact (double) bounds would cull it too, minus a sliver of clusters right at its
// threshold. The slack has a relative part (kBatchRelativeSlack times the eye distance) and an
// absolute part (kBatchAbsoluteSlack times the largest coordinate of the eye and of the cluster's
// own centre and apex); the error bound they
// come from is worked out at the top of BatchCulling.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "ClusterBounds.h"
#include "CullTest.h"

namespace conescope {

// Added to sin(alpha) before it is rounded up to float: covers the rounding of the products with it.
constexpr double kBatchSinMargin = 1e-6;
// Multiples of float's unit roundoff 2^-24, from the error bound worked out in BatchCulling.cpp.
constexpr double kBatchRelativeSlack = 16.0 / 16777216.0;
constexpr double kBatchAbsoluteSlack = 64.0 / 16777216.0;

// Clusters as parallel float arrays, padded with never-culled entries to a multiple of 8 so the
// SIMD loops need no remainder loop. A cluster whose cone is not cullable has a zero axis and a
// threshold above 1, so no comparison can pass for it.
struct ClusterBatch {
    size_t count = 0;                           // real clusters; arrays hold paddedCount() entries
    std::vector<float> axisX, axisY, axisZ;     // cone axis V1
    std::vector<float> sinHalfAngle;            // sin(alpha) + kBatchSinMargin, rounded up
    std::vector<float> cosHalfAngleUp;          // cos(alpha) + margin, rounded up: the sphere test's threshold
    std::vector<float> cosHalfAngleDown;        // cos(alpha) - margin, rounded down: its "eye outside" condition
    std::vector<float> centerX, centerY, centerZ;
    std::vector<float> radius;                  // rounded up
    std::vector<float> apexX, apexY, apexZ;
    // The octagon test's apex, eight unit edges and slack (zero for a cluster that is not cullable),
    // all of a group of 8 clusters together: field f of cluster c at [c / 8 * 28 * 8 + f * 8 + c % 8],
    // fields apex x, y, z, then x, y, z of each edge, then the slack. One stream of loads, not 28.
    static constexpr size_t kOctagonFields = 28;
    std::vector<float> octagonBlocks;
    // Each cluster's part of the absolute slack: kBatchAbsoluteSlack times the largest |coordinate|
    // of its centre (plus its radius) or apex, rounded up (the eye adds its own part per call).
    std::vector<float> slack;

    size_t paddedCount() const { return axisX.size(); }
};

// From bounds computed by computeClusterBounds (any cone or sphere method).
ClusterBatch makeClusterBatch(const ClusterBounds& bounds);

// Which instruction set a batched test runs on. Asking for more than the CPU has falls back to the
// best it has, so every level can be requested on any x86-64 machine.
enum class SimdLevel { Scalar, Sse2, Avx2 };
SimdLevel bestSimdLevel();
const char* toString(SimdLevel level);

// Each writes culled[c] = 1 or 0 for c in [0, batch.count); `culled` holds at least batch.count
// bytes. The eye is a perspective eye position in world space. The scalar level is the reference:
// the SIMD levels compute the same float operations in the same order, so they agree bit for bit.
//
// Seed 000's sphere test (CullTest::Sphere): (c - e).V1 > sin(alpha) sqrt(d^2 - r^2) + cos(alpha) r,
// which is v.V1 > cos(B - asin(r/d)) multiplied out, and d cos(alpha) > r (B > asin(r/d)).
void cullSphereBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled,
                     SimdLevel level = bestSimdLevel());
// meshoptimizer's apex test (CullTest::Apex): (a - e).V1 > sin(alpha) |a - e|.
void cullApexBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled,
                   SimdLevel level = bestSimdLevel());
// meshoptimizer's sphere test (CullTest::MeshoptSphere): (c - e).V1 > sin(alpha) |c - e| + r.
void cullMeshoptSphereBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled,
                            SimdLevel level = bestSimdLevel());
// The octagon test (CullTest::Octagon): (a - e).g > 0 for each of the eight edges g.
void cullOctagonBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled,
                      SimdLevel level = bestSimdLevel());

// The four tests above by CullTest; batchSupports says which tests have a batched form.
bool batchSupports(CullTest test);
void cullBatch(const ClusterBatch& batch, const glm::dvec3& eye, CullTest test, uint8_t* culled,
               SimdLevel level = bestSimdLevel());
std::vector<uint8_t> cullBatch(const ClusterBatch& batch, const glm::dvec3& eye, CullTest test,
                               SimdLevel level = bestSimdLevel());

}  // namespace conescope
