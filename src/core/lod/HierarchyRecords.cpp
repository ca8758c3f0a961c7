#include "HierarchyRecords.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace conescope {

namespace {

[[noreturn]] void fail(const std::string& what) { throw HierarchyError(what); }

std::string clusterName(size_t m) { return "cluster " + std::to_string(m); }

// Spheres and errors a cut can compare: finite, the radius not negative.
void checkBound(const Sphere& sphere, double error, const std::string& who) {
    if (!std::isfinite(sphere.center.x) || !std::isfinite(sphere.center.y) || !std::isfinite(sphere.center.z) ||
        !std::isfinite(sphere.radius) || sphere.radius < 0.0)
        fail(who + ": its sphere is not finite with a radius of 0 or more");
    if (!std::isfinite(error) || error < 0.0) fail(who + ": its error " + std::to_string(error) + " is not finite and 0 or more");
}

// Whether `inner` lies in `outer`, allowing the float rounding of a file.
bool holds(const Sphere& outer, const Sphere& inner) {
    const double slack = 1e-5 * (outer.radius + glm::length(outer.center)) + 1e-30;
    return glm::length(inner.center - outer.center) + inner.radius <= outer.radius + slack;
}

// Every check of the records against one another (not yet against the mesh); the levels' count.
uint32_t checkRecords(const HierarchyRecords& records) {
    const auto& clusters = records.clusters;
    const auto& groups = records.groups;
    if (clusters.size() != records.arrays.meshlets.size())
        fail(std::to_string(clusters.size()) + " cluster records for " + std::to_string(records.arrays.meshlets.size()) + " meshlets");
    if (clusters.empty()) fail("no clusters");
    uint32_t top = 0;
    for (size_t m = 0; m < clusters.size(); ++m) {
        if (m > 0 && clusters[m].level < clusters[m - 1].level) fail(clusterName(m) + ": level " + std::to_string(clusters[m].level) + " after level " + std::to_string(clusters[m - 1].level) + " (levels come in order)");
        if (m > 0 && clusters[m].level > clusters[m - 1].level + 1) fail(clusterName(m) + ": level " + std::to_string(clusters[m].level) + " after level " + std::to_string(clusters[m - 1].level) + " (a level is missing)");
        top = std::max(top, clusters[m].level);
    }
    if (clusters[0].level != 0) fail("cluster 0: level " + std::to_string(clusters[0].level) + ", the first level is 0");
    std::vector<size_t> members(groups.size(), 0), made(groups.size(), 0);
    for (size_t g = 0; g < groups.size(); ++g) {
        checkBound(groups[g].sphere, groups[g].error, "group " + std::to_string(g));
        if (g > 0 && groups[g].level < groups[g - 1].level) fail("group " + std::to_string(g) + ": level " + std::to_string(groups[g].level) + " after level " + std::to_string(groups[g - 1].level) + " (groups come in the order of their levels)");
    }
    for (size_t m = 0; m < clusters.size(); ++m) {
        const HierarchyClusterRecord& c = clusters[m];
        const std::string who = clusterName(m);
        checkBound(c.sphere, c.error, who);
        if (c.group < -1 || c.group >= int64_t(groups.size())) fail(who + ": group " + std::to_string(c.group) + " is not a group (-1 or below " + std::to_string(groups.size()) + ")");
        if (c.refined < -1 || c.refined >= int64_t(groups.size())) fail(who + ": refined group " + std::to_string(c.refined) + " is not a group");
        if ((c.group == -1) != (c.level == top)) fail(who + (c.group == -1 ? ": no group below the top level" : ": a group at the top level"));
        if ((c.refined == -1) != (c.level == 0)) fail(who + (c.refined == -1 ? ": made from no group above level 0" : ": made from a group at level 0"));
        if (c.group >= 0) {
            const HierarchyGroupRecord& group = groups[size_t(c.group)];
            if (group.level != c.level) fail(who + ": its group " + std::to_string(c.group) + " is at level " + std::to_string(group.level) + ", not " + std::to_string(c.level));
            if (!(group.error >= c.error) || !holds(group.sphere, c.sphere))
                fail(who + ": its group " + std::to_string(c.group) + "'s error and sphere do not hold its own (the cut needs them to grow going up)");
            ++members[size_t(c.group)];
        }
        if (c.refined >= 0) {
            const HierarchyGroupRecord& source = groups[size_t(c.refined)];
            if (source.level + 1 != c.level) fail(who + ": made from group " + std::to_string(c.refined) + " at level " + std::to_string(source.level) + ", not the level below");
            if (source.error != c.error) fail(who + ": its error is not that of group " + std::to_string(c.refined) + " it was made from");
            ++made[size_t(c.refined)];
        }
    }
    for (size_t g = 0; g < groups.size(); ++g)
        if (members[g] == 0 || made[g] == 0) fail("group " + std::to_string(g) + (members[g] == 0 ? ": no cluster is in it" : ": no cluster was made from it"));
    return top + 1;
}

// A triangle as its corners turned to start at the smallest: the same key for the same triangle
// wound the same way, another for its back-to-back twin.
std::array<uint32_t, 3> orientedKey(uint32_t a, uint32_t b, uint32_t c) {
    if (b < a && b < c) return {b, c, a};
    if (c < a && c < b) return {c, a, b};
    return {a, b, c};
}

// Level 0 as the mesh itself, polygons whole, when the records' level-0 triangles are exactly its
// faces' fans (as meshletsOfPartition writes them) with each face's in one cluster: the level a
// hierarchy built from the mesh has, so a hierarchy written and read back measures the same (K-cone
// sub-groups split faces, not triangles). Empty when they are not: the level is then its triangles.
std::optional<LodLevel> levelZeroOnMesh(const PreparedMesh& prepared, const std::vector<uint32_t>& triangles,
                                        const std::vector<uint32_t>& clusterOfTriangle, size_t clusterCount, const Settings& settings) {
    const Mesh& mesh = prepared.mesh();
    std::map<std::array<uint32_t, 3>, uint32_t> faceOfTriangle;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* corners = mesh.faceBegin(f);
        for (size_t k = 1; k + 1 < mesh.faceSize(f); ++k)
            if (!faceOfTriangle.emplace(orientedKey(corners[0], corners[k], corners[k + 1]), uint32_t(f)).second) return std::nullopt;
    }
    if (faceOfTriangle.size() != clusterOfTriangle.size()) return std::nullopt;
    constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    ClusterSet given;
    given.builtWith = settings;
    given.partition.clusterCount = uint32_t(clusterCount);
    given.partition.clusterOfFace.assign(mesh.faceCount(), kNone);
    for (size_t t = 0; t < clusterOfTriangle.size(); ++t) {
        const auto found = faceOfTriangle.find(orientedKey(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]));
        if (found == faceOfTriangle.end()) return std::nullopt;
        uint32_t& cluster = given.partition.clusterOfFace[found->second];
        if (cluster != kNone && cluster != clusterOfTriangle[t]) return std::nullopt;
        cluster = clusterOfTriangle[t];
    }
    // As many triangles as fans, each on a face: a face left out means another's was given twice.
    if (std::count(given.partition.clusterOfFace.begin(), given.partition.clusterOfFace.end(), kNone) > 0) return std::nullopt;
    LodLevel level;
    level.prepared = prepared;
    level.clusters = buildClusters(prepared, settings, &given);  // the partition given, bounds as the settings make them
    return level;
}

}  // namespace

