#include "CullMap.h"

#include <algorithm>


namespace conescope {

namespace {

void mapClusters(const ClusterBounds& bounds, size_t begin, size_t end, CullMap& map) {
    for (size_t c = begin; c < end; ++c) {
        const ConeOfNormals& cone = bounds.cones[c];
        map.coneFraction[c] = cone.cullable ? coneCullShare(cone.sinHalfAngle) : 0.0;
        map.octagonFraction[c] = octagonCullShare(bounds.octagons[c]);
        // Exact areas: only rounding could put the oracle's below the regions it holds.
        map.oracleFraction[c] = std::max({bounds.normalsShares[c], map.octagonFraction[c], map.coneFraction[c]});
    }
}

CullMap sized(size_t clusterCount) {
    return CullMap{std::vector<double>(clusterCount, 0.0), std::vector<double>(clusterCount, 0.0), std::vector<double>(clusterCount, 0.0)};
}

}  // namespace

CullMap computeCullMap(const ClusterBounds& bounds) {
    CullMap map = sized(bounds.count());
    mapClusters(bounds, 0, bounds.count(), map);
    return map;
}

void appendCullMap(CullMap& map, CullMap&& more) {
    map.coneFraction.insert(map.coneFraction.end(), more.coneFraction.begin(), more.coneFraction.end());
    map.octagonFraction.insert(map.octagonFraction.end(), more.octagonFraction.begin(), more.octagonFraction.end());
    map.oracleFraction.insert(map.oracleFraction.end(), more.oracleFraction.begin(), more.oracleFraction.end());
}

double cullFraction(const CullMap& map, uint32_t cluster, CullTest test) {
    if (test == CullTest::Oracle) return map.oracleFraction[cluster];
    return test == CullTest::Octagon ? map.octagonFraction[cluster] : map.coneFraction[cluster];
}

}  // namespace conescope
