#include "io/StatisticsText.h"

#include <cstdio>
#include <string>

#include "core/ClusterRanking.h"
#include "core/RecordTests.h"

namespace conescope {

namespace {

// printf into a string: the table's fixed widths, whatever the stream's locale.
template <typename... Values>
std::string formatted(const char* format, Values... values) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, values...);
    return buffer;
}

double share(size_t part, size_t whole) { return whole ? double(part) / double(whole) : 0.0; }

}  // namespace

void writeClusterTableText(const CullTestStatistics& result, const std::vector<uint32_t>& order, std::ostream& out) {
    // False culls only for an engine's record (every other test has none); quantisation loss only for a quantised one.
    const bool engine = result.engineRecord, quantised = hasFloatOriginal(result.test);
    out << formatted("%8s %6s %6s %7s %10s %6s %7s %7s %7s %10s %10s", "cluster", "tris", "verts", "alpha", "radius", "cull", "oracle",
                     "culled", "missed", "test_loss", "part_loss")
        << (engine ? formatted(" %7s", "false") : "") << (quantised ? formatted(" %10s", "quant_loss") : "") << '\n';
    for (uint32_t c : order) {
        const ClusterStatistics& s = result.clusters.at(c);
        out << formatted("%8u %6zu %6zu %6.1f%s %10.4g %6.3f %7.3f %7zu %7zu %10zu %10zu", s.cluster, s.triangles, s.vertices,
                         s.halfAngleDegrees, s.cullable ? " " : "*", s.sphereRadius, s.cullFraction, s.oracleFraction,
                         s.timesCulled, s.timesMissed, s.testLossTriangles, s.partitionLossTriangles)
            << (engine ? formatted(" %7zu", s.falseCulls) : "") << (quantised ? formatted(" %10zu", s.quantisationLossTriangles) : "")
            << '\n';
    }
}

void writeStatisticsText(const RunStatistics& run, std::ostream& out, size_t worstClusters) {
    out << run.meshName << ": " << run.vertices << " vertices, " << run.triangles << " triangles in " << run.clusters
        << " clusters (" << toString(run.settings.builder) << "), " << run.viewCount << (run.viewCount == 1 ? " view" : " views")
        << '\n';
    const std::string fellBack = bestEffortNote(run.bestEffort);
    if (!fellBack.empty()) out << "  " << fellBack << '\n';
    for (const CullTestStatistics& r : run.results) {
        out << '\n' << toString(r.cone) << " cone, " << toString(r.test) << " test\n";
        out << formatted("  efficiency        %.3f of the back faces culled (mean per view %.3f), false culls %zu\n", r.efficiency,
                         r.meanViewEfficiency, r.falseCulls);
        out << formatted("  not culled        %.3f lost by the test (whole cluster faced away), %.3f by the partition "
                         "(cluster also held a visible face)\n",
                         share(r.testLossTriangles, r.backFacingTriangles), share(r.partitionLossTriangles, r.backFacingTriangles));
        out << formatted("  record            %zu bytes a cluster%s", r.bytesPerCluster,
                         r.engineRecord ? ", an engine's as it ships (not conservative: its false culls are above)" : "");
        if (hasFloatOriginal(r.test))
            out << formatted(", quantisation loss %.3f (back faces its float original culls)", share(r.quantisationLossTriangles, r.backFacingTriangles));
        out << '\n';
        out << formatted("  from any side     the test culls %.3f of the directions, every face faces away from %.3f "
                         "(triangle-weighted)\n",
                         r.cullFraction, r.oracleFraction);
        out << formatted("  clusters          %.1f triangles and %.1f vertices on average, sphere radius mean %.4g max %.4g, "
                         "%zu never cullable\n",
                         r.meanClusterTriangles, r.meanClusterVertices, r.meanSphereRadius, r.maxSphereRadius, r.uncullableClusters);
        const std::string nothing = uncullableNote(r.uncullableClusters, r.clusters.size());
        if (!nothing.empty()) out << "  most uncullable   " << nothing << '\n';
        if (worstClusters == 0 || r.clusters.empty()) continue;
        out << "  worst clusters by test loss (alpha* = never cullable):\n";
        writeClusterTableText(r, rankClusters(r, ClusterSortKey::TestLoss, worstClusters), out);
    }
    const MultiConeCulling& m = run.multiCones;
    if (m.cones > 0)
        out << formatted("\n%u cones per cluster (%s cone's clusters, sub-group cones, each cluster's sphere)\n"
                         "  efficiency        %.3f of the back faces culled, false culls %zu, record %zu bytes a cluster\n",
                         m.cones, toString(run.settings.cones.front()).c_str(), m.efficiency, m.falseCulls, m.bytesPerCluster);
}

}  // namespace conescope
