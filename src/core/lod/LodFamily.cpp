#include "LodFamily.h"

#include <stdexcept>
#include <string>

namespace conescope {

namespace {

// The clusters of `level` whose `field` (group or sourceGroup) is `group`; none for kNoGroup.
std::vector<uint32_t> clustersWith(const LodLevel& level, uint32_t LodCluster::*field, uint32_t group, uint32_t except = kNoGroup) {
    std::vector<uint32_t> found;
    if (group == kNoGroup) return found;
    for (uint32_t c = 0; c < level.place.size(); ++c)
        if (level.place[c].*field == group && c != except) found.push_back(c);
    return found;
}

}  // namespace

LodFamily lodFamilyOf(const ClusterHierarchy& hierarchy, LodClusterId id) {
    if (id.level >= hierarchy.levels.size() || id.cluster >= hierarchy.levels[id.level].place.size())
        throw std::out_of_range("lodFamilyOf: no cluster " + std::to_string(id.cluster) + " on level " + std::to_string(id.level));
    const LodLevel& level = hierarchy.levels[id.level];
    LodFamily family;
    family.cluster = id;
    family.group = level.place[id.cluster].group;
    family.sourceGroup = level.place[id.cluster].sourceGroup;
    family.groupMates = clustersWith(level, &LodCluster::group, family.group, id.cluster);
    if (id.level + 1 < hierarchy.levels.size())
        family.parents = clustersWith(hierarchy.levels[id.level + 1], &LodCluster::sourceGroup, family.group);
    if (id.level > 0) family.children = clustersWith(hierarchy.levels[id.level - 1], &LodCluster::group, family.sourceGroup);
    return family;
}

std::vector<std::vector<uint8_t>> cutClassesFrom(const ClusterHierarchy& hierarchy, const glm::dvec3& eye, const LodThreshold& threshold) {
    const std::vector<std::vector<uint8_t>> drawn = cutFrom(hierarchy, eye, threshold);
    std::vector<std::vector<uint8_t>> classes(drawn.size());
    for (size_t l = 0; l < drawn.size(); ++l)
        for (size_t c = 0; c < drawn[l].size(); ++c) {
            const LodCluster& place = hierarchy.levels[l].place[c];
            const bool coarser = projectedError(place.parentError, place.parentSphere, eye, threshold) <= threshold.value;
            classes[l].push_back(drawn[l][c] ? 0 : coarser ? 1 : 2);
        }
    return classes;
}

LodLevel levelOfCut(const ClusterHierarchy& hierarchy, const std::vector<std::vector<uint8_t>>& drawn, const Settings& settings,
                    std::vector<LodClusterId>& origin) {
    if (hierarchy.levels.empty() || drawn.size() != hierarchy.levels.size()) throw std::invalid_argument("levelOfCut: one flag list per level expected");
    origin.clear();
    std::vector<uint32_t> triangles, clusterOfTriangle;
    for (size_t l = 0; l < hierarchy.levels.size(); ++l) {
        const LodLevel& level = hierarchy.levels[l];
        const Mesh& mesh = level.prepared.mesh();
        const std::vector<uint32_t>& clusterOf = level.clusters.partition.clusterOfFace;
        // Numbered in cluster order within the level, as the level numbers them.
        std::vector<uint32_t> number(drawn[l].size(), kNoGroup);
        for (uint32_t c = 0; c < drawn[l].size(); ++c) {
            if (!drawn[l][c]) continue;
            number[c] = uint32_t(origin.size());
            origin.push_back({l, c});
        }
        // lodLevelOf numbers clusters in order of first use: faces go in cluster order so that it keeps ours.
        std::vector<std::vector<size_t>> facesOf(drawn[l].size());
        for (size_t f = 0; f < mesh.faceCount(); ++f)
            if (drawn[l][clusterOf[f]]) facesOf[clusterOf[f]].push_back(f);
        for (uint32_t c = 0; c < facesOf.size(); ++c)
            for (size_t f : facesOf[c]) {
                const uint32_t* corners = mesh.faceBegin(f);
                for (size_t i = 1; i + 1 < mesh.faceSize(f); ++i) {
                    triangles.insert(triangles.end(), {corners[0], corners[i], corners[i + 1]});
                    clusterOfTriangle.push_back(number[c]);
                }
            }
    }
    LodLevel cut = lodLevelOf(hierarchy.levels.front().prepared, triangles, clusterOfTriangle, settings);
    cut.place.reserve(origin.size());
    for (const LodClusterId& id : origin) cut.place.push_back(hierarchy.levels[id.level].place[id.cluster]);
    return cut;
}

}  // namespace conescope
