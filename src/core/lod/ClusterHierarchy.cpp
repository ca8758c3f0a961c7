#include "ClusterHierarchy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>

#include "core/Parallel.h"
#include "core/meshopt/Meshopt.h"

namespace conescope {

namespace {

// Every face of `mesh` as fan triangles (three vertex ids each), and the face each came from.
void fanTrianglesOf(const Mesh& mesh, std::vector<uint32_t>& triangles, std::vector<uint32_t>& faceOfTriangle) {
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* corners = mesh.faceBegin(f);
        for (size_t i = 1; i + 1 < mesh.faceSize(f); ++i) {
            triangles.insert(triangles.end(), {corners[0], corners[i], corners[i + 1]});
            faceOfTriangle.push_back(uint32_t(f));
        }
    }
}

// A group's triangles over its own vertices (simplification and splitting read only those).
struct LocalTriangles {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    std::vector<uint32_t> globalVertex;  // per local vertex
};
LocalTriangles localTriangles(const std::vector<uint32_t>& indices, const std::vector<glm::vec3>& world) {
    LocalTriangles local;
    std::unordered_map<uint32_t, uint32_t> localOf;
    local.indices.reserve(indices.size());
    for (uint32_t v : indices) {
        const auto [at, added] = localOf.emplace(v, uint32_t(local.globalVertex.size()));
        if (added) {
            local.globalVertex.push_back(v);
            local.positions.push_back(world[v]);
        }
        local.indices.push_back(at->second);
    }
    return local;
}

// The simplified triangles of a group split into clusters within the limits by level 0's builder
// (the optimized one for a partition read from a file) at `effort`: per local triangle its cluster.
Partition splitGroup(const LocalTriangles& local, const std::vector<uint32_t>& indices, const Settings& settings, Effort effort) {
    Mesh mesh;
    mesh.positions = local.positions;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) mesh.addFace(&indices[t], 3);
    Settings own = settings;
    if (own.builder == Builder::File) own.builder = Builder::Optimized;
    own.clusterCount = 0;
    own.effort = effort;
    return buildPartition(mesh, computeFaceGeometry(mesh), own);
}

// A level's mesh: its triangles over the original's positions and transform, with their clusters as
// the cluster_id array the file builder reads.
std::shared_ptr<Mesh> levelMesh(const Mesh& original, const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle) {
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = original.positions;
    mesh->model = original.model;
    mesh->faceVertices = triangles;
    mesh->faceStarts.resize(triangles.size() / 3 + 1);
    for (size_t t = 0; t < mesh->faceStarts.size(); ++t) mesh->faceStarts[t] = uint32_t(3 * t);
    mesh->faceArrays["cluster_id"].assign(clusterOfTriangle.begin(), clusterOfTriangle.end());
    return mesh;
}

// One group of the level above: its triangles simplified (ids into the level's positions) in order of
// their clusters, numbered in order of first use, and the simplification's error.
struct SimplifiedGroup {
    std::vector<uint32_t> triangles, clusterOfTriangle;
    uint32_t clusterCount = 0;
    double error = 0.0;
};
SimplifiedGroup simplifyAndSplit(const std::vector<uint32_t>& groupTriangles, const std::vector<glm::vec3>& world,
                            const LodBuildOptions& options, const Settings& settings) {
    const LocalTriangles local = localTriangles(groupTriangles, world);
    const size_t count = local.indices.size() / 3;
    const size_t target = std::max<size_t>(1, size_t(std::ceil(double(count) * options.reduction)));
    SimplifiedTriangles simplified = simplifyWithLockedBorder(local.positions, local.indices, target);
    if (simplified.indices.empty()) simplified = {local.indices, 0.0};  // nothing left: keep the group as it was
    const Partition split = splitGroup(local, simplified.indices, settings, options.splitEffort);
    std::vector<std::vector<uint32_t>> byCluster(split.clusterCount);
    for (size_t t = 0; t < split.clusterOfFace.size(); ++t) byCluster[split.clusterOfFace[t]].push_back(uint32_t(t));
    SimplifiedGroup out;
    out.clusterCount = split.clusterCount;
    out.error = simplified.error;
    for (uint32_t c = 0; c < split.clusterCount; ++c)
        for (uint32_t t : byCluster[c]) {
            for (int k = 0; k < 3; ++k) out.triangles.push_back(local.globalVertex[simplified.indices[3 * t + k]]);
            out.clusterOfTriangle.push_back(c);
        }
    return out;
}

