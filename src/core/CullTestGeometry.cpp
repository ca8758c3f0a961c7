#include "CullTestGeometry.h"

#include <algorithm>
#include <cmath>

namespace conescope {

namespace {

// Boundary angle of the region at distance d from its origin, or a negative value where it has none.
double regionAngle(CullTest test, bool orthographic, double sinAlpha, double cosAlpha, double radius, double d) {
    const double angleB = std::asin(std::clamp(cosAlpha, -1.0, 1.0));
    if (orthographic || test == CullTest::Apex) return angleB;
    if (test == CullTest::Sphere) return d > radius ? angleB - std::asin(radius / d) : -1.0;
    const double cosine = sinAlpha + radius / d;  // meshopt-sphere
    return cosine < 1.0 ? std::acos(cosine) : -1.0;
}

// Where the region starts: the distance at which its angle opens from zero.
double regionStart(CullTest test, bool orthographic, double sinAlpha, double cosAlpha, double radius) {
    if (orthographic || test == CullTest::Apex) return 0.0;
    if (test == CullTest::Sphere) return cosAlpha > 0.0 ? radius / cosAlpha : INFINITY;
    return sinAlpha < 1.0 ? radius / (1.0 - sinAlpha) : INFINITY;
}

}  // namespace

CullRegion cullRegion(const ClusterBounds& bounds, uint32_t cluster, CullTest test, bool orthographic, double reach,
                      size_t samples) {
    CullRegion region;
    const ConeOfNormals& cone = bounds.cones[cluster];
    const Sphere& sphere = bounds.spheres[cluster];
    const bool drawable = orthographic || test == CullTest::Apex || test == CullTest::Sphere ||
                          test == CullTest::MeshoptSphere || test == CullTest::Octagon;
    if (!cone.cullable || !drawable || test == CullTest::Oracle) return region;
    const bool fromApex = (test == CullTest::Apex || test == CullTest::Octagon) && !orthographic;
    region.origin = fromApex ? bounds.apexes[cluster] : sphere.center;
    region.direction = -cone.axis;
    if (test == CullTest::Octagon) {
        const OctagonCone& octagon = bounds.octagons[cluster];
        if (!octagon.cullable) return region;
        const std::array<glm::dvec3, 8> edges = octagonPyramidEdges(octagon);
        region.edges.assign(edges.begin(), edges.end());
        samples = std::max<size_t>(samples, 2);
        for (size_t i = 0; i < samples; ++i) {
            region.distances.push_back(reach * double(i) / double(samples - 1));
            region.angles.push_back(0.0);
        }
        return region;
    }
    const double start = regionStart(test, orthographic, cone.sinHalfAngle, cone.cosHalfAngle, sphere.radius);
    if (!(start < reach)) return region;
    samples = std::max<size_t>(samples, 2);
    for (size_t i = 0; i < samples; ++i) {
        // Denser near the start, where the sphere tests' boundary bends most.
        const double t = double(i) / double(samples - 1);
        const double d = start + (reach - start) * t * t;
        const double angle = regionAngle(test, orthographic, cone.sinHalfAngle, cone.cosHalfAngle, sphere.radius, d);
        region.distances.push_back(d);
        region.angles.push_back(std::max(angle, 0.0));
    }
    return region;
}

GaussMap gaussMapOf(const PreparedMesh& prepared, const ClusterSet& clusters, uint32_t cluster, const CullExplanation& why) {
    GaussMap map;
    const ClusterFaces& rows = clusters.bounds.faces;
    const uint32_t* faces = rows.faces.data() + rows.starts[cluster];
    const size_t count = rows.starts[cluster + 1] - rows.starts[cluster];
    for (size_t i = 0; i < count; ++i)
        if (!prepared.faces.degenerate[faces[i]]) map.normals.push_back(prepared.faces.normals[faces[i]]);
    for (ConeMethod method : allConeMethods())
        map.cones.emplace_back(method, clusterCone(prepared.mesh(), prepared.world, prepared.faces, faces, count, method,
                                                         clusters.builtWith.sphere));
    map.octagon = clusters.bounds.octagons[cluster];
    map.view = why.view;
    return map;
}

}  // namespace conescope
