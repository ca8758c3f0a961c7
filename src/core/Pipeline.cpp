#include "Pipeline.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "BatchCulling.h"
#include "EngineRecords.h"
#include "FileBuilder.h"
#include "MultiConeCulling.h"
#include "RecordTests.h"
#include "SettingsSchema.h"
#include "meshopt/Meshopt.h"

namespace conescope {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Calls the callback and turns a refusal into the core's cancellation exception, like runStatistics.
void report(const ProgressCallback& progress, double fraction, const std::string& stage) { reportProgress(progress, fraction, stage); }

// meshoptimizer's bounds a meshlet file stored for the file builder's cluster file: the meshopt
// tests then test those (EngineRecords.h) instead of the library's.
void useStoredMeshletBounds(ClusterBounds& bounds, const Mesh& mesh, const Settings& settings) {
    if (settings.builder != Builder::File) return;
    if (const std::vector<MeshletBounds>* stored = storedMeshletBounds(mesh, settings.clusterFile)) bounds.records->useStoredMeshoptBounds(*stored);
}

}  // namespace

bool partitionChanged(const Settings& before, const Settings& after) {
    const std::optional<Stage> stale = firstStaleStage(before, after);
    return stale && *stale <= Stage::Clusters;
}

bool boundsChanged(const Settings& before, const Settings& after) {
    const std::optional<Stage> stale = firstStaleStage(before, after);
    return stale && *stale <= Stage::Bounds;
}

PreparedMesh prepareMesh(std::shared_ptr<const Mesh> mesh, const std::string& path, bool fixWinding,
                         const ProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    PreparedMesh prepared;
    prepared.path = path;
    prepared.name = std::filesystem::path(path).filename().string();
    prepared.original = mesh;
    prepared.culled = mesh;
    prepared.fixWindingAsked = fixWinding;
    report(progress, 0.3, "face geometry");
    prepared.faces = computeFaceGeometry(*mesh);
    report(progress, 0.5, "mesh checks");
    prepared.report = checkMesh(*mesh, prepared.faces);
    // The same repair runStatistics makes, so the window culls the mesh an export would.
    if (fixWinding && windingNeedsFixing(prepared.report)) {
        report(progress, 0.6, "winding repair");
        auto repaired = std::make_shared<Mesh>(*mesh);
        prepared.windingFixedFaces = conescope::fixWinding(*repaired);
        if (prepared.windingFixedFaces > 0) {
            prepared.faces = computeFaceGeometry(*repaired);
            prepared.culled = repaired;
        }
    }
    report(progress, 0.8, "world positions");
    prepared.world = worldPositions(prepared.mesh());
    prepared.box = computeAabb(prepared.world);
    prepared.triangles = triangleCount(prepared.mesh());
    prepared.prepareSeconds = secondsSince(start);
    return prepared;
}

