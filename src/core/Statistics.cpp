#include "Statistics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "BatchCulling.h"
#include "ExpectedCull.h"
#include "RecordTests.h"

namespace conescope {

namespace {

// A quantised record's float original's decisions (RecordTests.h), the float octagon as the
// product runs it; empty for a test without one.
std::vector<uint8_t> floatOriginalDecisions(const CullingInput& input, const Eye& eye, CullTest test) {
    if (!hasFloatOriginal(test)) return {};
    if (test == CullTest::OctagonCompact) return cullClusters(input, eye, CullTest::Octagon);
    std::vector<uint8_t> culled(input.bounds.count());
    for (uint32_t c = 0; c < culled.size(); ++c) culled[c] = floatOriginalCulls(input, c, eye, test);
    return culled;
}

// What the oracle says about each cluster from one eye; shared by every test of that view.
struct ClusterTruth {
    std::vector<uint32_t> frontFaces;
    std::vector<uint32_t> backTriangles;
};

ClusterTruth truthForView(const CullingInput& input, const std::vector<Facing>& facing) {
    const ClusterFaces& rows = input.bounds.faces;
    const size_t clusterCount = input.bounds.count();
    ClusterTruth truth{std::vector<uint32_t>(clusterCount, 0), std::vector<uint32_t>(clusterCount, 0)};
    for (uint32_t c = 0; c < clusterCount; ++c)
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            const uint32_t f = rows.faces[i];
            if (facing[f] == Facing::Front) ++truth.frontFaces[c];
            if (facing[f] == Facing::Back) truth.backTriangles[c] += uint32_t(input.mesh.faceSize(f) - 2);
        }
    return truth;
}


}  // namespace

double uncullableShare(size_t uncullableClusters, size_t clusters) {
    return clusters == 0 ? 0.0 : double(uncullableClusters) / double(clusters);
}

std::string uncullableNote(size_t uncullableClusters, size_t clusters) {
    if (!(2 * uncullableClusters > clusters)) return {};
    const long percent = std::lround(100.0 * uncullableShare(uncullableClusters, clusters));
    return std::to_string(uncullableClusters) + " of " + std::to_string(clusters) + " clusters (" + std::to_string(percent) +
           "%) can never be culled: each holds face normals over more than a hemisphere (a small closed part, or faces "
           "turned every way), so no cone of normals narrower than a hemisphere holds them and no test culls them from any "
           "eye. Only smaller clusters, or several cones per cluster, could cull there.";
}

std::string bestEffortNote(const BestEffortChoice& choice) {
    if (!choice.ran || !choice.keptBalanced) return {};
    const std::string kept = "the best effort kept the balanced search's partition: ";
    if (choice.ownClusters != choice.balancedClusters)
        return kept + "its own search made " + std::to_string(choice.ownClusters) + " clusters, the balanced one " +
               std::to_string(choice.balancedClusters) + ", nearer the budget";
    // At one count: each measure by which best's own culled less, with both figures.
    char figures[2][128] = {"", ""};
    if (choice.ownEfficiency < choice.balancedEfficiency)
        std::snprintf(figures[0], sizeof figures[0], "from the run's orbit (%.3f against %.3f)", choice.balancedEfficiency,
                      choice.ownEfficiency);
    if (choice.ownExpected < choice.balancedExpected)
        std::snprintf(figures[1], sizeof figures[1], "in expectation over far views (%.3f against %.3f)", choice.balancedExpected,
                      choice.ownExpected);
    const std::string both = *figures[0] && *figures[1] ? " and " : "";
    return kept + "at " + std::to_string(choice.balancedClusters) + " clusters each it culls more than best's own search " +
           figures[0] + both + figures[1];
}

double shownEfficiency(const Mesh& mesh, const FaceGeometry& faces, const Partition& partition, const Settings& settings) {
    const std::vector<glm::vec3> world = worldPositions(mesh);
    const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, displayedCone(settings), settings.sphere);
    return measureCulling({mesh, world, faces, bounds}, orbitOf(settings, computeAabb(world)), displayedTest(settings)).efficiency;
}

