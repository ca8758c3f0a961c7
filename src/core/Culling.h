// Per-face truth and per-cluster cull tests. A test culls a cluster only when every face in it is
// strictly back-facing, n.(e - q) < 0 for every vertex q; edge-on faces count as visible.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ClusterBounds.h"
#include "CullTest.h"
#include "CullingInput.h"
#include "Views.h"

namespace conescope {

enum class Facing : uint8_t { Front = 0, Back = 1, Degenerate = 2 };

// The exact per-face oracle: Back iff n.(e - q) < 0 for every vertex q of the face (perspective),
// or n.d > 0 for the view direction d (orthographic). Degenerate faces have no side.
Facing classifyFace(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces, size_t face,
                    const Eye& eye);
std::vector<Facing> classifyFaces(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                  const Eye& eye);

// Fan triangles of the faces classifyFaces found back-facing.
size_t backFacingTriangles(const Mesh& mesh, const std::vector<Facing>& facing);


// One cluster, one eye, one test.
bool cullCluster(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test);

// All clusters: 1 = culled. What the product runs: the batched float kernel (BatchCulling.h, AVX2,
// SSE2 or scalar as the CPU allows) for the perspective apex, sphere and meshopt-sphere tests, which
// culls only what the exact test culls (minus a sliver at its threshold), and the exact
// double-precision test for the others.
std::vector<uint8_t> cullClusters(const CullingInput& input, const Eye& eye, CullTest test);

// The exact double-precision test for every cluster (cullCluster): the reference the batched
// kernel is checked against.
std::vector<uint8_t> cullClustersExact(const CullingInput& input, const Eye& eye, CullTest test);

// Whether cullClusters runs the batched kernel for this eye and test.
bool culledInBatch(const Eye& eye, CullTest test);

// The single comparisons the tests are made of, exposed so the GUI can show each step.
// v.V1 > sin(alpha): the unit view vector lies inside the cone of views that see every normal's back.
bool viewDirectionSeesBack(const ConeOfNormals& cone, const glm::dvec3& unitView);
// Seed 000's bounding-sphere test: v.V1 > cos(B - asin(r/d)); never culls with the eye inside.
bool sphereSeesBack(const ConeOfNormals& cone, const Sphere& sphere, const glm::dvec3& eye);
// meshoptimizer's apex test: (a - e).V1 > sin(alpha) |a - e|, the apex a behind every face plane
// (its threshold allows for the apex's rounding, apexRoundingSlack).
bool apexSeesBack(const ConeOfNormals& cone, const glm::dvec3& apex, const glm::dvec3& eye);
// meshoptimizer's sphere test: (c - e).V1 > sin(alpha) |c - e| + r.
bool meshoptSphereSeesBack(const ConeOfNormals& cone, const Sphere& sphere, const glm::dvec3& eye);
// Seed 000's box test without normalisation: for each corner k, (k - e).V1 > 0 and
// ((k - e).V1)^2 > sin^2(alpha) |k - e|^2.
bool pointSeesBackUnnormalised(const ConeOfNormals& cone, const glm::dvec3& point, const glm::dvec3& eye);
std::array<glm::dvec3, 8> aabbCorners(const Aabb& box);

// A learner's view of one decision: every number the chosen test compared.
struct CullExplanation {
    bool culled = false;              // the product's decision (cullClusters: batched where it can be)
    bool exactCulled = false;         // the exact double test's; differs only in a sliver at the threshold
    bool cullable = false;
    glm::dvec3 axis{0.0};
    double halfAngleDegrees = 90.0;
    double cosHalfAngle = 0.0;        // min n.V1
    double angleBDegrees = 0.0;       // B = 90 - alpha
    double threshold = 0.0;           // the value v.V1 had to exceed
    glm::dvec3 view{0.0};             // unit vector from the eye to the sphere centre (or the view direction)
    double viewDotAxis = 0.0;
    double distance = 0.0;            // |c - e|
    double radius = 0.0;
    double sphereAngleDegrees = 0.0;  // asin(r/d)
    bool eyeInsideSphere = false;
    glm::dvec3 apex{0.0};
    // Octagon test: the eight edges of the cone of normals and g.v for each (v the unit view vector
    // to the apex); all must exceed kCullMargin.
    std::array<glm::dvec3, 8> octagonEdges{};
    std::array<double, 8> edgeDotView{};
    size_t edgesBack = 0;
    std::array<glm::dvec3, 8> corners{};
    std::array<double, 8> cornerDotAxis{};
    std::array<bool, 8> cornerBack{};
    size_t pointsTested = 0;          // vertices or corners looked at
    size_t pointsBack = 0;
    // Vertices test: each cluster vertex and whether its view vector sees the back (1 = yes).
    std::vector<glm::dvec3> vertices;
    std::vector<uint8_t> vertexBack;
    // How far the tightest compared value is past its threshold, in units of v.V1: above 0 the exact
    // test culls with that much to spare, below 0 it is short by that much. NaN for the oracle and
    // for a cluster without a cone. The meshopt-sphere test is written as v.V1 > sin(alpha) + r/d.
    double margin = 0.0;
    size_t frontFaces = 0;            // by the oracle
    size_t backFaces = 0;
    size_t degenerateFaces = 0;
};
CullExplanation explainCull(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test);

}  // namespace conescope
