#include "CullMap.h"

#include <algorithm>

#include "RecordTests.h"

namespace conescope {

CullMap computeCullMap(const ClusterBounds& bounds) {
    const size_t clusterCount = bounds.count();
    CullMap map{std::vector<double>(clusterCount), std::vector<double>(clusterCount), std::vector<double>(clusterCount)};
    for (size_t c = 0; c < clusterCount; ++c) {
        const ConeOfNormals& cone = bounds.cones[c];
        map.coneFraction[c] = cone.cullable ? coneCullShare(cone.sinHalfAngle) : 0.0;
        map.octagonFraction[c] = octagonCullShare(bounds.octagons[c]);
        // Exact areas: only rounding could put the oracle's below the regions it holds.
        map.oracleFraction[c] = std::max({bounds.normalsShares[c], map.octagonFraction[c], map.coneFraction[c]});
    }
    return map;
}

double cullFraction(const CullMap& map, uint32_t cluster, CullTest test) {
    if (test == CullTest::Oracle) return map.oracleFraction[cluster];
    return test == CullTest::Octagon ? map.octagonFraction[cluster] : map.coneFraction[cluster];
}

double testCullFraction(const CullMap& map, const CullingInput& input, uint32_t cluster, CullTest test) {
    if (!readsOwnRecord(test)) return cullFraction(map, cluster, test);
    return ownRecordCullShare({input.mesh, input.world, input.faces, input.bounds}, cluster, test);
}

}  // namespace conescope