double cullEfficiency(size_t trianglesCulled, size_t backFacingTriangles) {
    return backFacingTriangles == 0 ? 1.0 : double(trianglesCulled) / double(backFacingTriangles);
}

// Each cluster's size, bounds and cone, with their means over the clusters: what no view changes.
static void describeClusters(const ClusterBounds& bounds, CullTestStatistics& result) {
    const size_t clusterCount = bounds.count();
    result.clusters.resize(clusterCount);
    for (uint32_t c = 0; c < clusterCount; ++c) {
        ClusterStatistics& cluster = result.clusters[c];
        cluster.cluster = c;
        cluster.faces = bounds.faces.starts[c + 1] - bounds.faces.starts[c];
        cluster.triangles = bounds.triangles[c];
        cluster.vertices = bounds.vertexStarts[c + 1] - bounds.vertexStarts[c];
        cluster.cullable = bounds.cones[c].cullable;
        cluster.sphereRadius = bounds.spheres[c].radius;
        cluster.halfAngleDegrees = cluster.cullable ? glm::degrees(bounds.cones[c].halfAngle()) : 90.0;
        result.uncullableClusters += cluster.cullable ? 0 : 1;
        result.meanClusterTriangles += double(cluster.triangles);
        result.meanClusterVertices += double(cluster.vertices);
        result.meanSphereRadius += cluster.sphereRadius;
        result.maxSphereRadius = std::max(result.maxSphereRadius, cluster.sphereRadius);
    }
    result.expectedEfficiency = expectedCullRate(bounds.cones.data(), bounds.triangles.data(), clusterCount);
    if (clusterCount > 0) {
        result.meanClusterTriangles /= double(clusterCount);
        result.meanClusterVertices /= double(clusterCount);
        result.meanSphereRadius /= double(clusterCount);
    }
}

// One view's culls against the truth, counted for the view and for each cluster: culled, missed by
// the test (or by its quantisation), or lost to the partition.
static void tallyView(const ClusterTruth& truth, const std::vector<uint8_t>& culled, const std::vector<uint8_t>& floatCulled,
                      const std::vector<uint32_t>& triangles, ViewStatistics& view, std::vector<ClusterStatistics>& clusters) {
    for (uint32_t c = 0; c < clusters.size(); ++c) {
        const bool backFacing = truth.frontFaces[c] == 0 && truth.backTriangles[c] > 0;
        view.backFacingTriangles += truth.backTriangles[c];
        view.frontFacingTriangles += triangles[c] - truth.backTriangles[c];
        view.backFacingClusters += backFacing;
        ClusterStatistics& cluster = clusters[c];
        cluster.timesBackFacing += backFacing;
        if (culled[c]) {
            ++view.clustersCulled;
            ++cluster.timesCulled;
            view.trianglesCulled += truth.backTriangles[c];
            if (truth.frontFaces[c] > 0) ++view.falseCulls, ++cluster.falseCulls;
        } else if (truth.frontFaces[c] == 0) {
            // Every face away (or degenerate), yet drawn: the test's loss.
            view.missedClusters += backFacing;
            cluster.timesMissed += backFacing;
            view.testLossTriangles += truth.backTriangles[c];
            cluster.testLossTriangles += truth.backTriangles[c];
            if (!floatCulled.empty() && floatCulled[c]) {
                view.quantisationLossTriangles += truth.backTriangles[c];
                cluster.quantisationLossTriangles += truth.backTriangles[c];
            }
        } else {
            view.partitionLossTriangles += truth.backTriangles[c];
            cluster.partitionLossTriangles += truth.backTriangles[c];
        }
    }
}