ClusterSet buildClusters(const PreparedMesh& prepared, const Settings& settings, const ClusterSet* previous,
                         const ProgressCallback& progress, MeshletStream* meshlets) {
    ClusterSet clusters;
    clusters.builtWith = settings;
    const ConeMethod cone = displayedCone(settings);
    // The optimized builder hands over its parts as they are made: their bounds are made at once,
    // on the core that made the part, while the other core still builds.
    struct PartBounds {
        ClusterBounds bounds;
        bool made = false;
    };
    std::vector<PartBounds> parts;
    std::mutex partsMutex;
    double partBoundsSeconds = 0.0;
    const PartClusters boundPart = [&](size_t part, size_t partCount, const std::vector<uint32_t>& faces, const Partition& partClusters) {
        const auto start = std::chrono::steady_clock::now();
        PartBounds made{boundsOfClusters(prepared.mesh(), prepared.world, prepared.faces, clusterRowsOf(faces.data(), partClusters), cone,
                                         settings.sphere, &prepared.box),
                        true};
        std::lock_guard<std::mutex> lock(partsMutex);
        if (parts.size() != partCount) parts.assign(partCount, PartBounds{});  // a new start: its own parts
        parts[part] = std::move(made);
        partBoundsSeconds += secondsSince(start);
    };
    if (previous && !partitionChanged(previous->builtWith, settings)) {
        clusters.partition = previous->partition;
        clusters.partitionSeconds = previous->partitionSeconds;
        clusters.bestEffort = previous->bestEffort;
    } else {
        const std::string stage = "clusters (" + toString(settings.builder) + ")";
        report(progress, 0.0, stage);
        const auto start = std::chrono::steady_clock::now();
        // The builder's own progress (parts done) fills the stage's share, under the stage's name.
        clusters.partition =
            buildPartition(prepared.mesh(), prepared.faces, settings, progressWithin(progress, 0.0, 0.6, stage), meshlets, boundPart,
                           &clusters.bestEffort);
        clusters.partitionSeconds = secondsSince(start);
    }
    report(progress, 0.6, "bounds (" + toString(cone) + ")");
    const auto start = std::chrono::steady_clock::now();
    size_t partClusters = 0;
    bool everyPart = !parts.empty();
    for (const PartBounds& part : parts) everyPart &= part.made, partClusters += part.bounds.count();
    if (everyPart && partClusters == clusters.partition.clusterCount) {
        clusters.bounds.coneMethod = cone;
        clusters.bounds.sphereMethod = settings.sphere;
        for (PartBounds& part : parts) appendClusterBounds(clusters.bounds, std::move(part.bounds));
        clusters.boundsSeconds = partBoundsSeconds + secondsSince(start);
    } else {
        clusters.bounds = computeClusterBounds(prepared.mesh(), prepared.world, prepared.faces, clusters.partition, cone, settings.sphere);
        clusters.boundsSeconds = secondsSince(start);
    }
    useStoredMeshletBounds(clusters.bounds, prepared.mesh(), settings);
    report(progress, 0.9, "cull map (" + toString(cone) + ")");
    clusters.cullMap = computeCullMap(clusters.bounds);
    report(progress, 1.0, "clusters ready");
    return clusters;
}

std::shared_ptr<MeshletStream> meshoptStartInBackground(std::shared_ptr<const Mesh> mesh, const Settings& settings) {
    if (!startsFromMeshoptMeshlets(settings) || settings.fixWinding || mesh->faceCount() == 0) return {};
    const size_t parts = meshletPartsFor(mesh->faceCount());
    return std::make_shared<MeshletStream>(std::move(mesh), settings.limits, parts);
}

CullingInput cullingInput(const PreparedMesh& prepared, const ClusterSet& clusters) {
    return CullingInput{prepared.mesh(), prepared.world, prepared.faces, clusters.bounds};
}

Eye eyeAt(const Settings& settings, const glm::dvec3& position, const Aabb& worldBox) {
    Settings single = settings;
    single.eye = position;
    return viewsFor(single, worldBox).front();
}

size_t nearestOrbitView(const Settings& settings, const Aabb& worldBox, const glm::dvec3& position) {
    const glm::dvec3 center(worldBox.center());
    const std::vector<Eye> views = orbitOf(settings, worldBox);
    size_t nearest = 0;
    double best = -2.0;
    for (size_t v = 0; v < views.size(); ++v) {
        // Cosine of the angle between the two directions from the centre (0 for a zero vector).
        const glm::dvec3 a = position - center, b = views[v].position - center;
        const double lengths = glm::length(a) * glm::length(b);
        const double cosine = lengths > 0.0 ? glm::dot(a, b) / lengths : 0.0;
        if (cosine > best) best = cosine, nearest = v;
    }
    return nearest;
}

EyeMeasurement measureEye(const PreparedMesh& prepared, const ClusterSet& clusters, const Eye& eye, CullTest test) {
    const CullingInput input = cullingInput(prepared, clusters);
    EyeMeasurement measurement;
    measurement.eye = eye;
    // One cull: the statistics of a single view already hold each cluster's decision.
    measurement.statistics = measureCulling(input, {eye}, test);
    measurement.culled.resize(measurement.statistics.clusters.size());
    for (size_t c = 0; c < measurement.culled.size(); ++c) measurement.culled[c] = measurement.statistics.clusters[c].timesCulled > 0;
    return measurement;
}

std::vector<uint8_t> allBackFacingClusters(const EyeMeasurement& measurement) {
    std::vector<uint8_t> backFacing(measurement.statistics.clusters.size());
    for (size_t c = 0; c < backFacing.size(); ++c) backFacing[c] = measurement.statistics.clusters[c].timesBackFacing > 0;
    return backFacing;
}