// Level 0's places: no error, each cluster measured from its own bounding sphere.
std::vector<LodCluster> basePlaces(const ClusterSet& clusters) {
    std::vector<LodCluster> place(clusters.partition.clusterCount);
    for (size_t c = 0; c < place.size(); ++c) place[c].errorSphere = clusters.bounds.spheres[c];
    return place;
}

// The level above `below`: its groups simplified and split, in group order. Fills the groups'
// places in `below`. Empty when `below` is one cluster.
struct NextLevel {
    std::vector<uint32_t> triangles, clusterOfTriangle;
    std::vector<LodCluster> place;
};
NextLevel simplifyLevel(LodLevel& below, const Settings& settings, const LodBuildOptions& options, double step,
                        const ProgressCallback& progress, const std::string& stage) {
    std::vector<uint32_t> triangles, faceOfTriangle;
    fanTrianglesOf(below.prepared.mesh(), triangles, faceOfTriangle);
    const Partition& partition = below.clusters.partition;
    std::vector<uint32_t> clusterOfTriangle(faceOfTriangle.size());
    for (size_t t = 0; t < faceOfTriangle.size(); ++t) clusterOfTriangle[t] = partition.clusterOfFace[faceOfTriangle[t]];
    const ClusterGrouping& grouping = options.grouping ? options.grouping : ClusterGrouping(groupAdjacentClusters);
    const std::vector<uint32_t> groupOf = grouping(triangles, clusterOfTriangle, partition.clusterCount, options.groupSize);
    below.groups = groupOf.empty() ? 0 : size_t(*std::max_element(groupOf.begin(), groupOf.end())) + 1;
    std::vector<std::vector<uint32_t>> groupTriangles(below.groups), groupClusters(below.groups);
    for (size_t t = 0; t < clusterOfTriangle.size(); ++t) {
        std::vector<uint32_t>& into = groupTriangles[groupOf[clusterOfTriangle[t]]];
        into.insert(into.end(), &triangles[3 * t], &triangles[3 * t] + 3);
    }
    for (size_t c = 0; c < groupOf.size(); ++c) groupClusters[groupOf[c]].push_back(uint32_t(c));

    // Each group simplified and split on its own (on all cores; the same result on any number), then
    // appended in group order.
    std::vector<SimplifiedGroup> splits(below.groups);
    forEachInParallel(below.groups, [&](size_t g, size_t worker) {
        if (worker == 0) reportProgress(progress, double(g) / double(below.groups), stage);
        splits[g] = simplifyAndSplit(groupTriangles[g], below.prepared.world, options, settings);
    });
    NextLevel next;
    for (size_t g = 0; g < below.groups; ++g) {
        // The group's error and sphere hold its members', and the error grows by at least `step` a
        // level: strictly monotone going up, so that threshold 0 cuts exactly level 0.
        double error = splits[g].error, members = 0.0;
        std::vector<Sphere> spheres;
        for (uint32_t c : groupClusters[g]) {
            members = std::max(members, below.place[c].error);
            spheres.push_back(below.place[c].errorSphere);
        }
        error = std::max(error, members + step);
        const Sphere sphere = sphereAroundSpheres(spheres);
        for (uint32_t c : groupClusters[g]) {
            below.place[c].group = uint32_t(g);
            below.place[c].parentError = error;
            below.place[c].parentSphere = sphere;
        }
        const uint32_t first = uint32_t(next.place.size());
        next.triangles.insert(next.triangles.end(), splits[g].triangles.begin(), splits[g].triangles.end());
        for (uint32_t c : splits[g].clusterOfTriangle) next.clusterOfTriangle.push_back(first + c);
        LodCluster made;
        made.sourceGroup = uint32_t(g);
        made.error = error;
        made.errorSphere = sphere;
        next.place.insert(next.place.end(), splits[g].clusterCount, made);
    }
    return next;
}

}  // namespace

LodLevel lodLevelOf(const PreparedMesh& base, const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle,
                    const Settings& settings) {
    // The clusters read from the level's mesh: bounds as any partition gets them.
    Settings fromIds = settings;
    fromIds.builder = Builder::File;
    fromIds.clusterFile.clear();
    fromIds.clusterIds.reset();
    fromIds.fixWinding = false;
    LodLevel level;
    level.prepared = prepareMesh(levelMesh(base.mesh(), triangles, clusterOfTriangle), base.path, false);
    level.prepared.name = base.name;
    level.clusters = buildClusters(level.prepared, fromIds);
    return level;
}

