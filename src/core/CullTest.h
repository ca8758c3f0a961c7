// The cull tests by name, and the margins every one of them compares with: what the exact tests
// (Culling.h), the batched kernel (BatchCulling.h) and the octagon's test (OctagonCones.h) share.
#pragma once

#include <algorithm>
#include <string>

#include <glm/glm.hpp>

namespace conescope {

// The last four read records of their own (RecordTests.h): meshoptimizer's meshopt_Bounds tested as
// shaders test it, cadscene's packed box and cone, and the octagon in 16 bytes.
enum class CullTest { Oracle, Vertices, Aabb, AabbFast, Sphere, Apex, MeshoptSphere, Octagon, MeshoptApexF32, MeshoptSphereS8, CadsceneBoxS8,
                      OctagonCompact };

// The defaults, here and nowhere else (Settings, the statistics and every struct that carries a test):
// the best measured with the exact minimal cone (docs/benchmarks.md).
constexpr CullTest kDefaultTest = CullTest::Octagon;

// The test's name in the settings and statistics ("octagon"); Settings.cpp holds the names.
std::string toString(CullTest);

// Margin added to every threshold a cluster test compares against: it absorbs the rounding of the
// double-precision dot products so that a face exactly edge-on is never culled.
constexpr double kCullMargin = 1e-9;

// The tests from the apex (apex, octagon) also allow for the rounding of the apex itself. The apex
// is moved behind every face plane; for a cluster tiny against its distance from the origin (a few
// nanometres across, 3e19 away) that move is below a coordinate's rounding and is lost, and the
// rounded apex sits in front of a plane by up to a few units in the last place of the largest
// coordinate. Each comparison's threshold gets this many times the largest |coordinate| of the apex
// and the eye on top (64 units in the last place: the apex's placement, the view vector's and the
// oracle's own subtractions each round by about one); on ordinary scenes it is 1e-14 of the scene's
// size.
constexpr double kApexRoundingSlack = 64.0 / 9007199254740992.0;  // 64 * 2^-53
inline double apexRoundingSlack(const glm::dvec3& apex, const glm::dvec3& eyePosition) {
    const glm::dvec3 largest = glm::max(glm::abs(apex), glm::abs(eyePosition));
    return kApexRoundingSlack * std::max({largest.x, largest.y, largest.z});
}

}  // namespace conescope
