#include "scene/ClusterPalette.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace conescope {

ClusterAdjacency clusterAdjacency(const Mesh& mesh, const Partition& partition) {
    const uint32_t clusterCount = partition.clusterCount;
    // Clusters around each vertex as (vertex, cluster) pairs; sorting them groups every vertex's
    // clusters, and each group yields the pairs of clusters that meet at that vertex.
    std::vector<uint64_t> vertexClusters;
    vertexClusters.reserve(mesh.faceVertices.size());
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint64_t cluster = partition.clusterOfFace[f];
        for (size_t k = 0; k < mesh.faceSize(f); ++k) vertexClusters.push_back(uint64_t(mesh.faceBegin(f)[k]) << 32 | cluster);
    }
    std::sort(vertexClusters.begin(), vertexClusters.end());
    vertexClusters.erase(std::unique(vertexClusters.begin(), vertexClusters.end()), vertexClusters.end());

    std::vector<uint64_t> pairs;
    for (size_t begin = 0; begin < vertexClusters.size();) {
        size_t end = begin + 1;
        while (end < vertexClusters.size() && (vertexClusters[end] >> 32) == (vertexClusters[begin] >> 32)) ++end;
        for (size_t i = begin; i < end; ++i)
            for (size_t j = begin; j < end; ++j)
                if (i != j) pairs.push_back((vertexClusters[i] & 0xffffffffu) << 32 | (vertexClusters[j] & 0xffffffffu));
        begin = end;
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

    ClusterAdjacency adjacency;
    adjacency.starts.assign(clusterCount + 1, 0);
    adjacency.neighbours.reserve(pairs.size());
    for (uint64_t pair : pairs) {
        adjacency.starts[(pair >> 32) + 1]++;
        adjacency.neighbours.push_back(uint32_t(pair & 0xffffffffu));
    }
    for (uint32_t c = 0; c < clusterCount; ++c) adjacency.starts[c + 1] += adjacency.starts[c];
    return adjacency;
}

std::vector<uint32_t> colourClasses(const ClusterAdjacency& adjacency, uint32_t hueCount) {
    const size_t clusterCount = adjacency.starts.empty() ? 0 : adjacency.starts.size() - 1;
    auto degree = [&](size_t c) { return adjacency.starts[c + 1] - adjacency.starts[c]; };
    std::vector<uint32_t> order(clusterCount);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return degree(a) > degree(b); });

    const uint32_t unset = ~0u;
    std::vector<uint32_t> classes(clusterCount, unset);
    std::vector<size_t> uses;         // clusters per class so far
    std::vector<size_t> takenBy;      // takenBy[k] == c + 1 when a neighbour of c holds class k
    for (uint32_t c : order) {
        for (uint32_t i = adjacency.starts[c]; i < adjacency.starts[c + 1]; ++i) {
            const uint32_t k = classes[adjacency.neighbours[i]];
            if (k == unset) continue;
            if (k >= takenBy.size()) takenBy.resize(k + 1, 0);
            takenBy[k] = size_t(c) + 1;
        }
        auto taken = [&](uint32_t k) { return k < takenBy.size() && takenBy[k] == size_t(c) + 1; };
        uint32_t chosen = unset;
        for (uint32_t k = 0; k < hueCount; ++k) {
            if (taken(k)) continue;
            if (chosen == unset || (k < uses.size() ? uses[k] : 0) < (chosen < uses.size() ? uses[chosen] : 0)) chosen = k;
        }
        for (uint32_t k = hueCount; chosen == unset; ++k)
            if (!taken(k)) chosen = k;
        if (chosen >= uses.size()) uses.resize(chosen + 1, 0);
        uses[chosen]++;
        classes[c] = chosen;
    }
    return classes;
}

const std::vector<Rgb>& baseHues() {
    // Tableau-like categorical hues, with yellow in place of grey (grey means "culled").
    static const std::vector<Rgb> hues = {
        {0.12, 0.47, 0.71}, {1.00, 0.50, 0.05}, {0.17, 0.63, 0.17}, {0.84, 0.15, 0.16}, {0.58, 0.40, 0.74},
        {0.55, 0.34, 0.29}, {0.89, 0.47, 0.76}, {0.95, 0.85, 0.20}, {0.74, 0.74, 0.13}, {0.09, 0.75, 0.81},
    };
    return hues;
}

namespace {

Rgb hsvToRgb(double hue, double saturation, double value) {
    const double h = std::fmod(hue, 1.0) * 6.0;
    const int sector = int(h) % 6;
    const double f = h - std::floor(h);
    const double p = value * (1 - saturation), q = value * (1 - saturation * f), t = value * (1 - saturation * (1 - f));
    switch (sector) {
    case 0: return {value, t, p};
    case 1: return {q, value, p};
    case 2: return {p, value, t};
    case 3: return {p, q, value};
    case 4: return {t, p, value};
    default: return {value, p, q};
    }
}

// A fixed value in [-1, 1] per cluster id (integer hash), so the jitter is the same on every run.
double jitterOf(uint32_t cluster) {
    uint32_t x = cluster * 0x9e3779b9u;
    x ^= x >> 16;
    x *= 0x85ebca6bu;
    x ^= x >> 13;
    return double(x % 2001u) / 1000.0 - 1.0;
}

}  // namespace

Rgb colourOfClass(uint32_t colourClass) {
    const auto& hues = baseHues();
    if (colourClass < hues.size()) return hues[colourClass];
    // Beyond the base hues: golden-angle steps around the hue circle, alternating two saturations.
    const uint32_t extra = colourClass - uint32_t(hues.size());
    return hsvToRgb(0.05 + extra * 0.618033988749895, extra % 2 ? 0.45 : 0.75, 0.85);
}

std::vector<Rgb> clusterPalette(const ClusterAdjacency& adjacency) {
    const std::vector<uint32_t> classes = colourClasses(adjacency, uint32_t(baseHues().size()));
    std::vector<Rgb> palette(classes.size());
    for (uint32_t c = 0; c < classes.size(); ++c) {
        // Mix up to 22% towards white or black: visible between same-hue clusters, never a new hue.
        const double jitter = 0.22 * jitterOf(c);
        const Rgb base = colourOfClass(classes[c]);
        for (int i = 0; i < 3; ++i)
            palette[c][i] = jitter > 0 ? base[i] + (1.0 - base[i]) * jitter : base[i] * (1.0 + jitter);
    }
    return palette;
}

}  // namespace conescope