Sphere sphereAroundSpheres(const std::vector<Sphere>& spheres) {
    Sphere around;
    if (spheres.empty()) return around;
    for (const Sphere& s : spheres) around.center += s.center;
    around.center /= double(spheres.size());
    for (const Sphere& s : spheres) around.radius = std::max(around.radius, glm::length(s.center - around.center) + s.radius);
    return around;
}

std::vector<uint32_t> groupAdjacentClusters(const std::vector<uint32_t>& triangles, const std::vector<uint32_t>& clusterOfTriangle,
                                            size_t clusterCount, size_t groupSize) {
    // Border edges between clusters: per pair of clusters, how many edges they share.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> clusterOfEdge;
    std::vector<std::map<uint32_t, size_t>> shared(clusterCount);
    for (size_t t = 0; t < clusterOfTriangle.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
            const auto [at, added] = clusterOfEdge.emplace(std::minmax(a, b), clusterOfTriangle[t]);
            const uint32_t other = at->second, mine = clusterOfTriangle[t];
            if (!added && other != mine) ++shared[mine][other], ++shared[other][mine];
        }
    std::vector<uint32_t> groupOf(clusterCount, kNoGroup);
    std::vector<size_t> freeNeighbours(clusterCount);
    for (size_t c = 0; c < clusterCount; ++c) freeNeighbours[c] = shared[c].size();
    const auto join = [&](uint32_t c, uint32_t group) {
        groupOf[c] = group;
        for (const auto& [neighbour, edges] : shared[c]) --freeNeighbours[neighbour];
    };
    uint32_t groups = 0;
    for (size_t placed = 0; placed < clusterCount; ++groups) {
        // The seed with the fewest free neighbours: corners first, so no cluster is left alone at the end.
        uint32_t seed = kNoGroup;
        for (uint32_t c = 0; c < clusterCount; ++c)
            if (groupOf[c] == kNoGroup && (seed == kNoGroup || freeNeighbours[c] < freeNeighbours[seed])) seed = c;
        join(seed, groups), ++placed;
        std::map<uint32_t, size_t> border = shared[seed];
        for (size_t size = 1; size < groupSize; ++size, ++placed) {
            uint32_t best = kNoGroup;
            size_t bestEdges = 0;
            for (const auto& [c, edges] : border)
                if (groupOf[c] == kNoGroup && edges > bestEdges) best = c, bestEdges = edges;
            if (best == kNoGroup) break;
            join(best, groups);
            for (const auto& [neighbour, edges] : shared[best]) border[neighbour] += edges;
        }
    }
    return groupOf;
}

ClusterHierarchy buildClusterHierarchy(const PreparedMesh& prepared, const Settings& settings, const LodBuildOptions& options,
                                       const ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    ClusterHierarchy hierarchy;
    hierarchy.settings = settings;
    LodLevel base;
    base.prepared = prepared;
    base.clusters = buildClusters(prepared, settings, nullptr, progressWithin(progress, 0.0, 0.3, "level 0"));
    base.place = basePlaces(base.clusters);
    hierarchy.levels.push_back(std::move(base));
    // The least an error grows going up a level: a billionth of the mesh's size.
    const double step = 1e-9 * std::max(glm::length(glm::dvec3(prepared.box.max - prepared.box.min)), 1e-30);
    while (hierarchy.levels.size() < options.maxLevels && hierarchy.levels.back().clusters.partition.clusterCount > 1) {
        LodLevel& below = hierarchy.levels.back();
        const std::string stage = "level " + std::to_string(hierarchy.levels.size());
        const double at = 0.3 + 0.7 * (1.0 - std::pow(0.5, double(hierarchy.levels.size() - 1)));
        const double share = 0.7 * std::pow(0.5, double(hierarchy.levels.size()));
        NextLevel next = simplifyLevel(below, settings, options, step, progressWithin(progress, at, at + share, stage), stage);
        if (double(next.clusterOfTriangle.size()) > options.stallShare * double(below.triangles())) {
            // Stalled: the level below is the top, never replaced.
            for (LodCluster& place : below.place) {
                place.group = kNoGroup;
                place.parentError = std::numeric_limits<double>::infinity();
                place.parentSphere = {};
            }
            below.groups = 0;
            break;
        }
        LodLevel level = lodLevelOf(prepared, next.triangles, next.clusterOfTriangle, settings);
        level.place = std::move(next.place);
        hierarchy.levels.push_back(std::move(level));
    }
    hierarchy.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return hierarchy;
}

}  // namespace conescope
