#include "MultiConeCulling.h"

#include <algorithm>
#include <cmath>


namespace conescope {

size_t multiConeBytesPerCluster(const MultiCones& multi) {
    const uint32_t k = std::max<uint32_t>(multi.conesPerCluster, 1);
    size_t largest = 0;
    for (size_t first = 0; first + k <= multi.groupTriangles.size(); first += k) {
        size_t triangles = 0;
        for (uint32_t g = 0; g < k; ++g) triangles += multi.groupTriangles[first + g];
        largest = std::max(largest, triangles);
    }
    return multiConeRecordBytes(k, largest, false);
}

void addMultiConeView(MultiConeCulling& total, const SubGroupRecord& record, const Mesh& mesh,
                      const std::vector<Facing>& facing, const Eye& eye) {
    const SubGroupCulling counted = countSubGroupCulling(record, facing, eye);
    total.trianglesCulled += counted.trianglesCulled;
    total.falseCulls += counted.falseCulls;
    total.backFacingTriangles += backFacingTriangles(mesh, facing);
    total.efficiency = cullEfficiency(total.trianglesCulled, total.backFacingTriangles);
}

MultiConeCulling measureMultiCones(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                   const SubGroupRecord& record, const std::vector<Eye>& views,
                                   const ProgressCallback& progress) {
    MultiConeCulling total;
    total.cones = record.multi->conesPerCluster;
    total.bytesPerCluster = multiConeBytesPerCluster(*record.multi);
    for (size_t v = 0; v < views.size(); ++v) {
        reportProgress(progress, double(v) / double(views.size()), "cones per cluster");
        addMultiConeView(total, record, mesh, classifyFaces(mesh, world, faces, views[v]), views[v]);
    }
    total.efficiency = cullEfficiency(total.trianglesCulled, total.backFacingTriangles);
    return total;
}

MultiConeCulling measureMultiConeRun(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                     const ClusterBounds& bounds, uint32_t conesPerCluster, const std::vector<Eye>& views,
                                     const ProgressCallback& progress) {
    const MultiCones multi = computeMultiCones(mesh, faces, bounds, conesPerCluster);
    const SubGroupRecord record = subGroupRecord(multi, multi.cones, bounds.spheres);
    return measureMultiCones(mesh, world, faces, record, views, progress);
}

std::vector<SubGroupVerdict> subGroupVerdicts(const MultiCones& multi, uint32_t cluster, const std::vector<uint8_t>& culled,
                                              const std::vector<Facing>& facing) {
    std::vector<SubGroupVerdict> verdicts;
    const uint32_t k = std::max<uint32_t>(multi.conesPerCluster, 1);
    for (uint32_t g = cluster * k; g < (cluster + 1) * k && g < multi.groupCount(); ++g) {
        SubGroupVerdict& verdict = verdicts.emplace_back();
        verdict.group = g;
        verdict.faces = multi.groupStarts[g + 1] - multi.groupStarts[g];
        verdict.triangles = multi.groupTriangles[g];
        verdict.cullable = multi.cones[g].cullable;
        verdict.halfAngleDegrees = multi.cones[g].cullable ? multi.cones[g].halfAngle() * 180.0 / M_PI : 90.0;
        verdict.culled = g < culled.size() && culled[g];
        verdict.allBackFacing = verdict.faces > 0;
        for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i)
            if (facing[multi.faces[i]] != Facing::Back) verdict.allBackFacing = false;
    }
    return verdicts;
}

std::vector<uint8_t> subGroupOfFace(const MultiCones& multi, size_t faceCount) {
    std::vector<uint8_t> group(faceCount, 0);
    const uint32_t k = std::max<uint32_t>(multi.conesPerCluster, 1);
    for (size_t g = 0; g < multi.groupCount(); ++g)
        for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i) group[multi.faces[i]] = uint8_t(g % k);
    return group;
}

SubGroupEyeCounts countCulledSubGroups(const MultiCones& multi, const std::vector<uint8_t>& culled, const std::vector<Facing>& facing) {
    SubGroupEyeCounts counts;
    counts.groups = multi.groupCount();
    for (size_t g = 0; g < culled.size() && g < multi.groupCount(); ++g) {
        if (!culled[g]) continue;
        ++counts.groupsCulled;
        counts.trianglesCulled += multi.groupTriangles[g];
        for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i)
            if (facing[multi.faces[i]] != Facing::Back) {
                ++counts.falseCulls;
                break;
            }
    }
    return counts;
}

}  // namespace conescope
