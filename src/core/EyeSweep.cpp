#include "EyeSweep.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "BatchCulling.h"

namespace conescope {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Eyes on a circle around `centre` in the plane of `axis` and `across`: at angle theta the view
// direction (from the eye to the centre) is cos(theta) axis + sin(theta) across.
struct Arc {
    glm::dvec3 centre{0.0}, axis{0.0, 0.0, 1.0}, across{1.0, 0.0, 0.0};
    double distance = 1.0;
    glm::dvec3 eye(double degrees) const {
        const double theta = degrees * kPi / 180.0;
        return centre - distance * (std::cos(theta) * axis + std::sin(theta) * across);
    }
};

glm::dvec3 perpendicularTo(const glm::dvec3& axis) {
    const glm::dvec3 other = std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::normalize(glm::cross(axis, other));
}

}  // namespace

EyeSweep sweepAcrossCull(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings, uint32_t cluster,
                         const glm::dvec3& position, size_t frames, double spanDegrees) {
    if (frames < 2) throw std::invalid_argument("a sweep needs at least 2 frames");
    const ClusterBounds& bounds = clusters.bounds;
    if (cluster >= bounds.count())
        throw std::invalid_argument("cluster " + std::to_string(cluster) + " does not exist (" + std::to_string(bounds.count()) + " clusters)");
    const ConeOfNormals& cone = bounds.cones[cluster];
    if (!cone.cullable)
        throw std::invalid_argument("cluster " + std::to_string(cluster) + " has no cone: its normals span more than a half-space, so no eye culls it");

    const ClusterBatch batch = makeClusterBatch(bounds);
    CullingInput input = cullingInput(prepared, clusters);
    input.batch = &batch;
    const CullTest test = displayedTest(settings);
    // The product's decision, as the lesson and the statistics take it.
    auto culledAt = [&](const glm::dvec3& eyePosition) {
        const Eye eye = eyeAt(settings, eyePosition, prepared.box);
        return culledInBatch(eye, test) ? cullClusters(input, eye, test)[cluster] != 0 : cullCluster(input, cluster, eye, test);
    };

    Arc arc;
    arc.axis = glm::normalize(cone.axis);
    // An orthographic eye looks at the mesh centre from wherever it is: the arc turns around that.
    arc.centre = settings.orthographic ? glm::dvec3(prepared.box.center()) : bounds.spheres[cluster].center;
    const glm::dvec3 towards = arc.centre - position;
    const glm::dvec3 off = towards - glm::dot(towards, arc.axis) * arc.axis;
    arc.across = glm::length(off) > 1e-9 * std::max(glm::length(towards), 1e-300) ? glm::normalize(off) : perpendicularTo(arc.axis);
    const double now = glm::length(towards) > 0.0 ? glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(towards), arc.axis), -1.0, 1.0)))
                                                  : 90.0;
    const double reach = std::max(bounds.spheres[cluster].radius, double(prepared.box.halfDiagonal()) * 1e-6);
    const double start = std::max(glm::length(towards), 1.5 * reach);

    // The flip nearest the eye's own angle, on the nearest arc that has one, to a millionth of a degree.
    double boundary = -1.0;
    for (double scale = 1.0; scale <= 16.0 && boundary < 0.0; scale *= 2.0) {
        arc.distance = start * scale;
        bool previous = culledAt(arc.eye(0.0));
        for (int degree = 1; degree <= 180; ++degree) {
            const bool current = culledAt(arc.eye(degree));
            if (current != previous) {
                double inside = degree - 1, outside = degree;
                for (int i = 0; i < 30; ++i) {
                    const double middle = 0.5 * (inside + outside);
                    (culledAt(arc.eye(middle)) == previous ? inside : outside) = middle;
                }
                const double found = 0.5 * (inside + outside);
                if (boundary < 0.0 || std::abs(found - now) < std::abs(boundary - now)) boundary = found;
            }
            previous = current;
        }
    }
    if (boundary < 0.0)
        throw std::invalid_argument("no eye on the arcs around cluster " + std::to_string(cluster) + " (up to 16 times the eye's distance) is culled by " +
                                    toString(test));

    EyeSweep sweep;
    sweep.boundaryDegrees = boundary;
    sweep.centre = arc.centre;
    sweep.distance = arc.distance;
    const double low = std::max(0.0, boundary - spanDegrees), high = std::min(180.0, boundary + spanDegrees);
    // From the eye's side of the boundary to the other.
    sweep.startDegrees = now <= boundary ? low : high;
    sweep.endDegrees = now <= boundary ? high : low;
    const double step = (sweep.endDegrees - sweep.startDegrees) / double(frames - 1);
    for (size_t k = 0; k < frames; ++k) {
        double degrees = sweep.startDegrees + step * double(k);
        // No frame on the boundary itself, where the decision is the rounding's.
        if (std::abs(degrees - boundary) < 0.01 * std::abs(step)) degrees += 0.25 * step;
        sweep.positions.push_back(arc.eye(degrees));
        sweep.culled.push_back(culledAt(sweep.positions.back()) ? 1 : 0);
    }
    return sweep;
}

}  // namespace conescope
