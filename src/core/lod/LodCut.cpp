#include "LodCut.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/MultiCones.h"

namespace conescope {

namespace {

// Size and cone widths of a level from its statistics' clusters.
void describeLevel(LodLevelStatistics& level, const LodLevel& source) {
    level.clusters = source.clusters.partition.clusterCount;
    level.triangles = source.triangles();
    level.groups = source.groups;
    double weighted = 0.0, weight = 0.0;
    for (const ClusterStatistics& cluster : level.culling.clusters) {
        if (!cluster.cullable) continue;
        weighted += cluster.halfAngleDegrees * double(cluster.triangles);
        weight += double(cluster.triangles);
        level.maxHalfAngleDegrees = std::max(level.maxHalfAngleDegrees, cluster.halfAngleDegrees);
    }
    level.meanHalfAngleDegrees = weight > 0.0 ? weighted / weight : 0.0;
    level.minError = std::numeric_limits<double>::infinity();
    for (const LodCluster& place : source.place) {
        level.minError = std::min(level.minError, place.error);
        level.maxError = std::max(level.maxError, place.error);
    }
    if (source.place.empty()) level.minError = 0.0;
}

// What the test does to the cut's clusters of one level from one eye, added to `view`: the
// level's own decisions (measureEye) and the faces' facing, counted over the clusters in the cut;
// with `multi`, also its K cones' culling of the same clusters.
void cullCutOfLevel(const LodLevel& level, const std::vector<uint8_t>& inCut, const Eye& eye, CullTest test, const SubGroupRecord* multi,
                    LodCutView& view) {
    const EyeMeasurement measured = measureEye(level.prepared, level.clusters, eye, test);
    const Mesh& mesh = level.prepared.mesh();
    const std::vector<Facing> facing = classifyFaces(mesh, level.prepared.world, level.prepared.faces, eye);
    const std::vector<uint32_t>& clusterOf = level.clusters.partition.clusterOfFace;
    std::vector<uint8_t> holdsFront(inCut.size(), 0);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t c = clusterOf[f];
        if (!inCut[c]) continue;
        const size_t triangles = mesh.faceSize(f) - 2;
        view.triangles += triangles;
        if (facing[f] == Facing::Front) holdsFront[c] = 1;
        if (facing[f] != Facing::Back) continue;
        view.backFacingTriangles += triangles;
        if (measured.culled[c]) view.trianglesCulled += triangles;
    }
    for (size_t c = 0; c < inCut.size(); ++c) {
        if (!inCut[c]) continue;
        ++view.clusters;
        if (!measured.culled[c]) continue;
        ++view.clustersCulled;
        view.falseCulls += holdsFront[c];
    }
    if (multi) {
        const SubGroupCulling counted = countSubGroupCulling(*multi, facing, eye, inCut);
        view.multiCones.trianglesCulled += counted.trianglesCulled;
        view.multiCones.falseCulls += counted.falseCulls;
    }
}

// Adds `part` (one view's or level's counts) to `total`, and sets both's efficiency.
void addMultiCones(LodMultiConeCulling& total, LodMultiConeCulling& part) {
    part.efficiency = cullEfficiency(part.trianglesCulled, part.backFacingTriangles);
    total.trianglesCulled += part.trianglesCulled;
    total.backFacingTriangles += part.backFacingTriangles;
    total.falseCulls += part.falseCulls;
    total.efficiency = cullEfficiency(total.trianglesCulled, total.backFacingTriangles);
}

}  // namespace

double projectedError(double error, const Sphere& sphere, const glm::dvec3& eye, const LodThreshold& threshold) {
    if (threshold.worldUnits) return error;
    if (std::isinf(error)) return error;
    const double distance = glm::length(eye - sphere.center) - sphere.radius;
    if (distance <= 0.0) return error > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    const double pixelsPerTangent = threshold.screenHeight / (2.0 * std::tan(0.5 * threshold.fovDegrees * M_PI / 180.0));
    return error / distance * pixelsPerTangent;
}

std::vector<std::vector<uint8_t>> cutFrom(const ClusterHierarchy& hierarchy, const glm::dvec3& eye, const LodThreshold& threshold) {
    std::vector<std::vector<uint8_t>> cut;
    for (const LodLevel& level : hierarchy.levels) {
        std::vector<uint8_t>& drawn = cut.emplace_back(level.place.size(), 0);
        for (size_t c = 0; c < level.place.size(); ++c) {
            const LodCluster& place = level.place[c];
            drawn[c] = projectedError(place.error, place.errorSphere, eye, threshold) <= threshold.value &&
                       !(projectedError(place.parentError, place.parentSphere, eye, threshold) <= threshold.value);
        }
    }
    return cut;
}

