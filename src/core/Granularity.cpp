#include "Granularity.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "ExpectedCull.h"

#include "MultiCones.h"
#include "RecordTests.h"

namespace conescope {

namespace {

void finishRow(GranularityRow& row, size_t clusters, size_t triangles, size_t views) {
    row.bitsPerTriangle = triangles == 0 ? 0.0 : double(row.bytesPerCluster) * 8.0 * double(clusters) / double(triangles);
    row.efficiency = cullEfficiency(row.trianglesCulled, row.backFacingTriangles);
    row.culledShare = triangles == 0 || views == 0 ? 0.0 : double(row.trianglesCulled) / (double(triangles) * double(views));
}

// One K-cone record (float or compact) as it is counted over the views.
struct MultiConeRecord {
    SubGroupRecord record;
    GranularityRow row;
};

size_t largestClusterTriangles(const Mesh& mesh, const ClusterBounds& bounds) {
    size_t largest = 0;
    for (size_t c = 0; c < bounds.count(); ++c) {
        size_t triangles = 0;
        for (uint32_t i = bounds.faces.starts[c]; i < bounds.faces.starts[c + 1]; ++i) triangles += mesh.faceSize(bounds.faces.faces[i]) - 2;
        largest = std::max(largest, triangles);
    }
    return largest;
}

GranularityConeWidths coneWidthsOf(const MultiCones& multi) {
    GranularityConeWidths widths;
    widths.cones = multi.conesPerCluster;
    double triangles = 0.0, withCone = 0.0, angleSum = 0.0, coneless = 0.0, expected = 0.0;
    for (size_t g = 0; g < multi.groupCount(); ++g) {
        const double t = multi.groupTriangles[g];
        const ConeOfNormals& cone = multi.cones[g];
        triangles += t;
        if (t == 0.0) continue;
        if (!cone.cullable) {
            coneless += t;
            continue;
        }
        withCone += t;
        angleSum += t * cone.halfAngle() * 180.0 / M_PI;
        expected += t * coneCullShare(cone.sinHalfAngle);
    }
    widths.meanHalfAngleDegrees = withCone > 0.0 ? angleSum / withCone : 0.0;
    widths.conelessShare = triangles > 0.0 ? coneless / triangles : 0.0;
    widths.expectedCulledShare = triangles > 0.0 ? expected / triangles : 0.0;
    return widths;
}

}  // namespace

Settings granularitySettings(Settings settings, bool testsGiven) {
    if (testsGiven) return settings;
    settings.tests = {Settings{}.tests.front()};
    for (CullTest test : allCullTests())
        if (test != CullTest::Oracle && test != settings.tests.front()) settings.tests.push_back(test);
    return settings;
}

std::vector<GranularityRow> oneConeRows(const RunStatistics& run) {
    std::vector<GranularityRow> rows;
    std::set<CullTest> enginesDone;
    for (const CullTestStatistics& result : run.results) {
        if (result.engineRecord && !enginesDone.insert(result.test).second) continue;
        GranularityRow row;
        row.record = result.engineRecord ? toString(result.test) : toString(result.cone) + "/" + toString(result.test);
        row.bytesPerCluster = result.bytesPerCluster;
        row.trianglesCulled = result.trianglesCulled;
        row.backFacingTriangles = result.backFacingTriangles;
        row.testsPerView = double(run.clusters);
        row.falseCulls = result.falseCulls;
        finishRow(row, run.clusters, run.triangles, run.viewCount);
        rows.push_back(row);
    }
    return rows;
}

std::vector<GranularityRow> finerRows(const PreparedMesh& prepared, const ClusterSet& clusters, const std::vector<Eye>& views,
                                      const Settings& settings, const ProgressCallback& progress,
                                      std::vector<GranularityConeWidths>* widths) {
    const Mesh& mesh = prepared.mesh();
    const ClusterBounds& bounds = clusters.bounds;
    const size_t largest = largestClusterTriangles(mesh, bounds);
    std::vector<MultiCones> multis;
    std::vector<CompactMultiCones> compacts;
    multis.reserve(std::size(kGranularityCones));
    compacts.reserve(std::size(kGranularityCones));
    std::vector<MultiConeRecord> records;
    for (uint32_t k : kGranularityCones) {
        multis.push_back(computeMultiCones(mesh, prepared.faces, bounds, k, prepared.world));
        compacts.push_back(compactMultiCones(prepared.faces, bounds, multis.back(), prepared.box));
    }
    if (widths) {
        widths->assign(1, coneWidthsOf(computeMultiCones(mesh, prepared.faces, bounds, 1)));
        for (const MultiCones& multi : multis) widths->push_back(coneWidthsOf(multi));
    }
    for (size_t i = 0; i < multis.size(); ++i)
        for (bool compact : {false, true}) {
            MultiConeRecord record;
            record.record = compact ? subGroupRecord(multis[i], compacts[i].cones, compacts[i].spheres, &compacts[i].apexes)
                                    : subGroupRecord(multis[i], multis[i].cones, bounds.spheres);
            const uint32_t k = multis[i].conesPerCluster;
            record.row.record = "cones-" + std::to_string(k) + (compact ? "-compact" : "");
            record.row.bytesPerCluster = multiConeRecordBytes(k, largest, compact);
            size_t nonEmpty = 0;
            for (uint32_t triangles : multis[i].groupTriangles) nonEmpty += triangles > 0 ? 1 : 0;
            record.row.testsPerView = double(nonEmpty);
            records.push_back(std::move(record));
        }
    // Per-triangle culling after the cluster test: every back face culled, one test per cluster
    // plus one per triangle of each cluster the cluster test drew.
    const CullTest clusterTest = displayedTest(settings);
    GranularityRow triangle;
    triangle.record = "triangle";
    triangle.bytesPerCluster = recordBytes(clusterTest);
    std::vector<size_t> clusterTriangles(bounds.count(), 0);
    for (size_t c = 0; c < bounds.count(); ++c)
        for (uint32_t i = bounds.faces.starts[c]; i < bounds.faces.starts[c + 1]; ++i)
            clusterTriangles[c] += mesh.faceSize(bounds.faces.faces[i]) - 2;
    const CullingInput input = cullingInput(prepared, clusters);
    double triangleTests = 0.0;
    for (size_t v = 0; v < views.size(); ++v) {
        if (v % 8 == 0) reportProgress(progress, double(v) / double(views.size()), "finer records");
        const std::vector<Facing> facing = classifyFaces(mesh, prepared.world, prepared.faces, views[v]);
        const size_t back = backFacingTriangles(mesh, facing);
        for (MultiConeRecord& record : records) {
            record.row.backFacingTriangles += back;
            const SubGroupCulling counted = countSubGroupCulling(record.record, facing, views[v]);
            record.row.trianglesCulled += counted.trianglesCulled;
            record.row.falseCulls += counted.falseCulls;
        }
        const std::vector<uint8_t> culled = cullClusters(input, views[v], clusterTest);
        triangleTests += double(bounds.count());
        for (size_t c = 0; c < culled.size(); ++c)
            if (!culled[c]) triangleTests += double(clusterTriangles[c]);
        triangle.trianglesCulled += back;
        triangle.backFacingTriangles += back;
    }
    triangle.testsPerView = views.empty() ? 0.0 : triangleTests / double(views.size());
    std::vector<GranularityRow> rows;
    for (MultiConeRecord& record : records) {
        finishRow(record.row, bounds.count(), prepared.triangles, views.size());
        rows.push_back(record.row);
    }
    finishRow(triangle, bounds.count(), prepared.triangles, views.size());
    rows.push_back(triangle);
    return rows;
}

GranularityReport measureGranularity(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings,
                                     const ProgressCallback& progress) {
    GranularityReport report;
    report.run = measureRun(prepared, clusters, settings, progressWithin(progress, 0.0, 0.5));
    report.rows = oneConeRows(report.run);
    const std::vector<GranularityRow> finer =
        finerRows(prepared, clusters, viewsFor(settings, prepared.box), settings, progressWithin(progress, 0.5, 1.0), &report.widths);
    report.rows.insert(report.rows.end(), finer.begin(), finer.end());
    return report;
}

GranularityReport runGranularity(const Mesh& mesh, const Settings& settings, const std::string& meshName,
                                 const ProgressCallback& progress) {
    const PreparedMesh prepared = prepareBorrowed(mesh, meshName, settings.fixWinding, progressWithin(progress, 0.0, 0.05));
    const ClusterSet clusters = buildClusters(prepared, settings, nullptr, progressWithin(progress, 0.05, 0.15));
    return measureGranularity(prepared, clusters, settings, progressWithin(progress, 0.15, 1.0));
}

}  // namespace conescope
