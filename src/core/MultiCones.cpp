#include "MultiCones.h"

#include <algorithm>
#include <cmath>

#include "Culling.h"

namespace conescope {

double expectedCulledTriangles(const ConeOfNormals& cone, size_t triangles) {
    if (!cone.cullable) return 0.0;
    return double(triangles) * (1.0 - cone.sinHalfAngle) / 2.0;
}

namespace {

// Sum of expectedCulledTriangles over the groups of one assignment, cones from minimalCone.
double splitValue(const glm::dvec3* normals, const uint32_t* triangles, size_t count, const std::vector<uint8_t>& group,
                  uint32_t groups) {
    double value = 0.0;
    std::vector<glm::dvec3> members;
    for (uint32_t g = 0; g < groups; ++g) {
        members.clear();
        size_t tris = 0;
        for (size_t i = 0; i < count; ++i)
            if (group[i] == g) members.push_back(normals[i]), tris += triangles[i];
        if (!members.empty()) value += expectedCulledTriangles(minimalCone(members.data(), members.size()), tris);
    }
    return value;
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

}  // namespace

std::vector<uint8_t> splitForCones(const glm::dvec3* normals, const uint32_t* triangles, size_t count, uint32_t groups) {
    std::vector<uint8_t> single(count, 0);
    groups = uint32_t(std::min<size_t>(groups, count));
    if (groups <= 1) return single;
    std::vector<glm::dvec3> seeds = farthestSeeds(normals, count, groups);
    std::vector<uint8_t> group(count, 0);
    for (int iteration = 0; iteration < 8; ++iteration) {
        for (size_t i = 0; i < count; ++i) {
            uint8_t best = 0;
            for (uint32_t g = 1; g < groups; ++g)
                if (glm::dot(normals[i], seeds[g]) > glm::dot(normals[i], seeds[best])) best = uint8_t(g);
            group[i] = best;
        }
        std::vector<glm::dvec3> sums(groups, glm::dvec3(0.0));
        for (size_t i = 0; i < count; ++i) sums[group[i]] += double(triangles[i]) * normals[i];
        for (uint32_t g = 0; g < groups; ++g)
            if (glm::length(sums[g]) > 0.0) seeds[g] = glm::normalize(sums[g]);
    }
    // Lloyd minimises spread, not culled share: keep the split only where it pays.
    return splitValue(normals, triangles, count, group, groups) > splitValue(normals, triangles, count, single, 1) ? group
                                                                                                                 : single;
}

MultiCones computeMultiCones(const Mesh& mesh, const FaceGeometry& faces, const ClusterBounds& bounds, uint32_t conesPerCluster) {
    MultiCones multi;
    multi.conesPerCluster = conesPerCluster;
    multi.groupStarts.push_back(0);
    std::vector<glm::dvec3> normals, members;
    std::vector<uint32_t> tris, ids;
    for (size_t c = 0; c < bounds.count(); ++c) {
        normals.clear();
        tris.clear();
        ids.clear();
        std::vector<uint32_t> degenerate;  // no normal: kept in group 0, where its faces stay visible
        for (uint32_t i = bounds.faces.starts[c]; i < bounds.faces.starts[c + 1]; ++i) {
            const uint32_t f = bounds.faces.faces[i];
            if (faces.degenerate[f]) { degenerate.push_back(f); continue; }
            normals.push_back(faces.normals[f]);
            tris.push_back(uint32_t(mesh.faceSize(f) - 2));
            ids.push_back(f);
        }
        const std::vector<uint8_t> group = normals.empty() ? std::vector<uint8_t>{}
                                                           : splitForCones(normals.data(), tris.data(), normals.size(), conesPerCluster);
        for (uint32_t g = 0; g < conesPerCluster; ++g) {
            members.clear();
            uint32_t groupTris = 0;
            for (size_t i = 0; i < ids.size(); ++i)
                if (group[i] == g) multi.faces.push_back(ids[i]), members.push_back(normals[i]), groupTris += tris[i];
            ConeOfNormals cone = minimalCone(members.data(), members.size());
            if (g == 0 && !degenerate.empty()) {
                // A degenerate face has no side: conservative tests never cull its group.
                for (uint32_t f : degenerate) multi.faces.push_back(f), groupTris += uint32_t(mesh.faceSize(f) - 2);
                cone = ConeOfNormals{};
            }
            if (members.empty()) cone = ConeOfNormals{};  // an empty group culls nothing and costs nothing
            multi.cones.push_back(cone);
            multi.groupTriangles.push_back(groupTris);
            multi.groupStarts.push_back(uint32_t(multi.faces.size()));
        }
    }
    return multi;
}

bool subGroupSeesBack(const ConeOfNormals& cone, const Sphere& sphere, const Eye& eye) {
    if (eye.orthographic) return viewDirectionSeesBack(cone, eye.direction);
    return sphereSeesBack(cone, sphere, eye.position);
}

std::vector<uint8_t> cullSubGroups(const ClusterBounds& bounds, const MultiCones& multi, const Eye& eye) {
    std::vector<uint8_t> culled(multi.groupCount(), 0);
    const uint32_t k = multi.conesPerCluster;
    for (size_t g = 0; g < culled.size(); ++g) culled[g] = subGroupSeesBack(multi.cones[g], bounds.spheres[g / k], eye) ? 1 : 0;
    return culled;
}

size_t culledTriangles(const MultiCones& multi, const std::vector<uint8_t>& culledGroups) {
    size_t total = 0;
    for (size_t g = 0; g < culledGroups.size(); ++g)
        if (culledGroups[g]) total += multi.groupTriangles[g];
    return total;
}

}  // namespace conescope