glm::dvec3 startingEyePosition(const Aabb& worldBox, const Settings& settings) {
    const glm::dvec3 direction = glm::normalize(glm::dvec3(0.45, 0.5, 1.0));
    const double radius = std::max(double(worldBox.halfDiagonal()), 1e-6);
    // Near enough that the eye and the mesh share the first picture at a readable size.
    return glm::dvec3(worldBox.center()) + std::min(settings.distance, 2.0) * radius * direction;
}

CullTestStatistics measureOrbit(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                            const ProgressCallback& progress) {
    const CullingInput input = cullingInput(prepared, clusters);
    CullTestStatistics statistics = measureCulling(input, orbitOf(settings, prepared.box), displayedTest(settings),
                                               progressWithin(progress, 0.0, 1.0, "orbit statistics"));
    addCullMap(statistics, clusters.cullMap);
    return statistics;
}

std::vector<ClusterInView> clusterOverOrbit(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                                            uint32_t cluster) {
    const ClusterBatch batch = makeClusterBatch(clusters.bounds);
    const CullingInput input{prepared.mesh(), prepared.world, prepared.faces, clusters.bounds, &batch};
    const ClusterFaces& rows = clusters.bounds.faces;
    const CullTest test = displayedTest(settings);
    std::vector<ClusterInView> seen;
    for (const Eye& view : orbitOf(settings, prepared.box)) {
        ClusterInView in;
        for (uint32_t i = rows.starts[cluster]; i < rows.starts[cluster + 1]; ++i) {
            const Facing facing = classifyFace(prepared.mesh(), prepared.world, prepared.faces, rows.faces[i], view);
            in.frontFaces += facing == Facing::Front;
            in.backFaces += facing == Facing::Back;
        }
        in.culled = culledInBatch(view, test) ? cullClusters(input, view, test)[cluster] != 0 : cullCluster(input, cluster, view, test);
        seen.push_back(in);
    }
    return seen;
}

long viewMissingCluster(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings, uint32_t cluster) {
    const std::vector<ClusterInView> seen = clusterOverOrbit(prepared, clusters, settings, cluster);
    long partitionLoss = -1;
    for (size_t v = 0; v < seen.size(); ++v) {
        const ClusterInView& in = seen[v];
        if (in.culled && in.frontFaces > 0) return long(v);  // a false cull (an engine's record): the worst there is
        if (in.backFaces == 0 || in.culled) continue;
        if (in.frontFaces == 0) return long(v);
        if (partitionLoss < 0) partitionLoss = long(v);
    }
    return partitionLoss;
}

Settings exportSettings(const Settings& settings, const std::optional<glm::dvec3>& eye) {
    Settings result = settings;
    result.eye = eye;
    return result;
}

Settings builderForMesh(const Settings& settings, const Mesh& mesh, std::string& why) {
    Settings result = settings;
    const bool hasIds = mesh.faceArrays.count("cluster_id") > 0;
    // An id file travels in the settings (io's withClusterIds), a meshlet file on the mesh.
    const ClusterIdFile* idFile = settings.clusterIds && settings.clusterIds->path == settings.clusterFile ? settings.clusterIds.get() : nullptr;
    const bool hasClusters = settings.clusterFile.empty() ? meshHasOwnClusters(mesh)
                                                          : mesh.fileClusters.count(settings.clusterFile) > 0 || (idFile && idFile->error.empty());
    if (settings.builder != Builder::File && hasIds) {
        result.builder = Builder::File;
        result.clusterFile.clear();
        why = "the mesh carries a cluster_id array: showing its own partition (the file builder); choose another builder to compare";
    } else if (settings.builder == Builder::File && !hasClusters) {
        result.builder = Settings{}.builder;
        why = (settings.clusterFile.empty() ? std::string("the mesh has no cluster_id array or groups and no cluster file is given")
               : idFile                     ? idFile->error
                                            : settings.clusterFile + " was not read with the mesh") +
              ": clusters from the " + toString(result.builder) + " builder instead of the file builder";
    }
    return result;
}

std::string budgetMissed(const Settings& settings, size_t clustersMade, size_t fewestPossible) {
    const bool takesBudget = settings.builder == Builder::Optimized || settings.builder == Builder::KMeans;
    if (!takesBudget || settings.clusterCount == 0 || clustersMade == settings.clusterCount) return {};
    const std::string asked = "asked for " + std::to_string(settings.clusterCount) + (settings.clusterCount == 1 ? " cluster" : " clusters") + ", made " + std::to_string(clustersMade);
    const std::string limits = std::to_string(settings.limits.maxVertices) + " vertices and " +
                               std::to_string(settings.limits.maxTriangles) + " triangles per cluster";
    if (clustersMade > settings.clusterCount && fewestPossible > settings.clusterCount)
        return asked + ": impossible within " + limits + ", which allow no fewer than " + std::to_string(fewestPossible);
    std::string sentence = asked + ": the nearest count the " + toString(settings.builder) + " builder reached within " + limits;
    if (clustersMade > settings.clusterCount && fewestPossible > 0)
        sentence += " (the limits alone allow as few as " + std::to_string(fewestPossible) + ")";
    return sentence;
}

