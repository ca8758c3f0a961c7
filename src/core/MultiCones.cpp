#include "MultiCones.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "Culling.h"
#include "Parallel.h"

namespace conescope {

double expectedCulledTriangles(const ConeOfNormals& cone, size_t triangles) {
    if (!cone.cullable) return 0.0;
    return double(triangles) * (1.0 - cone.sinHalfAngle) / 2.0;
}

namespace {

// One sub-group's members and cone during the split.
struct SplitGroup {
    std::vector<size_t> members;  // indices into the cluster's normals
    size_t triangles = 0;
    ConeOfNormals cone;
    double value = 0.0;           // expectedCulledTriangles
};

void measureGroup(SplitGroup& group, const glm::dvec3* normals, const uint32_t* triangles) {
    std::vector<glm::dvec3> tips;
    group.triangles = 0;
    for (size_t i : group.members) tips.push_back(normals[i]), group.triangles += triangles[i];
    group.cone = tips.empty() ? ConeOfNormals{} : minimalCone(tips.data(), tips.size());
    group.value = tips.empty() ? 0.0 : expectedCulledTriangles(group.cone, group.triangles);
}

std::vector<SplitGroup> groupsOf(const glm::dvec3* normals, const uint32_t* triangles, size_t count,
                                 const std::vector<uint8_t>& group, uint32_t groups) {
    std::vector<SplitGroup> split(groups);
    for (size_t i = 0; i < count; ++i) split[group[i]].members.push_back(i);
    for (SplitGroup& g : split) measureGroup(g, normals, triangles);
    return split;
}

double totalValue(const std::vector<SplitGroup>& split) {
    double value = 0.0;
    for (const SplitGroup& g : split) value += g.value;
    return value;
}

// Lloyd from `seeds`: each normal to the seed it leans on most, each seed the triangle-weighted mean.
std::vector<uint8_t> lloyd(const glm::dvec3* normals, const uint32_t* triangles, size_t count, std::vector<glm::dvec3> seeds) {
    const uint32_t groups = uint32_t(seeds.size());
    std::vector<uint8_t> group(count, 0);
    for (int iteration = 0; iteration < 8; ++iteration) {
        bool moved = iteration == 0;
        for (size_t i = 0; i < count; ++i) {
            uint8_t best = 0;
            for (uint32_t g = 1; g < groups; ++g)
                if (glm::dot(normals[i], seeds[g]) > glm::dot(normals[i], seeds[best])) best = uint8_t(g);
            moved |= group[i] != best;
            group[i] = best;
        }
        if (!moved) break;  // settled: the means would not move again
        std::vector<glm::dvec3> sums(groups, glm::dvec3(0.0));
        for (size_t i = 0; i < count; ++i) sums[group[i]] += double(triangles[i]) * normals[i];
        for (uint32_t g = 0; g < groups; ++g)
            if (glm::length(sums[g]) > 0.0) seeds[g] = glm::normalize(sums[g]);
    }
    return group;
}

// Seeds spread over the normals: each next seed the normal least aligned with all seeds so far.
std::vector<glm::dvec3> farthestSeeds(const glm::dvec3* normals, size_t count, uint32_t groups) {
    std::vector<glm::dvec3> seeds{normals[0]};
    while (seeds.size() < groups) {
        size_t best = 0;
        double bestAlign = 2.0;
        for (size_t i = 0; i < count; ++i) {
            double align = -2.0;
            for (const glm::dvec3& s : seeds) align = std::max(align, glm::dot(normals[i], s));
            if (align < bestAlign) bestAlign = align, best = i;
        }
        seeds.push_back(normals[best]);
    }
    return seeds;
}

// A sub-group's value with its members and `extra`, in the cone around its present axis: a lower
// bound (the minimal cone is no wider), without a minimal cone per candidate move.
double valueWithAroundAxis(const SplitGroup& group, const glm::dvec3* normals, const uint32_t* triangles, size_t extra,
                           std::vector<glm::dvec3>& tips) {
    tips.clear();
    for (size_t i : group.members) tips.push_back(normals[i]);
    tips.push_back(normals[extra]);
    return expectedCulledTriangles(coneAroundAxis(group.cone.axis, tips.data(), tips.size()), group.triangles + triangles[extra]);
}

// A sub-group's value without its member `face`, in its minimal cone.
double valueWithout(const SplitGroup& group, const glm::dvec3* normals, const uint32_t* triangles, size_t face,
                    std::vector<glm::dvec3>& tips) {
    tips.clear();
    for (size_t i : group.members)
        if (i != face) tips.push_back(normals[i]);
    return expectedCulledTriangles(minimalCone(tips.data(), tips.size()), group.triangles - triangles[face]);
}

// Moves faces on a sub-group's cone boundary (the normals that hold its half-angle up) to the
// sub-group where the sum gains most, while a move gains: Lloyd balances directions, while the
// culled share is decided by each cone's widest normal. The receiving cone is weighed around its
// axis (a lower bound, so every move taken gains) and both minimal cones made again after a move.
// A move must gain this share of the cluster's triangles: smaller gains cost a move's minimal cones
// for almost nothing (docs/benchmarks.md, the split's cost).
constexpr double kSmallestMoveGain = 1e-3;

void refineOnBoundaries(const glm::dvec3* normals, const uint32_t* triangles, size_t count, std::vector<SplitGroup>& split, int passes) {
    // A move changes two sub-groups: each value is kept with the version of the sub-group it was
    // weighed in, and weighed again only once that sub-group has changed.
    const size_t groups = split.size();
    constexpr uint32_t kNever = ~0u;
    std::vector<uint32_t> version(groups, 0), withoutVersion(count * groups, kNever), withVersion(count * groups, kNever);
    std::vector<double> withoutValue(count * groups), withValue(count * groups);
    std::vector<glm::dvec3> tips;
    double triangleCount = 0.0;
    for (const SplitGroup& g : split) triangleCount += double(g.triangles);
    const double smallestGain = std::max(1e-9, kSmallestMoveGain * triangleCount);
    for (int pass = 0; pass < passes; ++pass) {
        double bestGain = smallestGain;
        size_t bestFrom = 0, bestTo = 0, bestFace = 0;
        for (size_t from = 0; from < groups; ++from) {
            const SplitGroup& source = split[from];
            if (!source.cone.cullable || source.members.size() < 2) continue;
            for (size_t i : source.members) {
                if (glm::dot(normals[i], source.cone.axis) > source.cone.cosHalfAngle + 1e-6) continue;  // inside, not holding it
                const size_t own = i * groups + from;
                if (withoutVersion[own] != version[from])
                    withoutValue[own] = valueWithout(source, normals, triangles, i, tips), withoutVersion[own] = version[from];
                for (size_t to = 0; to < groups; ++to) {
                    if (to == from || split[to].members.empty()) continue;
                    const size_t key = i * groups + to;
                    if (withVersion[key] != version[to])
                        withValue[key] = valueWithAroundAxis(split[to], normals, triangles, i, tips), withVersion[key] = version[to];
                    const double gain = withoutValue[own] + withValue[key] - source.value - split[to].value;
                    if (gain > bestGain) bestGain = gain, bestFrom = from, bestTo = to, bestFace = i;
                }
            }
        }
        if (bestGain <= smallestGain) return;
        std::vector<size_t>& members = split[bestFrom].members;
        members.erase(std::find(members.begin(), members.end(), bestFace));
        split[bestTo].members.push_back(bestFace);
        measureGroup(split[bestFrom], normals, triangles);
        measureGroup(split[bestTo], normals, triangles);
        ++version[bestFrom], ++version[bestTo];
    }
}

// Clusters this small are split by trying every split: each as a restricted growth string (face 0
// in group 0, each next face in a group used before or the next new one), so no split is tried
// twice under another numbering. At most 2,048 splits for 2 groups, 4,140 for 4 or 8.
size_t exactSplitFacesAtMost(uint32_t groups) { return groups <= 2 ? 12 : 8; }

double splitValue(const glm::dvec3* normals, const uint32_t* triangles, size_t count, const std::vector<uint8_t>& label,
                  uint32_t groups, std::vector<glm::dvec3>& tips) {
    double value = 0.0;
    for (uint32_t g = 0; g < groups; ++g) {
        tips.clear();
        size_t groupTriangles = 0;
        for (size_t i = 0; i < count; ++i)
            if (label[i] == g) tips.push_back(normals[i]), groupTriangles += triangles[i];
        if (!tips.empty()) value += expectedCulledTriangles(minimalCone(tips.data(), tips.size()), groupTriangles);
    }
    return value;
}

// The split with the largest sum of expectedCulledTriangles among all of them (the first found on a
// tie, so one group where splitting gains nothing).
std::vector<uint8_t> bestSplitOfAll(const glm::dvec3* normals, const uint32_t* triangles, size_t count, uint32_t groups) {
    std::vector<uint8_t> label(count, 0), best(count, 0);
    std::vector<glm::dvec3> tips;
    double bestValue = -1.0;
    auto visit = [&](auto&& self, size_t face, uint32_t used) -> void {
        if (face == count) {
            const double value = splitValue(normals, triangles, count, label, used, tips);
            if (value > bestValue) bestValue = value, best = label;
            return;
        }
        for (uint32_t g = 0; g <= std::min(used, groups - 1); ++g) {
            label[face] = uint8_t(g);
            self(self, face + 1, std::max(used, g + 1));
        }
    };
    label[0] = 0;
    visit(visit, 1, 1);
    return best;
}

}  // namespace

std::vector<uint8_t> splitForCones(const glm::dvec3* normals, const uint32_t* triangles, size_t count, uint32_t groups,
                                   std::vector<ConeOfNormals>* cones) {
    std::vector<uint8_t> single(count, 0);
    if (cones) cones->assign(std::max<uint32_t>(groups, 1), ConeOfNormals{});
    const uint32_t requested = groups;
    groups = uint32_t(std::min<size_t>(groups, count));
    auto keep = [&](const std::vector<SplitGroup>& split) {
        if (cones)
            for (size_t g = 0; g < split.size(); ++g) (*cones)[g] = split[g].members.empty() ? ConeOfNormals{} : split[g].cone;
    };
    if (groups <= 1) {
        if (cones && count > 0 && requested > 0) keep(groupsOf(normals, triangles, count, single, 1));
        return single;
    }
    // Every split of a small cluster; else Lloyd from spread seeds, refined on the cones' boundaries.
    // Either is kept where it beats one group.
    std::vector<SplitGroup> split;
    if (count <= exactSplitFacesAtMost(groups)) {
        split = groupsOf(normals, triangles, count, bestSplitOfAll(normals, triangles, count, groups), groups);
    } else {
        split = groupsOf(normals, triangles, count, lloyd(normals, triangles, count, farthestSeeds(normals, count, groups)), groups);
        refineOnBoundaries(normals, triangles, count, split, int(2 * count));
    }
    const std::vector<SplitGroup> one = groupsOf(normals, triangles, count, single, 1);
    if (!(totalValue(split) > totalValue(one))) {
        keep(one);
        return single;
    }
    keep(split);
    std::vector<uint8_t> group(count, 0);
    for (size_t g = 0; g < split.size(); ++g)
        for (size_t i : split[g].members) group[i] = uint8_t(g);
    return group;
}

MultiCones computeMultiCones(const Mesh& mesh, const FaceGeometry& faces, const ClusterBounds& bounds, uint32_t conesPerCluster,
                             const std::vector<glm::vec3>& givenWorld) {
    const std::vector<glm::vec3> ownWorld = givenWorld.empty() ? worldPositions(mesh) : std::vector<glm::vec3>{};
    const std::vector<glm::vec3>& world = givenWorld.empty() ? ownWorld : givenWorld;
    // Each cluster's faces with a side, their normals and triangles; degenerate faces apart (no
    // normal: kept in sub-group 0, where they stay visible).
    struct ClusterFacesSplit {
        std::vector<glm::dvec3> normals;
        std::vector<uint32_t> triangles, ids, degenerate;
        std::vector<uint8_t> group;
        std::vector<ConeOfNormals> cones;  // each sub-group's minimal cone, from the split
    };
    std::vector<ClusterFacesSplit> clusters(bounds.count());
    forEachInParallel(bounds.count(), [&](size_t c, size_t) {
        ClusterFacesSplit& split = clusters[c];
        for (uint32_t i = bounds.faces.starts[c]; i < bounds.faces.starts[c + 1]; ++i) {
            const uint32_t f = bounds.faces.faces[i];
            if (faces.degenerate[f]) { split.degenerate.push_back(f); continue; }
            split.normals.push_back(faces.normals[f]);
            split.triangles.push_back(uint32_t(mesh.faceSize(f) - 2));
            split.ids.push_back(f);
        }
        if (!split.normals.empty())
            split.group = splitForCones(split.normals.data(), split.triangles.data(), split.normals.size(), conesPerCluster, &split.cones);
    });
    MultiCones multi;
    multi.conesPerCluster = conesPerCluster;
    multi.groupStarts.push_back(0);
    for (size_t c = 0; c < clusters.size(); ++c) {
        const ClusterFacesSplit& split = clusters[c];
        const glm::dvec3 center = bounds.spheres[c].center;
        for (uint32_t g = 0; g < conesPerCluster; ++g) {
            const uint32_t start = uint32_t(multi.faces.size());
            uint32_t groupTris = 0;
            for (size_t i = 0; i < split.ids.size(); ++i)
                if (split.group[i] == g) multi.faces.push_back(split.ids[i]), groupTris += split.triangles[i];
            const size_t members = multi.faces.size() - start;
            // An empty group culls nothing and costs nothing.
            ConeOfNormals cone = members == 0 ? ConeOfNormals{} : split.cones[g];
            glm::dvec3 apex = coneApex(cone, center, mesh, world, faces, multi.faces.data() + start, members);
            if (g == 0 && !split.degenerate.empty()) {
                // A degenerate face has no side: conservative tests never cull its group.
                for (uint32_t f : split.degenerate) multi.faces.push_back(f), groupTris += uint32_t(mesh.faceSize(f) - 2);
                cone = ConeOfNormals{};
                apex = center;
            }
            multi.cones.push_back(cone);
            multi.apexes.push_back(apex);
            multi.groupTriangles.push_back(groupTris);
            multi.groupStarts.push_back(uint32_t(multi.faces.size()));
        }
    }
    return multi;
}

bool subGroupSeesBack(const ConeOfNormals& cone, const glm::dvec3& apex, const Eye& eye) {
    if (eye.orthographic) return viewDirectionSeesBack(cone, eye.direction);
    return apexSeesBack(cone, apex, eye.position);
}

std::vector<uint8_t> cullSubGroups(const std::vector<ConeOfNormals>& cones, const std::vector<glm::dvec3>& apexes, const Eye& eye) {
    std::vector<uint8_t> culled(cones.size(), 0);
    for (size_t g = 0; g < culled.size(); ++g) culled[g] = subGroupSeesBack(cones[g], apexes[g], eye) ? 1 : 0;
    return culled;
}

std::vector<uint8_t> cullSubGroups(const ClusterBounds&, const MultiCones& multi, const Eye& eye) {
    return cullSubGroups(multi.cones, multi.apexes, eye);
}

ClusterBatch subGroupBatch(const std::vector<ConeOfNormals>& cones, const std::vector<glm::dvec3>& apexes) {
    ClusterBounds groups;
    groups.cones = cones;
    groups.apexes = apexes;
    for (const glm::dvec3& apex : apexes) groups.spheres.push_back(Sphere{apex, 0.0});  // only its slack is read
    groups.octagons.assign(cones.size(), OctagonCone{});
    return makeClusterBatch(groups);
}

std::vector<uint8_t> cullSubGroupsBatched(const ClusterBatch& batch, const std::vector<ConeOfNormals>& cones,
                                          const std::vector<glm::dvec3>& apexes, const Eye& eye) {
    if (eye.orthographic) return cullSubGroups(cones, apexes, eye);
    std::vector<uint8_t> culled(batch.count, 0);
    cullApexBatch(batch, eye.position, culled.data());
    return culled;
}

size_t multiConeRecordBytes(uint32_t conesPerCluster, size_t maxClusterTriangles, bool compact) {
    // The K - 1 offsets are bit fields just wide enough for the largest cluster, packed together.
    size_t bitsPerOffset = 1;
    while ((size_t(1) << bitsPerOffset) <= maxClusterTriangles) ++bitsPerOffset;
    const size_t offsets = ((conesPerCluster - 1) * bitsPerOffset + 7) / 8;
    const size_t bytes = compact ? 8 + 5 * conesPerCluster + offsets : 16 + 20 * conesPerCluster + offsets;
    return (bytes + 3) / 4 * 4;
}

namespace {

// The sphere as 16-bit fixed point within the box (one step: the box's largest side / 65535), its
// radius in steps of the box's diagonal / 65535, both decoded: the centre's rounding is added to
// the radius before it is rounded up, so the decoded sphere holds the original.
Sphere compactSphere(const Sphere& sphere, const Aabb& box) {
    const glm::dvec3 origin(box.min);
    const glm::dvec3 extent = glm::dvec3(box.max) - origin;
    const double step = std::max({extent.x, extent.y, extent.z, 1e-30}) / 65535.0;
    const double radiusStep = std::max(glm::length(extent), 1e-30) / 65535.0;
    Sphere decoded;
    for (int i = 0; i < 3; ++i)
        decoded.center[i] = origin[i] + step * std::clamp(std::round((sphere.center[i] - origin[i]) / step), 0.0, 65535.0);
    const double needed = (sphere.radius + glm::length(sphere.center - decoded.center)) * (1.0 + 1e-12);
    decoded.radius = radiusStep * std::ceil(needed / radiusStep);
    if (needed / radiusStep > 65535.0) decoded.radius = std::numeric_limits<double>::infinity();  // cannot be stored: never culls
    return decoded;
}

// The cone around the 8-bit rounding of `cone`'s axis holding every normal of the sub-group, its
// sin(alpha) rounded up to a multiple of 1/254 (255 stores "never").
ConeOfNormals compactCone(const ConeOfNormals& cone, const FaceGeometry& faces, const uint32_t* groupFaces, size_t count) {
    if (!cone.cullable) return ConeOfNormals{};
    const glm::dvec3 rounded = glm::round(cone.axis * 127.0) / 127.0;
    std::vector<glm::dvec3> normals;
    for (size_t i = 0; i < count; ++i) normals.push_back(faces.normals[groupFaces[i]]);
    const ConeOfNormals around = coneAroundAxis(rounded, normals.data(), normals.size());
    if (!around.cullable) return ConeOfNormals{};
    const double sinSteps = std::ceil(around.sinHalfAngle * 254.0 * (1.0 + 1e-12));
    if (sinSteps >= 254.0) return ConeOfNormals{};
    ConeOfNormals decoded;
    decoded.axis = around.axis;
    decoded.sinHalfAngle = sinSteps / 254.0;
    decoded.cosHalfAngle = std::sqrt(1.0 - decoded.sinHalfAngle * decoded.sinHalfAngle);
    decoded.cullable = true;
    return decoded;
}

// The apex on `cone`'s decoded axis behind the decoded centre, at least as far back as the float
// apex `apex` is from every face plane: n.(c - a) / n.V over the sub-group's normals, stored as
// s = t cos(alpha) / r in 1/255 steps rounded up; s = 1 is the sphere test's apex, behind every plane
// of faces in the sphere with normals in the cone, so t never needs more.
glm::dvec3 compactApex(const ConeOfNormals& cone, const Sphere& sphere, const glm::dvec3& apex, const FaceGeometry& faces,
                       const uint32_t* groupFaces, size_t count) {
    double behind = 0.0;
    for (size_t i = 0; i < count; ++i) {
        const glm::dvec3& n = faces.normals[groupFaces[i]];
        behind = std::max(behind, glm::dot(n, sphere.center - apex) / glm::dot(n, cone.axis));
    }
    const double scale = sphere.radius / cone.cosHalfAngle;
    const double steps = std::min(255.0, std::ceil((behind + 1e-12 * sphere.radius) / scale * 255.0 * (1.0 + 1e-9)));
    return sphere.center - cone.axis * (scale * steps / 255.0);
}

}  // namespace

CompactMultiCones compactMultiCones(const FaceGeometry& faces, const ClusterBounds& bounds, const MultiCones& multi,
                                    const Aabb& meshBox) {
    CompactMultiCones compact;
    for (const Sphere& sphere : bounds.spheres) compact.spheres.push_back(compactSphere(sphere, meshBox));
    for (size_t g = 0; g < multi.groupCount(); ++g) {
        const uint32_t* groupFaces = multi.faces.data() + multi.groupStarts[g];
        const size_t count = multi.groupStarts[g + 1] - multi.groupStarts[g];
        const Sphere& sphere = compact.spheres[g / multi.conesPerCluster];
        ConeOfNormals cone = compactCone(multi.cones[g], faces, groupFaces, count);
        if (!std::isfinite(sphere.radius)) cone = ConeOfNormals{};  // no sphere to place the apex from
        compact.cones.push_back(cone);
        compact.apexes.push_back(cone.cullable ? compactApex(cone, sphere, multi.apexes[g], faces, groupFaces, count) : sphere.center);
    }
    return compact;
}

size_t culledTriangles(const MultiCones& multi, const std::vector<uint8_t>& culledGroups) {
    size_t total = 0;
    for (size_t g = 0; g < culledGroups.size(); ++g)
        if (culledGroups[g]) total += multi.groupTriangles[g];
    return total;
}

SubGroupRecord subGroupRecord(const MultiCones& multi, std::vector<ConeOfNormals> cones, const std::vector<Sphere>& spheres,
                              const std::vector<glm::dvec3>* apexes) {
    SubGroupRecord record;
    record.multi = &multi;
    record.cones = std::move(cones);
    record.apexes = apexes ? *apexes : multi.apexes;
    record.spheres = &spheres;
    record.batch = subGroupBatch(record.cones, record.apexes);
    return record;
}

SubGroupCulling countSubGroupCulling(const SubGroupRecord& record, const std::vector<Facing>& facing, const Eye& eye,
                                     const std::vector<uint8_t>& clusters) {
    const MultiCones& multi = *record.multi;
    const std::vector<uint8_t> culled = cullSubGroupsBatched(record.batch, record.cones, record.apexes, eye);
    SubGroupCulling counted;
    for (size_t g = 0; g < culled.size(); ++g) {
        if (!culled[g] || (!clusters.empty() && !clusters[g / multi.conesPerCluster])) continue;
        counted.trianglesCulled += multi.groupTriangles[g];
        for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i)
            if (facing[multi.faces[i]] != Facing::Back) {
                ++counted.falseCulls;
                break;
            }
    }
    return counted;
}

}  // namespace conescope
