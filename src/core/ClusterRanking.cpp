#include "ClusterRanking.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace conescope {

namespace {

const std::vector<std::pair<ClusterSortKey, const char*>>& sortKeyNames() {
    static const std::vector<std::pair<ClusterSortKey, const char*>> names = {
        {ClusterSortKey::TestLoss, "test-loss"},       {ClusterSortKey::PartitionLoss, "partition-loss"},
        {ClusterSortKey::Lost, "lost"},                {ClusterSortKey::Missed, "missed"},
        {ClusterSortKey::Triangles, "triangles"},      {ClusterSortKey::Vertices, "vertices"},
        {ClusterSortKey::HalfAngle, "half-angle"},     {ClusterSortKey::SphereRadius, "radius"},
        {ClusterSortKey::CullFraction, "cull-fraction"}, {ClusterSortKey::OracleFraction, "oracle-fraction"},
        {ClusterSortKey::Culled, "culled"},            {ClusterSortKey::FalseCulls, "false-culls"},
        {ClusterSortKey::QuantisationLoss, "quantisation-loss"}, {ClusterSortKey::MostCulled, "most-culled"}};
    return names;
}

// How bad a cluster is by `key`: larger is worse.
double badness(const ClusterStatistics& c, ClusterSortKey key) {
    switch (key) {
        case ClusterSortKey::TestLoss: return double(c.testLossTriangles);
        case ClusterSortKey::PartitionLoss: return double(c.partitionLossTriangles);
        case ClusterSortKey::Lost: return double(c.testLossTriangles + c.partitionLossTriangles);
        case ClusterSortKey::Missed: return double(c.timesMissed);
        case ClusterSortKey::Triangles: return double(c.triangles);
        case ClusterSortKey::Vertices: return double(c.vertices);
        case ClusterSortKey::HalfAngle: return c.halfAngleDegrees;
        case ClusterSortKey::SphereRadius: return c.sphereRadius;
        case ClusterSortKey::CullFraction: return -c.cullFraction;
        case ClusterSortKey::OracleFraction: return -c.oracleFraction;
        case ClusterSortKey::Culled: return -double(c.timesCulled);
        case ClusterSortKey::FalseCulls: return double(c.falseCulls);
        case ClusterSortKey::QuantisationLoss: return double(c.quantisationLossTriangles);
        case ClusterSortKey::MostCulled: return double(c.timesCulled);
    }
    return 0.0;
}

}  // namespace

std::string toString(ClusterSortKey key) {
    for (const auto& [entry, name] : sortKeyNames())
        if (entry == key) return name;
    return "unknown";
}

ClusterSortKey parseClusterSortKey(const std::string& text) {
    std::string accepted;
    for (const auto& [entry, name] : sortKeyNames()) {
        if (text == name) return entry;
        accepted += (accepted.empty() ? "" : ", ") + std::string(name);
    }
    throw std::invalid_argument("unknown sort key '" + text + "' (expected one of: " + accepted + ")");
}

const std::vector<ClusterSortKey>& allClusterSortKeys() {
    static const std::vector<ClusterSortKey> all = [] {
        std::vector<ClusterSortKey> keys;
        for (const auto& entry : sortKeyNames()) keys.push_back(entry.first);
        return keys;
    }();
    return all;
}

std::vector<uint32_t> rankClusters(const CullTestStatistics& statistics, ClusterSortKey key, size_t top) {
    std::vector<uint32_t> order(statistics.clusters.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return badness(statistics.clusters[a], key) > badness(statistics.clusters[b], key);
    });
    if (top > 0 && top < order.size()) order.resize(top);
    for (uint32_t& index : order) index = statistics.clusters[index].cluster;
    return order;
}

}  // namespace conescope
