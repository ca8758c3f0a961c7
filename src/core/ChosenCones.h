// The default cone (ConeMethod::Chosen): per cluster, of the cones the tool offers (minimal,
// meshoptimizer's, average, seed-sphere), the one whose octagon test culls the cluster from the
// most eyes of the standard orbit. Each candidate is a whole cone with its own apex and octagon,
// so the choice stays conservative and the record keeps its size; it only picks, per cluster,
// which of the offered records to store.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "Cones.h"
#include "Mesh.h"
#include "OctagonCones.h"

namespace conescope {

enum class ConeMethod;  // ClusterBounds.h

// The eyes the choice counts: on the standard orbit's sphere (kStandardOrbitDistance, Views.h)
// around the object's box, kChoiceEyes of them. Dense, so that the choice follows the share of that
// sphere each record culls, not where a few eyes happen to fall.
constexpr size_t kChoiceEyes = 4096;

// Their directions in groups of neighbours, and each group in subgroups, so that a record is
// compared with a whole group or subgroup at once where it can be. The same for every object.
struct DirectionGroups {
    std::vector<glm::dvec3> directions;  // unit, by subgroup
    std::vector<uint32_t> groupStarts;   // the subgroups of each group, with a trailing end
    std::vector<glm::dvec3> groupCenters;
    std::vector<double> groupReach;      // every direction of the group within this of its centre
    std::vector<uint32_t> subStarts;     // the directions of each subgroup, with a trailing end
    std::vector<glm::dvec3> subCenters;
    std::vector<double> subReach;
};

struct ChoiceEyes {
    glm::dvec3 center{0.0};
    double radius = 1.0;                      // the sphere's
    const DirectionGroups* groups = nullptr;
    // The eye of the i-th direction, as orbitViews places it (so bit for bit its eye at kChoiceEyes
    // views); made where asked, as few are.
    glm::dvec3 position(size_t i) const { return center + radius * groups->directions[i]; }
};
ChoiceEyes choiceEyes(const Aabb& objectBox);

// The eyes of `eyes` from which the octagon test (CullTest::Octagon) culls this octagon and apex:
// exactly the count of eyes one by one.
size_t eyesCulled(const OctagonCone& octagon, const glm::dvec3& apex, const ChoiceEyes& eyes);

struct ChosenCone {
    ConeMethod method;            // whose axis (and apex) it is
    ConeOfNormals cone;
    glm::dvec3 apex{0.0};
    OctagonCone octagon;
    size_t eyesCulled = 0;        // of the choice's eyes
};

// One offered cone of a cluster with the apex its method places (boundsOfClusters makes them).
struct OfferedCone {
    ConeMethod method;
    ConeOfNormals cone;
    glm::dvec3 apex{0.0};
};

// The choice among them for a cluster with these normals. The most eyes culled wins; then the
// octagon's share of far views (octagonCullShare); then the earlier candidate.
ChosenCone chooseCone(const OfferedCone* offered, size_t count, const std::vector<glm::dvec3>& normals, const ChoiceEyes& eyes);

}  // namespace conescope
