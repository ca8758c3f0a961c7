#include "ChosenCones.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "CullTest.h"
#include "Views.h"

namespace conescope {

namespace {

// A unit direction's cell on a cube around the sphere cut into n x n cells a face: its major axis
// and sign, then its place on that face. Cells of 9 x 9 lie within those of 3 x 3, so subgroups
// nest in groups; found in constant time, where a search for the nearest centre cost a millisecond
// a run (every run with the chosen cone makes these groups once).
uint32_t cubeCell(const glm::dvec3& d, uint32_t n) {
    const glm::dvec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    const double major = a[axis];
    const double u = d[(axis + 1) % 3] / major, v = d[(axis + 2) % 3] / major;
    auto index = [n](double t) { return std::min(n - 1, uint32_t(std::max(0.0, (t + 1.0) * 0.5 * double(n)))); };
    const uint32_t face = uint32_t(2 * axis + (d[axis] < 0.0 ? 1 : 0));
    return (face * n + index(u)) * n + index(v);
}

// The unit mean of some directions, and how far the farthest of them lies from it (with slack for
// the rounding of the test that trusts it).
std::pair<glm::dvec3, double> centreAndReach(const glm::dvec3* directions, size_t count) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < count; ++i) sum += directions[i];
    const glm::dvec3 centre = glm::normalize(sum);
    double reach = 0.0;
    for (size_t i = 0; i < count; ++i) reach = std::max(reach, glm::length(directions[i] - centre));
    return {centre, reach * (1.0 + 1e-9) + 1e-12};
}

// The spiral's directions by cube cells: 486 subgroups of 9 x 9 cells a face in 54 groups of 3 x 3,
// ordered by group then subgroup (one counting sort). Any grouping counts exactly (the reach is
// measured from the members); near cells prune well.
DirectionGroups groupDirections() {
    constexpr uint32_t kCells = 6 * 81;
    const std::vector<glm::dvec3> all = spiralDirections(kChoiceEyes);
    // A cell's rank in the order: its group (face, u / 3, v / 3), then its place within the group.
    auto rankOf = [](uint32_t cell) {
        const uint32_t face = cell / 81, u = cell / 9 % 9, v = cell % 9;
        return (((face * 3 + u / 3) * 3 + v / 3) * 3 + u % 3) * 3 + v % 3;
    };
    std::vector<uint32_t> rank(all.size()), starts(kCells + 1, 0);
    for (size_t i = 0; i < all.size(); ++i) ++starts[(rank[i] = rankOf(cubeCell(all[i], 9))) + 1];
    for (uint32_t r = 0; r < kCells; ++r) starts[r + 1] += starts[r];
    DirectionGroups groups;
    groups.directions.resize(all.size());
    std::vector<uint32_t> next(starts.begin(), starts.end() - 1);
    for (size_t i = 0; i < all.size(); ++i) groups.directions[next[rank[i]]++] = all[i];
    groups.groupStarts.push_back(0);
    groups.subStarts.push_back(0);
    for (uint32_t g = 0; g < kCells / 9; ++g) {
        for (uint32_t r = 9 * g; r < 9 * g + 9; ++r) {
            if (starts[r] == starts[r + 1]) continue;
            const auto [centre, reach] = centreAndReach(&groups.directions[starts[r]], starts[r + 1] - starts[r]);
            groups.subCenters.push_back(centre);
            groups.subReach.push_back(reach);
            groups.subStarts.push_back(starts[r + 1]);
        }
        if (starts[9 * g] == starts[9 * g + 9]) continue;
        const auto [centre, reach] = centreAndReach(&groups.directions[starts[9 * g]], starts[9 * g + 9] - starts[9 * g]);
        groups.groupCenters.push_back(centre);
        groups.groupReach.push_back(reach);
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
                else if (one == Side::Some) {
                    const glm::dvec3 eye = eyes.position(i);
                    culled += octagonSeesBack(octagon, apex - eye, apexRoundingSlack(apex, eye));
                }
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