RunStatistics measureRun(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                         const ProgressCallback& progress) {
    // Stages the settings make stale are built again; the rest is reused.
    if (prepared.fixWindingAsked != settings.fixWinding) {
        PreparedMesh again = prepareMesh(prepared.original, prepared.path, settings.fixWinding);
        again.name = prepared.name;
        return measureRun(again, buildClusters(again, settings), settings, progress);
    }
    if (partitionChanged(clusters.builtWith, settings))
        return measureRun(prepared, buildClusters(prepared, settings, &clusters), settings, progress);
    RunStatistics run;
    run.settings = settings;
    run.meshName = prepared.name;
    run.meshReport = prepared.report;
    run.windingFixedFaces = prepared.windingFixedFaces;
    run.vertices = prepared.mesh().positions.size();
    run.faces = prepared.mesh().faceCount();
    run.triangles = prepared.triangles;
    run.degenerateFaces = prepared.faces.degenerateCount;
    run.clusters = clusters.partition.clusterCount;
    if (settings.clusterCount != 0) run.fewestClusters = fewestClustersWithin(prepared.mesh(), settings.limits);
    run.bestEffort = clusters.bestEffort;
    const std::vector<Eye> views = viewsFor(settings, prepared.box);
    run.viewCount = views.size();
    const size_t steps = settings.cones.size() * settings.tests.size();
    size_t step = 0;
    for (ConeMethod cone : settings.cones) {
        // The displayed cone's bounds are built already; the other cones get theirs for the same partition.
        const bool built = cone == displayedCone(clusters.builtWith) && settings.sphere == clusters.builtWith.sphere;
        if (!built) report(progress, double(step) / double(steps), "bounds (" + toString(cone) + ")");
        ClusterBounds bounds = built ? ClusterBounds()
                                     : computeClusterBounds(prepared.mesh(), prepared.world, prepared.faces, clusters.partition, cone, settings.sphere);
        if (!built) useStoredMeshletBounds(bounds, prepared.mesh(), settings);
        const CullingInput input{prepared.mesh(), prepared.world, prepared.faces, built ? clusters.bounds : bounds};
        if (!built) report(progress, double(step) / double(steps), "cull map (" + toString(cone) + ")");
        const CullMap computed = built ? CullMap() : computeCullMap(input.bounds);
        const CullMap& map = built ? clusters.cullMap : computed;
        for (CullTest test : settings.tests) {
            report(progress, double(step) / double(steps), "culling (" + toString(cone) + ", " + toString(test) + ")");
            run.results.push_back(measureCulling(input, views, test));
            addCullMap(run.results.back(), map);
            ++step;
        }
        // K cones per cluster: the shown cone's partition and spheres, over the same views.
        if (settings.conesPerCluster > 1 && cone == settings.cones.front())
            run.multiCones = measureMultiConeRun(prepared.mesh(), prepared.world, prepared.faces, input.bounds,
                                                 settings.conesPerCluster, views);
    }
    report(progress, 1.0, "done");
    return run;
}

PreparedMesh prepareBorrowed(const Mesh& mesh, const std::string& meshName, bool fixWinding, const ProgressCallback& progress) {
    validateMesh(mesh);
    PreparedMesh prepared = prepareMesh(std::shared_ptr<const Mesh>(&mesh, [](const Mesh*) {}), meshName, fixWinding, progress);
    prepared.name = meshName;
    return prepared;
}