CullTestStatistics measureCulling(const CullingInput& input, const std::vector<Eye>& views, CullTest test,
                              const ProgressCallback& progress) {
    const ClusterBounds& bounds = input.bounds;
    const size_t clusterCount = bounds.count();
    CullTestStatistics result;
    result.cone = bounds.coneMethod;
    result.test = test;
    result.bytesPerCluster = recordBytes(test);
    result.engineRecord = reproducesEngineRecord(test);
    describeClusters(bounds, result);

    // The batched kernel reads the bounds as float arrays: made once for all the views.
    // The compact octagon's float original is the batched octagon test.
    const CullTest batchedTest = test == CullTest::OctagonCompact ? CullTest::Octagon : test;
    const bool anyBatched = std::any_of(views.begin(), views.end(), [&](const Eye& eye) { return culledInBatch(eye, batchedTest); });
    const ClusterBatch batch = anyBatched ? makeClusterBatch(bounds) : ClusterBatch();
    const CullingInput batched{input.mesh, input.world, input.faces, input.bounds, anyBatched ? &batch : input.batch};
    double totalNanoseconds = 0.0;
    for (size_t v = 0; v < views.size(); ++v) {
        if (progress && v % 16 == 0 && !progress(double(v) / double(views.size()), "views")) throw OperationCancelled();
        const Eye& eye = views[v];
        const std::vector<Facing> facing = classifyFaces(input.mesh, input.world, input.faces, eye);
        const ClusterTruth truth = truthForView(input, facing);
        const auto start = std::chrono::steady_clock::now();
        const std::vector<uint8_t> culled = cullClusters(batched, eye, test);
        const double nanoseconds = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
        totalNanoseconds += nanoseconds;
        const std::vector<uint8_t> floatCulled = floatOriginalDecisions(batched, eye, test);

        ViewStatistics view;
        view.view = v;
        view.eye = eye;
        view.nanosecondsPerCluster = clusterCount ? nanoseconds / double(clusterCount) : 0.0;
        tallyView(truth, culled, floatCulled, bounds.triangles, view, result.clusters);
        view.efficiency = cullEfficiency(view.trianglesCulled, view.backFacingTriangles);
        result.meanViewEfficiency += view.efficiency / double(views.size());
        result.testLossTriangles += view.testLossTriangles;
        result.partitionLossTriangles += view.partitionLossTriangles;
        result.quantisationLossTriangles += view.quantisationLossTriangles;
        result.clustersCulled += view.clustersCulled;
        result.trianglesCulled += view.trianglesCulled;
        result.backFacingTriangles += view.backFacingTriangles;
        result.missedClusters += view.missedClusters;
        result.falseCulls += view.falseCulls;
        result.views.push_back(view);
    }
    result.efficiency = cullEfficiency(result.trianglesCulled, result.backFacingTriangles);
    // The vertices test reads the cluster's vertices besides its cone: 12 bytes each, on average.
    if (test == CullTest::Vertices) result.bytesPerCluster += size_t(std::lround(12.0 * result.meanClusterVertices));
    // Own records' shares come from the records; addCullMap fills the others' from the cull map.
    if (readsOwnRecord(test))
        for (ClusterStatistics& cluster : result.clusters)
            cluster.cullFraction = ownRecordCullShare({input.mesh, input.world, input.faces, input.bounds}, cluster.cluster, test);
    result.nanosecondsPerCluster =
        clusterCount && !views.empty() ? totalNanoseconds / double(clusterCount * views.size()) : 0.0;
    return result;
}

void addCullMap(CullTestStatistics& statistics, const CullMap& map) {
    double cull = 0.0, oracle = 0.0, triangles = 0.0;
    for (ClusterStatistics& cluster : statistics.clusters) {
        if (!readsOwnRecord(statistics.test)) cluster.cullFraction = cullFraction(map, cluster.cluster, statistics.test);
        cluster.oracleFraction = map.oracleFraction[cluster.cluster];
        cull += double(cluster.triangles) * cluster.cullFraction;
        oracle += double(cluster.triangles) * cluster.oracleFraction;
        triangles += double(cluster.triangles);
    }
    statistics.cullFraction = triangles > 0.0 ? cull / triangles : 0.0;
    statistics.oracleFraction = triangles > 0.0 ? oracle / triangles : 0.0;
}

}  // namespace conescope