HierarchyRecords hierarchyRecordsOf(const ClusterHierarchy& hierarchy, const std::vector<uint32_t>& fileVertexOf) {
    HierarchyRecords records;
    std::vector<size_t> firstGroup;  // per level: its groups' first index
    for (const LodLevel& level : hierarchy.levels) firstGroup.push_back(records.groups.size()), records.groups.resize(records.groups.size() + level.groups);
    for (size_t l = 0; l < hierarchy.levels.size(); ++l) {
        const LodLevel& level = hierarchy.levels[l];
        MeshletArrays arrays = meshletsOfPartition(level.prepared.mesh(), level.clusters.partition);
        const uint32_t vertexBase = uint32_t(records.arrays.vertices.size()), triangleBase = uint32_t(records.arrays.triangles.size());
        for (auto meshlet : arrays.meshlets) {
            meshlet[0] += vertexBase, meshlet[1] += triangleBase;
            records.arrays.meshlets.push_back(meshlet);
        }
        for (uint32_t v : arrays.vertices) records.arrays.vertices.push_back(fileVertexOf.empty() ? v : fileVertexOf[v]);
        records.arrays.triangles.insert(records.arrays.triangles.end(), arrays.triangles.begin(), arrays.triangles.end());
        for (const LodCluster& place : level.place) {
            HierarchyClusterRecord& record = records.clusters.emplace_back();
            record.level = uint32_t(l);
            record.group = place.group == kNoGroup ? -1 : int64_t(firstGroup[l] + place.group);
            record.refined = place.sourceGroup == kNoGroup ? -1 : int64_t(firstGroup[l - 1] + place.sourceGroup);
            record.sphere = place.errorSphere;
            record.error = place.error;
            if (place.group != kNoGroup) records.groups[size_t(record.group)] = {uint32_t(l), place.parentSphere, place.parentError};
        }
    }
    return records;
}

