// The clusters nearest to a cluster by centre, as the reduction asks for them when it merges or
// dissolves across gaps: a uniform grid of the live clusters' centres, kept up to date as clusters
// merge, move and empty. The answer is the scan's over every live cluster (the k smallest squared
// distances, ties by id); the grid only spares looking at far cells. Parts of many small pieces
// (foliage: hundreds of leaves in a part) asked the scan a few hundred times per merge level.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace conescope::optimizer {

class NearestCentres {
public:
    // Cluster c is in the grid when live[c]; centres and live are indexed by cluster id.
    NearestCentres(const std::vector<glm::dvec3>& centres, const std::vector<bool>& live);

    // The `limit` live clusters nearest to cluster c (not c itself), nearest first, ties by id.
    void nearest(uint32_t c, size_t limit, std::vector<uint32_t>& out);
    // The `limit` live clusters nearest to a point (all of them when fewer), nearest first, ties by id.
    void nearestTo(const glm::dvec3& point, size_t limit, std::vector<uint32_t>& out, uint32_t except = ~0u);
    // Cluster c has a new centre (within the box of the centres the grid was made with: a merged
    // or grown cluster's centre is a weighted mean of centres in it).
    void move(uint32_t c, const glm::dvec3& centre);
    // Cluster c is no longer live.
    void remove(uint32_t c);

private:
    size_t cellOf(const glm::dvec3& p, int axis) const;
    size_t indexOf(const glm::dvec3& p) const;

    std::vector<glm::dvec3> centres_;
    std::vector<uint32_t> cellOfCluster_;            // kNoCell when not live
    std::vector<uint32_t> live_;                     // the live clusters, in no order
    std::vector<uint32_t> placeInLive_;
    std::vector<std::vector<uint32_t>> cells_;      // cluster ids per cell
    glm::dvec3 low_{0.0};
    double cell_ = 1.0;
    size_t dims_[3] = {1, 1, 1};
    std::vector<std::pair<double, uint32_t>> found_;  // scratch for nearest
};

}  // namespace conescope::optimizer
