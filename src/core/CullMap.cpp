#include "CullMap.h"

#include <algorithm>

#include "Parallel.h"

namespace conescope {

CullMap computeCullMap(const FaceGeometry& faces, const ClusterBounds& bounds) {
    const size_t clusterCount = bounds.count();
    CullMap map{std::vector<double>(clusterCount, 0.0), std::vector<double>(clusterCount, 0.0), std::vector<double>(clusterCount, 0.0)};
    // Clusters are independent: each core takes a range of them.
    forRangesInParallel(clusterCount, 16, [&](size_t begin, size_t end) {
        std::vector<glm::dvec3> normals;
        for (size_t c = begin; c < end; ++c) {
            const ConeOfNormals& cone = bounds.cones[c];
            map.coneFraction[c] = cone.cullable ? coneCullShare(cone.sinHalfAngle) : 0.0;
            normals.clear();
            for (uint32_t i = bounds.faces.starts[c]; i < bounds.faces.starts[c + 1]; ++i)
                if (!faces.degenerate[bounds.faces.faces[i]]) normals.push_back(faces.normals[bounds.faces.faces[i]]);
            map.octagonFraction[c] = octagonCullShare(bounds.octagons[c]);
            // Exact areas: only rounding could put the oracle's below the regions it holds.
            map.oracleFraction[c] = std::max({normalsCullShare(normals.data(), normals.size(), &cone), map.octagonFraction[c],
                                              map.coneFraction[c]});
        }
    });
    return map;
}

double cullFraction(const CullMap& map, uint32_t cluster, CullTest test) {
    if (test == CullTest::Oracle) return map.oracleFraction[cluster];
    return test == CullTest::Octagon ? map.octagonFraction[cluster] : map.coneFraction[cluster];
}

}  // namespace conescope
