#include "ChosenCones.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "CullTest.h"
#include "Views.h"

namespace conescope {

namespace {

// The index of the nearest of the `count` spiral directions (spiralDirections) to a unit direction:
// the spiral runs down in y, so it is among those whose y is near the direction's.
uint32_t nearestSpiral(const glm::dvec3& direction, const std::vector<glm::dvec3>& spiral) {
    const long count = long(spiral.size()), window = long(std::sqrt(double(count)));
    const long guess = std::lround((1.0 - direction.y) * double(count) / 2.0 - 0.5);
    long nearest = std::clamp(guess, 0L, count - 1);
    for (long i = std::max(0L, guess - window); i <= std::min(count - 1, guess + window); ++i)
        if (glm::dot(direction, spiral[size_t(i)]) > glm::dot(direction, spiral[size_t(nearest)])) nearest = i;
    return uint32_t(nearest);
}

// The spiral's directions by the nearest of 512 spiral directions (subgroups), and those by the
// nearest of 64 (groups). Were a direction given a centre not quite its nearest, the reach, measured
// from the members themselves, would still hold it.
DirectionGroups groupDirections() {
    const std::vector<glm::dvec3> all = spiralDirections(kChoiceEyes);
    const std::vector<glm::dvec3> groupCenters = spiralDirections(64), subCenters = spiralDirections(512);
    std::vector<std::vector<uint32_t>> bySub(subCenters.size()), subsByGroup(groupCenters.size());
    for (uint32_t i = 0; i < all.size(); ++i) bySub[nearestSpiral(all[i], subCenters)].push_back(i);
    for (uint32_t s = 0; s < subCenters.size(); ++s) subsByGroup[nearestSpiral(subCenters[s], groupCenters)].push_back(s);
    DirectionGroups groups;
    groups.groupStarts.push_back(0);
    groups.subStarts.push_back(0);
    for (size_t g = 0; g < groupCenters.size(); ++g) {
        double groupReach = 0.0;
        for (const uint32_t s : subsByGroup[g]) {
            if (bySub[s].empty()) continue;
            double subReach = 0.0;
            for (const uint32_t i : bySub[s]) {
                groups.directions.push_back(all[i]);
                subReach = std::max(subReach, glm::length(all[i] - subCenters[s]));
                groupReach = std::max(groupReach, glm::length(all[i] - groupCenters[g]));
            }
            groups.subCenters.push_back(subCenters[s]);
            groups.subReach.push_back(subReach * (1.0 + 1e-9) + 1e-12);
            groups.subStarts.push_back(uint32_t(groups.directions.size()));
        }
        groups.groupCenters.push_back(groupCenters[g]);
        groups.groupReach.push_back(groupReach * (1.0 + 1e-9) + 1e-12);
        groups.groupStarts.push_back(uint32_t(groups.subCenters.size()));
    }
    return groups;
}

enum class Side { None, Some, All };

// Whether the octagon culls from none, some or all of the directions within `reach` of `center`:
// culled where g.d < limit_g for every edge g, with `margin` for the test's margins and rounding.
Side sideOf(const glm::dvec3& center, double reach, const OctagonCone& octagon, const std::array<double, 8>& limit, double margin) {
    bool all = true;
    for (size_t k = 0; k < 8; ++k) {
        const double along = glm::dot(octagon.edges[k], center);
        if (along - reach >= limit[k] + margin) return Side::None;
        all = all && along + reach < limit[k] - margin;
    }
    return all ? Side::All : Side::Some;
}

}  // namespace

ChoiceEyes choiceEyes(const Aabb& objectBox) {
    static const DirectionGroups groups = groupDirections();
    ChoiceEyes eyes;
    eyes.center = glm::dvec3(objectBox.center());
    eyes.radius = kStandardOrbitDistance * objectBox.halfDiagonal();
    eyes.groups = &groups;
    eyes.positions.reserve(groups.directions.size());
    // As orbitViews places them, so that a run at kChoiceEyes views looks from these very eyes.
    for (const glm::dvec3& direction : groups.directions) eyes.positions.push_back(eyes.center + eyes.radius * direction);
    return eyes;
}

size_t eyesCulled(const OctagonCone& octagon, const glm::dvec3& apex, const ChoiceEyes& eyes) {
    if (!octagon.cullable) return 0;
    // Seen from the sphere's centre, an eye c + rho d is culled when g.d < g.(apex - c) / rho less the
    // test's margins for every edge g. Only directions within the margin of a limit are tested as
    // the octagon test tests them; the margin bounds those margins and the rounding of all this.
    const glm::dvec3 offset = (apex - eyes.center) / eyes.radius;
    const double coordinate = std::max({std::abs(apex.x), std::abs(apex.y), std::abs(apex.z),
                                        std::abs(eyes.center.x) + eyes.radius, std::abs(eyes.center.y) + eyes.radius,
                                        std::abs(eyes.center.z) + eyes.radius});
    const double margin = kCullMargin * (glm::length(offset) + 1.0) + kApexRoundingSlack * coordinate / eyes.radius +
                          1e-12 * (1.0 + glm::length(offset));
    std::array<double, 8> limit{};
    for (size_t k = 0; k < 8; ++k) limit[k] = glm::dot(octagon.edges[k], offset);
    const DirectionGroups& groups = *eyes.groups;
    size_t culled = 0;
    for (size_t g = 0; g + 1 < groups.groupStarts.size(); ++g) {
        const Side group = sideOf(groups.groupCenters[g], groups.groupReach[g], octagon, limit, margin);
        if (group == Side::None) continue;
        for (uint32_t s = groups.groupStarts[g]; s < groups.groupStarts[g + 1]; ++s) {
            const Side sub = group == Side::All ? Side::All : sideOf(groups.subCenters[s], groups.subReach[s], octagon, limit, margin);
            if (sub == Side::None) continue;
            if (sub == Side::All) {
                culled += groups.subStarts[s + 1] - groups.subStarts[s];
                continue;
            }
            for (uint32_t i = groups.subStarts[s]; i < groups.subStarts[s + 1]; ++i) {
                const Side one = sideOf(groups.directions[i], 0.0, octagon, limit, margin);
                if (one == Side::All) ++culled;
                else if (one == Side::Some)
                    culled += octagonSeesBack(octagon, apex - eyes.positions[i], apexRoundingSlack(apex, eyes.positions[i]));
            }
        }
    }
    return culled;
}

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

// One offered cone with its apex and its (least-area) octagon.
void considerCone(Choice& choice, ConeMethod method, const ConeOfNormals& cone, const glm::dvec3& apex,
                  const std::vector<glm::dvec3>& normals, const ChoiceEyes& eyes) {
    consider(choice, ChosenCone{method, cone, apex, octagonCone(cone, normals.data(), normals.size()), 0}, eyes);
}

}  // namespace

ChosenCone chooseCone(const OfferedCone* offered, size_t count, const std::vector<glm::dvec3>& normals, const ChoiceEyes& eyes) {
    Choice choice;
    for (size_t i = 0; i < count; ++i) considerCone(choice, offered[i].method, offered[i].cone, offered[i].apex, normals, eyes);
    return choice.best;
}

}  // namespace conescope