RunStatistics runStatistics(const Mesh& mesh, const Settings& settings, const std::string& meshName,
                            const ProgressCallback& progress) {
    validateMesh(mesh);
    // Borrowed for the call: the stages keep the mesh by shared pointer, and this one outlives them.
    const std::shared_ptr<const Mesh> borrowed(&mesh, [](const Mesh*) {});
    // meshoptimizer's meshlets on one core while the mesh is prepared on the other.
    const std::shared_ptr<MeshletStream> meshlets = meshoptStartInBackground(borrowed, settings);
    PreparedMesh prepared = prepareMesh(borrowed, meshName, settings.fixWinding, progressWithin(progress, 0.0, 0.05));
    prepared.name = meshName;
    const ClusterSet clusters = buildClusters(prepared, settings, nullptr, progressWithin(progress, 0.05, 0.1), meshlets.get());
    return measureRun(prepared, clusters, settings, progressWithin(progress, 0.1, 1.0));
}

std::map<std::string, std::vector<double>> partitionFaceArrays(const PreparedMesh& prepared, const ClusterSet& clusters,
                                                               CullTest test) {
    const size_t faceCount = prepared.mesh().faceCount();
    std::map<std::string, std::vector<double>> arrays;
    auto spread = [&](const std::string& name, auto valueOfCluster) {
        std::vector<double>& values = arrays[name];
        values.resize(faceCount);
        for (size_t f = 0; f < faceCount; ++f) values[f] = valueOfCluster(clusters.partition.clusterOfFace[f]);
    };
    const ClusterBounds& bounds = clusters.bounds;
    spread("cluster_id", [](uint32_t c) { return double(c); });
    spread("cone_half_angle_deg", [&](uint32_t c) { return glm::degrees(bounds.cones[c].halfAngle()); });
    spread("cone_cullable", [&](uint32_t c) { return bounds.cones[c].cullable ? 1.0 : 0.0; });
    for (int axis = 0; axis < 3; ++axis) {
        const std::string suffix = std::string("_") + "xyz"[axis];
        spread("cone_axis" + suffix, [&](uint32_t c) { return bounds.cones[c].axis[axis]; });
        spread("sphere_center" + suffix, [&](uint32_t c) { return bounds.spheres[c].center[axis]; });
        spread("aabb_min" + suffix, [&](uint32_t c) { return double(bounds.boxes[c].min[axis]); });
        spread("aabb_max" + suffix, [&](uint32_t c) { return double(bounds.boxes[c].max[axis]); });
    }
    spread("sphere_radius", [&](uint32_t c) { return bounds.spheres[c].radius; });
    const CullMap& map = clusters.cullMap;
    const CullingInput input = cullingInput(prepared, clusters);
    spread("cull_fraction", [&](uint32_t c) { return testCullFraction(map, input, c, test); });
    spread("oracle_fraction", [&](uint32_t c) { return map.oracleFraction[c]; });
    return arrays;
}

std::vector<FaceLoss> faceLosses(const ClusterSet& clusters, const EyeMeasurement& measurement,
                                 const std::vector<Facing>& facing) {
    const std::vector<uint8_t> backFacingCluster = allBackFacingClusters(measurement);
    std::vector<FaceLoss> losses(facing.size());
    for (size_t f = 0; f < facing.size(); ++f) {
        const uint32_t c = clusters.partition.clusterOfFace[f];
        // The loss classes of the statistics, per face: drawn as it should be, culled, or a back
        // face drawn because of the test or because of the partition.
        if (facing[f] != Facing::Back) losses[f] = FaceLoss::Visible;
        else if (measurement.culled[c]) losses[f] = FaceLoss::Culled;
        else losses[f] = backFacingCluster[c] ? FaceLoss::Test : FaceLoss::Partition;
    }
    return losses;
}

std::map<std::string, std::vector<double>> eyeFaceArrays(const PreparedMesh& prepared, const ClusterSet& clusters,
                                                         const EyeMeasurement& measurement) {
    const std::vector<Facing> facing = classifyFaces(prepared.mesh(), prepared.world, prepared.faces, measurement.eye);
    const std::vector<FaceLoss> losses = faceLosses(clusters, measurement, facing);
    const size_t faceCount = prepared.mesh().faceCount();
    std::map<std::string, std::vector<double>> arrays;
    std::vector<double>& culled = arrays["culled"];
    std::vector<double>& back = arrays["back_facing"];
    std::vector<double>& loss = arrays["loss"];
    culled.resize(faceCount), back.resize(faceCount), loss.resize(faceCount);
    for (size_t f = 0; f < faceCount; ++f) {
        culled[f] = measurement.culled[clusters.partition.clusterOfFace[f]];
        back[f] = facing[f] == Facing::Back;
        loss[f] = double(losses[f]);
    }
    return arrays;
}

}  // namespace conescope
