// Cluster colours where neighbours differ: a greedy colouring of the cluster adjacency graph over a
// small set of well-separated hues, with a per-cluster lightness jitter so that two far-apart
// clusters of the same hue still read as different clusters. Plain C++, no VTK.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/Mesh.h"
#include "core/Partition.h"

namespace conescope {

using Rgb = std::array<double, 3>;  // components in [0, 1]

// Clusters that share at least one vertex, as compressed rows: the neighbours of cluster c are
// neighbours[starts[c] .. starts[c + 1]), sorted, without c itself.
struct ClusterAdjacency {
    std::vector<uint32_t> starts;  // clusterCount + 1
    std::vector<uint32_t> neighbours;
};
ClusterAdjacency clusterAdjacency(const Mesh& mesh, const Partition& partition);

// Colour class of every cluster such that adjacent clusters never share a class. Largest degree
// first; among the free classes below hueCount it takes the one used least so far (so the hues stay
// balanced), and only when all of them are taken by neighbours it opens class hueCount, hueCount+1, ...
std::vector<uint32_t> colourClasses(const ClusterAdjacency& adjacency, uint32_t hueCount);

// The well-separated base hues (10). Classes beyond them get further hues spread by the golden angle.
const std::vector<Rgb>& baseHues();
Rgb colourOfClass(uint32_t colourClass);

// Final colour of every cluster: the colour of its class, lightened or darkened by a small
// deterministic amount that depends on the cluster id.
std::vector<Rgb> clusterPalette(const ClusterAdjacency& adjacency);

}  // namespace conescope
