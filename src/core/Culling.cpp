#include "Culling.h"

#include "BatchCulling.h"
#include "RecordTests.h"

#include <algorithm>
#include <limits>
#include <cmath>

namespace conescope {

Facing classifyFace(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces, size_t face,
                    const Eye& eye) {
    if (faces.degenerate[face]) return Facing::Degenerate;
    const glm::dvec3& n = faces.normals[face];
    if (eye.orthographic) return glm::dot(n, eye.direction) > 0.0 ? Facing::Back : Facing::Front;
    // Strict: n.(e - q) < 0 at every corner; zero (edge-on) is visible.
    const uint32_t* vertices = mesh.faceBegin(face);
    for (size_t k = 0; k < mesh.faceSize(face); ++k)
        if (!(glm::dot(n, eye.position - glm::dvec3(world[vertices[k]])) < 0.0)) return Facing::Front;
    return Facing::Back;
}

std::vector<Facing> classifyFaces(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                  const Eye& eye) {
    std::vector<Facing> facing(mesh.faceCount());
    for (size_t f = 0; f < facing.size(); ++f) facing[f] = classifyFace(mesh, world, faces, f, eye);
    return facing;
}

size_t backFacingTriangles(const Mesh& mesh, const std::vector<Facing>& facing) {
    size_t total = 0;
    for (size_t f = 0; f < facing.size(); ++f)
        if (facing[f] == Facing::Back) total += mesh.faceSize(f) - 2;
    return total;
}

bool viewDirectionSeesBack(const ConeOfNormals& cone, const glm::dvec3& unitView) {
    return cone.cullable && glm::dot(unitView, cone.axis) > cone.sinHalfAngle + kCullMargin;
}

// Same comparison for an unnormalised view vector v = point - eye: v.V1 > sin(alpha) |v| (+ slack).
static bool vectorSeesBack(const ConeOfNormals& cone, const glm::dvec3& view, double slack = 0.0) {
    const double length = glm::length(view);
    return length > 0.0 && glm::dot(view, cone.axis) > (cone.sinHalfAngle + kCullMargin) * length + slack;
}

bool pointSeesBackUnnormalised(const ConeOfNormals& cone, const glm::dvec3& point, const glm::dvec3& eye) {
    const glm::dvec3 view = point - eye;
    const double along = glm::dot(view, cone.axis);
    const double threshold = cone.sinHalfAngle + kCullMargin;
    // Both sides squared: no square root and no division per corner.
    return along > 0.0 && along * along > threshold * threshold * glm::dot(view, view);
}

bool sphereSeesBack(const ConeOfNormals& cone, const Sphere& sphere, const glm::dvec3& eye) {
    if (!cone.cullable) return false;
    const glm::dvec3 toCenter = sphere.center - eye;
    const double distance = glm::length(toCenter);
    if (!(distance > sphere.radius)) return false;  // eye inside the sphere: every direction is possible
    const double angleB = std::asin(std::clamp(cone.cosHalfAngle, -1.0, 1.0));
    const double spread = std::asin(sphere.radius / distance);
    if (!(angleB - spread > 0.0)) return false;
    return glm::dot(toCenter, cone.axis) / distance > std::cos(angleB - spread) + kCullMargin;
}

bool apexSeesBack(const ConeOfNormals& cone, const glm::dvec3& apex, const glm::dvec3& eye) {
    return cone.cullable && vectorSeesBack(cone, apex - eye, apexRoundingSlack(apex, eye));
}

bool meshoptSphereSeesBack(const ConeOfNormals& cone, const Sphere& sphere, const glm::dvec3& eye) {
    if (!cone.cullable) return false;
    const glm::dvec3 toCenter = sphere.center - eye;
    const double distance = glm::length(toCenter);
    return glm::dot(toCenter, cone.axis) > (cone.sinHalfAngle + kCullMargin) * distance + sphere.radius;
}

std::array<glm::dvec3, 8> aabbCorners(const Aabb& box) {
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i)
        corners[i] = glm::dvec3((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                                (i & 4) ? box.max.z : box.min.z);
    return corners;
}

static bool oracleCulls(const CullingInput& input, uint32_t cluster, const Eye& eye) {
    const ClusterFaces& rows = input.bounds.faces;
    size_t back = 0;
    for (uint32_t i = rows.starts[cluster]; i < rows.starts[cluster + 1]; ++i) {
        const Facing facing = classifyFace(input.mesh, input.world, input.faces, rows.faces[i], eye);
        if (facing == Facing::Front) return false;
        back += facing == Facing::Back;
    }
    return back > 0;
}

bool cullCluster(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    if (test == CullTest::Oracle) return oracleCulls(input, cluster, eye);
    if (readsOwnRecord(test)) return ownRecordCulls({input.mesh, input.world, input.faces, input.bounds}, cluster, eye, test);
    const ClusterBounds& bounds = input.bounds;
    const ConeOfNormals& cone = bounds.cones[cluster];
    if (!cone.cullable) return false;
    // From infinitely far every view vector is the view direction: all bounds give the same answer,
    // the cone's (round, or eight-sided for the octagon test).
    if (eye.orthographic)
        return test == CullTest::Octagon ? octagonSeesBack(bounds.octagons[cluster], eye.direction)
                                         : viewDirectionSeesBack(cone, eye.direction);
    switch (test) {
        case CullTest::Vertices:
            for (uint32_t i = bounds.vertexStarts[cluster]; i < bounds.vertexStarts[cluster + 1]; ++i)
                if (!vectorSeesBack(cone, glm::dvec3(input.world[bounds.vertexIds[i]]) - eye.position)) return false;
            return true;
        case CullTest::Aabb:
            for (const glm::dvec3& corner : aabbCorners(bounds.boxes[cluster]))
                if (!vectorSeesBack(cone, corner - eye.position)) return false;
            return true;
        case CullTest::AabbFast:
            for (const glm::dvec3& corner : aabbCorners(bounds.boxes[cluster]))
                if (!pointSeesBackUnnormalised(cone, corner, eye.position)) return false;
            return true;
        case CullTest::Sphere: return sphereSeesBack(cone, bounds.spheres[cluster], eye.position);
        case CullTest::Apex: return apexSeesBack(cone, bounds.apexes[cluster], eye.position);
        case CullTest::MeshoptSphere: return meshoptSphereSeesBack(cone, bounds.spheres[cluster], eye.position);
        case CullTest::Octagon:
            return octagonSeesBack(bounds.octagons[cluster], bounds.apexes[cluster] - eye.position,
                                   apexRoundingSlack(bounds.apexes[cluster], eye.position));
        case CullTest::Oracle:
        case CullTest::MeshoptApexF32:
        case CullTest::MeshoptSphereS8:
        case CullTest::CadsceneBoxS8:
        case CullTest::OctagonCompact: break;  // answered above
    }
    return false;
}

std::vector<uint8_t> cullClustersExact(const CullingInput& input, const Eye& eye, CullTest test) {
    std::vector<uint8_t> culled(input.bounds.count());
    for (uint32_t c = 0; c < culled.size(); ++c) culled[c] = cullCluster(input, c, eye, test) ? 1 : 0;
    return culled;
}

bool culledInBatch(const Eye& eye, CullTest test) { return !eye.orthographic && batchSupports(test); }

std::vector<uint8_t> cullClusters(const CullingInput& input, const Eye& eye, CullTest test) {
    if (!culledInBatch(eye, test)) return cullClustersExact(input, eye, test);
    if (input.batch) return cullBatch(*input.batch, eye.position, test);
    return cullBatch(makeClusterBatch(input.bounds), eye.position, test);
}

// The vertices test's points: each vertex, whether it sees the cluster's back, and the smallest
// v.V1 over them (returned).
static double explainVertices(const CullingInput& input, uint32_t cluster, const Eye& eye, CullExplanation& why) {
    const ClusterBounds& bounds = input.bounds;
    const ConeOfNormals& cone = bounds.cones[cluster];
    double tightest = std::numeric_limits<double>::infinity();
    for (uint32_t i = bounds.vertexStarts[cluster]; i < bounds.vertexStarts[cluster + 1]; ++i) {
        ++why.pointsTested;
        const glm::dvec3 vertex(input.world[bounds.vertexIds[i]]);
        const glm::dvec3 view = eye.orthographic ? eye.direction : vertex - eye.position;
        const bool back = cone.cullable && vectorSeesBack(cone, view);
        why.pointsBack += back;
        why.vertices.push_back(vertex);
        why.vertexBack.push_back(back);
        const double length = glm::length(view);
        tightest = std::min(tightest, length > 0.0 ? glm::dot(view, cone.axis) / length : 0.0);
    }
    return tightest;
}

// The cluster's faces as the eye sees them: front, back or degenerate.
static void countFacing(const CullingInput& input, uint32_t cluster, const Eye& eye, CullExplanation& why) {
    const ClusterFaces& rows = input.bounds.faces;
    for (uint32_t i = rows.starts[cluster]; i < rows.starts[cluster + 1]; ++i) {
        switch (classifyFace(input.mesh, input.world, input.faces, rows.faces[i], eye)) {
            case Facing::Front: ++why.frontFaces; break;
            case Facing::Back: ++why.backFaces; break;
            case Facing::Degenerate: ++why.degenerateFaces; break;
        }
    }
}

CullExplanation explainCull(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    CullExplanation why;
    const ClusterBounds& bounds = input.bounds;
    const ConeOfNormals& cone = bounds.cones[cluster];
    const Sphere& sphere = bounds.spheres[cluster];
    why.exactCulled = cullCluster(input, cluster, eye, test);
    why.culled = culledInBatch(eye, test) ? cullClusters(input, eye, test)[cluster] != 0 : why.exactCulled;
    why.cullable = cone.cullable;
    why.axis = cone.axis;
    why.cosHalfAngle = cone.cosHalfAngle;
    why.halfAngleDegrees = glm::degrees(cone.halfAngle());
    why.angleBDegrees = 90.0 - why.halfAngleDegrees;
    why.threshold = cone.sinHalfAngle + kCullMargin;
    why.radius = sphere.radius;
    why.apex = bounds.apexes[cluster];
    const glm::dvec3 toCenter = sphere.center - eye.position;
    why.distance = glm::length(toCenter);
    why.view = eye.orthographic ? eye.direction : (why.distance > 0.0 ? toCenter / why.distance : glm::dvec3(0.0));
    why.viewDotAxis = glm::dot(why.view, cone.axis);
    why.eyeInsideSphere = !eye.orthographic && !(why.distance > sphere.radius);
    why.sphereAngleDegrees = why.eyeInsideSphere ? 90.0 : glm::degrees(std::asin(sphere.radius / why.distance));
    // The apex tests' view vector runs from the eye to the apex, not to the sphere's centre, and
    // their thresholds allow for the apex's rounding (in units of the unit view's dot products).
    double apexSlack = 0.0;
    if ((test == CullTest::Apex || test == CullTest::Octagon) && !eye.orthographic) {
        const glm::dvec3 toApex = why.apex - eye.position;
        const double length = glm::length(toApex);
        why.view = length > 0.0 ? toApex / length : glm::dvec3(0.0);
        why.viewDotAxis = glm::dot(why.view, cone.axis);
        apexSlack = length > 0.0 ? apexRoundingSlack(why.apex, eye.position) / length : 0.0;
        why.threshold += apexSlack;
    }
    if (test == CullTest::Sphere && !why.eyeInsideSphere && !eye.orthographic)
        why.threshold = std::cos(glm::radians(why.angleBDegrees - why.sphereAngleDegrees)) + kCullMargin;
    why.corners = aabbCorners(bounds.boxes[cluster]);
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 view = eye.orthographic ? eye.direction : why.corners[i] - eye.position;
        const double length = glm::length(view);
        why.cornerDotAxis[i] = length > 0.0 ? glm::dot(view, cone.axis) / length : 0.0;
        why.cornerBack[i] = cone.cullable && length > 0.0 && why.cornerDotAxis[i] > cone.sinHalfAngle + kCullMargin;
    }
    // The tightest point of the test: its v.V1 less the threshold (the smallest over the points).
    double tightest = why.viewDotAxis;
    if (test == CullTest::Vertices) {
        tightest = explainVertices(input, cluster, eye, why);
    } else if (test == CullTest::Aabb || test == CullTest::AabbFast) {
        why.pointsTested = 8;
        why.pointsBack = size_t(std::count(why.cornerBack.begin(), why.cornerBack.end(), true));
        tightest = *std::min_element(why.cornerDotAxis.begin(), why.cornerDotAxis.end());
    }
    const OctagonCone& octagon = bounds.octagons[cluster];
    why.octagonEdges = octagon.edges;
    for (size_t k = 0; k < 8; ++k) {
        why.edgeDotView[k] = glm::dot(octagon.edges[k], why.view);
        why.edgesBack += octagon.cullable && why.edgeDotView[k] > kCullMargin + apexSlack;
    }
    if (test == CullTest::Octagon) {
        // Each edge's g.v must pass kCullMargin: the margin is the tightest edge's.
        why.threshold = kCullMargin + apexSlack;
        tightest = octagonTightest(octagon, why.view);
    }
    why.margin = tightest - why.threshold;
    if (test == CullTest::MeshoptSphere && !eye.orthographic)
        why.margin -= why.distance > 0.0 ? why.radius / why.distance : std::numeric_limits<double>::infinity();
    // Inside the sphere, or seeing it wider than B, the sphere test compares nothing; without a cone no test does.
    const bool sphereNeverCulls = test == CullTest::Sphere && !eye.orthographic &&
                                  (why.eyeInsideSphere || !(why.angleBDegrees - why.sphereAngleDegrees > 0.0));
    if (test == CullTest::Oracle || !cone.cullable || sphereNeverCulls || (test == CullTest::Octagon && !octagon.cullable))
        why.margin = std::numeric_limits<double>::quiet_NaN();
    // The records' own tests compare their own numbers, whatever the displayed cone.
    if (readsOwnRecord(test)) why.margin = ownRecordMargin({input.mesh, input.world, input.faces, input.bounds}, cluster, eye, test);
    countFacing(input, cluster, eye, why);
    return why;
}

}  // namespace conescope
