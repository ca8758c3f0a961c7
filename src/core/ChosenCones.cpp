#include "ChosenCones.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "CullTest.h"
#include "Views.h"

namespace conescope {

namespace {

struct Choice {
    ChosenCone best;
    double share = -1.0;  // the best's octagonCullShare
    bool any = false;
};

// Keeps the candidate that culls from more eyes, or from as many with a larger share of far views.
void consider(Choice& choice, ChosenCone&& candidate, const ChoiceEyes& eyes) {
    candidate.eyesCulled = eyesCulled(candidate.octagon, candidate.apex, eyes);
    if (choice.any && candidate.eyesCulled < choice.best.eyesCulled) return;
    const double share = octagonCullShare(candidate.octagon);
    if (choice.any && candidate.eyesCulled == choice.best.eyesCulled && !(share > choice.share)) return;
    choice.best = std::move(candidate);
    choice.share = share;
    choice.any = true;
}

// One offered cone with its apex: its least-area octagon, then each of the sixteen turns.
void considerCone(Choice& choice, ConeMethod method, const ConeOfNormals& cone, const glm::dvec3& apex,
                  const std::vector<glm::dvec3>& normals, const ChoiceEyes& eyes) {
    consider(choice, ChosenCone{method, -1, cone, apex, octagonCone(cone, normals.data(), normals.size()), 0}, eyes);
    if (!cone.cullable) return;
    for (int turn = 0; turn < kOctagonTurns; ++turn) {
        const std::optional<OctagonStrips> strips = octagonStripsOf(cone.axis, octagonTurnAngle(turn), normals.data(), normals.size());
        if (strips) consider(choice, ChosenCone{method, turn, cone, apex, octagonFromStrips(*strips), 0}, eyes);
    }
}

}  // namespace

namespace {

// The spiral's directions in groups of neighbours (each with its nearest of kGroups spiral
// directions): the same for every object, so made once.
struct DirectionGroups {
    std::vector<glm::dvec3> directions;
    std::vector<uint32_t> starts;
    std::vector<glm::dvec3> centers;
    std::vector<double> reach;
};

DirectionGroups groupDirections() {
    constexpr size_t kGroups = 128;
    DirectionGroups groups;
    const std::vector<glm::dvec3> all = spiralDirections(kChoiceEyes);
    groups.centers = spiralDirections(kGroups);
    std::vector<std::vector<uint32_t>> members(kGroups);
    for (uint32_t i = 0; i < all.size(); ++i) {
        size_t nearest = 0;
        for (size_t g = 1; g < kGroups; ++g)
            if (glm::dot(all[i], groups.centers[g]) > glm::dot(all[i], groups.centers[nearest])) nearest = g;
        members[nearest].push_back(i);
    }
    groups.starts.push_back(0);
    for (size_t g = 0; g < kGroups; ++g) {
        double reach = 0.0;
        for (const uint32_t i : members[g]) {
            groups.directions.push_back(all[i]);
            reach = std::max(reach, glm::length(all[i] - groups.centers[g]));
        }
        groups.reach.push_back(reach * (1.0 + 1e-9) + 1e-12);
        groups.starts.push_back(uint32_t(groups.directions.size()));
    }
    return groups;
}

}  // namespace

ChoiceEyes choiceEyes(const Aabb& objectBox) {
    static const DirectionGroups groups = groupDirections();
    ChoiceEyes eyes;
    eyes.center = glm::dvec3(objectBox.center());
    eyes.radius = kStandardOrbitDistance * objectBox.halfDiagonal();
    eyes.positions.reserve(groups.directions.size());
    // As orbitViews places them, so that a run at kChoiceEyes views looks from these very eyes.
    for (const glm::dvec3& direction : groups.directions) eyes.positions.push_back(eyes.center + eyes.radius * direction);
    eyes.groupStarts = groups.starts;
    eyes.groupCenters = groups.centers;
    eyes.groupReach = groups.reach;
    return eyes;
}

size_t eyesCulled(const OctagonCone& octagon, const glm::dvec3& apex, const ChoiceEyes& eyes) {
    if (!octagon.cullable) return 0;
    // Seen from the sphere's centre, an eye c + rho d is culled when g.d < g.(apex - c) / rho less the
    // test's margins for every edge g; a group whose every d is past one edge culls from none of its
    // eyes, and one whose every d clears every edge by more than the largest margin from all of them.
    const glm::dvec3 offset = (apex - eyes.center) / eyes.radius;
    const double coordinate = std::max({std::abs(apex.x), std::abs(apex.y), std::abs(apex.z),
                                        std::abs(eyes.center.x) + eyes.radius, std::abs(eyes.center.y) + eyes.radius,
                                        std::abs(eyes.center.z) + eyes.radius});
    const double margin = kCullMargin * (glm::length(offset) + 1.0) + kApexRoundingSlack * coordinate / eyes.radius +
                          1e-12 * (1.0 + glm::length(offset));
    std::array<double, 8> limit{};
    for (size_t k = 0; k < 8; ++k) limit[k] = glm::dot(octagon.edges[k], offset);
    size_t culled = 0;
    for (size_t g = 0; g + 1 < eyes.groupStarts.size(); ++g) {
        bool none = false, all = true;
        for (size_t k = 0; k < 8 && !none; ++k) {
            const double along = glm::dot(octagon.edges[k], eyes.groupCenters[g]);
            none = along - eyes.groupReach[g] >= limit[k] + margin;
            all = all && along + eyes.groupReach[g] < limit[k] - margin;
        }
        if (none) continue;
        if (all) {
            culled += eyes.groupStarts[g + 1] - eyes.groupStarts[g];
            continue;
        }
        for (uint32_t i = eyes.groupStarts[g]; i < eyes.groupStarts[g + 1]; ++i)
            culled += octagonSeesBack(octagon, apex - eyes.positions[i], apexRoundingSlack(apex, eyes.positions[i]));
    }
    return culled;
}

ChosenCone chooseCone(const OfferedCone* offered, size_t count, const std::vector<glm::dvec3>& normals, const ChoiceEyes& eyes) {
    Choice choice;
    for (size_t i = 0; i < count; ++i) considerCone(choice, offered[i].method, offered[i].cone, offered[i].apex, normals, eyes);
    return choice.best;
}

}  // namespace conescope
