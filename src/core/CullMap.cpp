#include "CullMap.h"

#include <algorithm>

#include "Parallel.h"
#include "Views.h"

namespace conescope {

namespace {

// Share of directions u with n.u < 0 for every normal: all faces back-facing from an eye far along u.
// Directions inside the cone test's cap (strictly) are back-facing for every face the cone holds, and
// those more than 90 + alpha from -axis are not: the cap's exact share plus the sampled share of the
// band between, so the oracle's share is never below the cone's.
double oracleShare(const std::vector<glm::dvec3>& normals, const ConeOfNormals& cone,
                   const std::vector<glm::dvec3>& directions) {
    if (normals.empty()) return 0.0;
    size_t culled = 0;
    for (const glm::dvec3& u : directions) {
        const double along = -glm::dot(u, cone.axis);  // cos of the angle between u and -axis
        if (cone.cullable && (along > cone.sinHalfAngle || along < -cone.sinHalfAngle)) continue;
        bool allBack = true;
        for (const glm::dvec3& n : normals)
            if (!(glm::dot(n, u) < 0.0)) {
                allBack = false;
                break;
            }
        culled += allBack;
    }
    const double sampled = double(culled) / double(directions.size());
    return cone.cullable ? std::min(1.0, coneCullShare(cone.sinHalfAngle) + sampled) : sampled;
}

}  // namespace

CullMap computeCullMap(const FaceGeometry& faces, const ClusterBounds& bounds, size_t directionCount) {
    const size_t clusterCount = bounds.count();
    CullMap map{std::vector<double>(clusterCount, 0.0), std::vector<double>(clusterCount, 0.0), std::vector<double>(clusterCount, 0.0)};
    const std::vector<glm::dvec3> directions = spiralDirections(directionCount);
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
            // The octagon's region lies inside the oracle's, exactly measured: the sampled estimate
            // is never let below it.
            map.oracleFraction[c] = std::max(oracleShare(normals, cone, directions), map.octagonFraction[c]);
        }
    });
    return map;
}

double cullFraction(const CullMap& map, uint32_t cluster, CullTest test) {
    if (test == CullTest::Oracle) return map.oracleFraction[cluster];
    return test == CullTest::Octagon ? map.octagonFraction[cluster] : map.coneFraction[cluster];
}

}  // namespace conescope