Mesh meshOfCut(const ClusterHierarchy& hierarchy, const std::vector<std::vector<uint8_t>>& drawn) {
    Mesh cut;
    if (hierarchy.levels.empty()) return cut;
    cut.positions = hierarchy.levels.front().prepared.mesh().positions;
    cut.model = hierarchy.levels.front().prepared.mesh().model;
    std::vector<double>& ids = cut.faceArrays["cluster_id"];
    std::vector<double>& levels = cut.faceArrays["level"];
    double first = 0.0;
    for (size_t l = 0; l < hierarchy.levels.size(); ++l) {
        const Mesh& mesh = hierarchy.levels[l].prepared.mesh();
        const std::vector<uint32_t>& clusterOf = hierarchy.levels[l].clusters.partition.clusterOfFace;
        for (size_t f = 0; f < mesh.faceCount(); ++f) {
            if (!drawn[l][clusterOf[f]]) continue;
            cut.addFace(mesh.faceBegin(f), mesh.faceSize(f));
            ids.push_back(first + clusterOf[f]);
            levels.push_back(double(l));
        }
        first += double(drawn[l].size());
    }
    return cut;
}

LodStatistics measureHierarchy(const ClusterHierarchy& hierarchy, const Settings& settings, const LodThreshold& threshold,
                               const ProgressCallback& progress, uint32_t conesPerCluster) {
    LodStatistics statistics;
    statistics.threshold = threshold;
    statistics.buildSeconds = hierarchy.buildSeconds;
    if (hierarchy.levels.empty()) return statistics;
    const CullTest test = displayedTest(settings);
    const std::vector<Eye> views = viewsFor(settings, hierarchy.levels.front().prepared.box);
    const size_t levelCount = hierarchy.levels.size();
    // Each level's K sub-groups per cluster and their float record, when asked for.
    std::vector<MultiCones> multis;
    std::vector<SubGroupRecord> records;
    multis.reserve(levelCount);
    for (const LodLevel& level : hierarchy.levels) {
        if (conesPerCluster == 0) break;
        multis.push_back(computeMultiCones(level.prepared.mesh(), level.prepared.faces, level.clusters.bounds, conesPerCluster,
                                             level.prepared.world));
        records.push_back(subGroupRecord(multis.back(), multis.back().cones, level.clusters.bounds.spheres));
    }
    for (size_t l = 0; l < levelCount; ++l) {
        const LodLevel& level = hierarchy.levels[l];
        LodLevelStatistics& row = statistics.levels.emplace_back();
        row.level = l;
        // The level's share of the first half: its one-cone run, then (when asked) its K cones.
        const double begin = 0.5 * double(l) / double(levelCount), end = 0.5 * double(l + 1) / double(levelCount);
        const double split = records.empty() ? end : 0.5 * (begin + end);
        row.culling = measureCulling(cullingInput(level.prepared, level.clusters), views, test, progressWithin(progress, begin, split, "levels"));
        describeLevel(row, level);
        if (!records.empty())
            row.multiCones = measureMultiCones(level.prepared.mesh(), level.prepared.world, level.prepared.faces, records[l], views,
                                               progressWithin(progress, split, end));
    }
    LodCutStatistics& cut = statistics.cut;
    std::vector<uint8_t> used(levelCount, 0);
    for (size_t v = 0; v < views.size(); ++v) {
        reportProgress(progress, 0.5 + 0.5 * double(v) / double(views.size()), "cut");
        LodCutView& view = cut.views.emplace_back();
        view.view = v;
        view.eye = views[v];
        view.clustersPerLevel.assign(levelCount, 0);
        const std::vector<std::vector<uint8_t>> drawn = cutFrom(hierarchy, views[v].position, threshold);
        for (size_t l = 0; l < levelCount; ++l) {
            view.clustersPerLevel[l] = size_t(std::count(drawn[l].begin(), drawn[l].end(), uint8_t(1)));
            if (view.clustersPerLevel[l] == 0) continue;
            used[l] = 1;
            cullCutOfLevel(hierarchy.levels[l], drawn[l], views[v], test, records.empty() ? nullptr : &records[l], view);
        }
        view.efficiency = cullEfficiency(view.trianglesCulled, view.backFacingTriangles);
        if (!records.empty()) {
            view.multiCones.cones = cut.multiCones.cones = conesPerCluster;
            view.multiCones.backFacingTriangles = view.backFacingTriangles;
            addMultiCones(cut.multiCones, view.multiCones);
        }
        cut.trianglesCulled += view.trianglesCulled;
        cut.backFacingTriangles += view.backFacingTriangles;
        cut.falseCulls += view.falseCulls;
        cut.meanTriangles += double(view.triangles) / double(views.size());
        cut.meanClusters += double(view.clusters) / double(views.size());
    }
    cut.efficiency = cullEfficiency(cut.trianglesCulled, cut.backFacingTriangles);
    for (size_t l = 0; l < levelCount; ++l)
        if (used[l]) cut.levelsUsed.push_back(l);
    return statistics;
}

LodStatistics lodOfMesh(const Mesh& mesh, const std::string& meshName, const Settings& settings, const LodThreshold& threshold,
                        const LodBuildOptions& options, const ProgressCallback& progress) {
    const PreparedMesh prepared = prepareBorrowed(mesh, meshName, settings.fixWinding, progressWithin(progress, 0.0, 0.1));
    const ClusterHierarchy hierarchy = buildClusterHierarchy(prepared, settings, options, progressWithin(progress, 0.1, 0.6));
    return measureHierarchy(hierarchy, settings, threshold, progressWithin(progress, 0.6, 1.0));
}

}  // namespace conescope