ClusterHierarchy hierarchyFromRecords(const PreparedMesh& prepared, const HierarchyRecords& records, const Settings& settings) {
    const uint32_t levelCount = checkRecords(records);
    const Mesh& mesh = prepared.mesh();
    const auto& arrays = records.arrays;
    std::vector<uint32_t> firstGroup(levelCount + 1, uint32_t(records.groups.size()));
    for (size_t g = records.groups.size(); g-- > 0;) firstGroup[records.groups[g].level] = uint32_t(g);
    for (uint32_t l = levelCount; l-- > 0;) firstGroup[l] = std::min(firstGroup[l], firstGroup[l + 1]);
    ClusterHierarchy hierarchy;
    hierarchy.settings = settings;
    size_t m = 0;
    for (uint32_t l = 0; l < levelCount; ++l) {
        std::vector<uint32_t> triangles, clusterOfTriangle;
        std::vector<LodCluster> place;
        for (; m < records.clusters.size() && records.clusters[m].level == l; ++m) {
            const auto [vertexOffset, triangleOffset, vertexCount, triangleCount] = arrays.meshlets[m];
            if (triangleCount == 0) fail(clusterName(m) + ": no triangles");
            if (uint64_t(vertexOffset) + vertexCount > arrays.vertices.size() || uint64_t(triangleOffset) + 3ull * triangleCount > arrays.triangles.size())
                fail(clusterName(m) + ": its vertices or triangles run past the arrays");
            for (size_t k = 0; k < 3ull * triangleCount; ++k) {
                const uint8_t local = arrays.triangles[triangleOffset + k];
                if (local >= vertexCount) fail(clusterName(m) + ": triangle corner " + std::to_string(local) + " past its " + std::to_string(vertexCount) + " vertices");
                uint32_t v = arrays.vertices[vertexOffset + local];
                const size_t fileVertices = mesh.fileVertices.empty() ? mesh.positions.size() : mesh.fileVertices.size();
                if (v >= fileVertices) fail(clusterName(m) + ": vertex " + std::to_string(v) + " past the mesh file's " + std::to_string(fileVertices));
                if (!mesh.fileVertices.empty()) v = mesh.fileVertices[v];
                triangles.push_back(v);
                if (k % 3 == 2) clusterOfTriangle.push_back(uint32_t(place.size()));
            }
            const HierarchyClusterRecord& record = records.clusters[m];
            LodCluster& cluster = place.emplace_back();
            cluster.error = record.error;
            cluster.errorSphere = record.sphere;
            if (record.group >= 0) {
                cluster.group = uint32_t(record.group) - firstGroup[l];
                cluster.parentError = records.groups[size_t(record.group)].error;
                cluster.parentSphere = records.groups[size_t(record.group)].sphere;
            }
            if (record.refined >= 0) cluster.sourceGroup = uint32_t(record.refined) - firstGroup[l - 1];
        }
        std::optional<LodLevel> onMesh = l == 0 ? levelZeroOnMesh(prepared, triangles, clusterOfTriangle, place.size(), settings) : std::nullopt;
        LodLevel level = onMesh ? std::move(*onMesh) : lodLevelOf(prepared, triangles, clusterOfTriangle, settings);
        level.place = std::move(place);
        level.groups = firstGroup[l + 1] - firstGroup[l];
        hierarchy.levels.push_back(std::move(level));
    }
    return hierarchy;
}

}  // namespace conescope
