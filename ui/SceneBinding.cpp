#include "SceneBinding.h"

#include "core/RecordTests.h"

#include "core/CullMap.h"
#include "core/MultiConeCulling.h"

namespace conescope {

std::map<Layer, bool> firstLookLayers() {
    std::map<Layer, bool> layers;
    for (Layer layer : allLayers())
        layers[layer] = layer != Layer::Normals && layer != Layer::Spheres && layer != Layer::Cones && layer != Layer::Boxes;
    return layers;
}

std::unique_ptr<ClusterScene> makeScene(const PreparedMesh& prepared, const ClusterSet& clusters) {
    return std::make_unique<ClusterScene>(prepared.mesh(), prepared.world, prepared.faces, clusters.partition,
                                          clusters.bounds);
}

void showMeasurement(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters,
                     const EyeMeasurement& measurement) {
    scene.setClusterDecisions(measurement.culled, allBackFacingClusters(measurement));
    scene.setEye(measurement.eye, glm::dvec3(prepared.box.center()));
    const size_t count = clusters.bounds.count();
    std::vector<double> cull(count);
    std::vector<uint8_t> cullable(count);
    const CullingInput input = cullingInput(prepared, clusters);
    const CullTest test = measurement.statistics.test;
    for (uint32_t c = 0; c < count; ++c) {
        cull[c] = testCullFraction(clusters.cullMap, input, c, test);
        // A record of its own is cullable when it culls from somewhere, whatever the displayed cone says.
        cullable[c] = readsOwnRecord(test) ? cull[c] > 0.0 : clusters.bounds.cones[c].cullable || test == CullTest::Oracle;
    }
    scene.setClusterFractions(cull, clusters.cullMap.oracleFraction, cullable);
}

void showSubGroupsFromEye(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters, uint32_t cones, const Eye& eye) {
    if (cones <= 1) return;
    const MultiCones multi = computeMultiCones(prepared.mesh(), prepared.faces, clusters.bounds, cones);
    scene.setSubGroups(subGroupOfFace(multi, prepared.mesh().faceCount()), cullSubGroups(clusters.bounds, multi, eye), cones);
}

void showEyeColouring(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters,
                      const EyeMeasurement& measurement, FaceColoring coloring) {
    if (coloring != FaceColoring::FaceFacing && coloring != FaceColoring::Loss) return;
    const std::vector<Facing> facing = classifyFaces(prepared.mesh(), prepared.world, prepared.faces, measurement.eye);
    if (coloring == FaceColoring::FaceFacing) scene.setFaceFacing(facing);
    else scene.setFaceLoss(faceLosses(clusters, measurement, facing));
}

Comparison showComparison(ClusterScene& scene, const PreparedMesh& prepared, const ClusterConfiguration& a,
                          const ClusterConfiguration& b, const EyeMeasurement& measurement) {
    const std::vector<uint8_t> culledA = cullClusters(cullingInput(prepared, a.clusters), measurement.eye, displayedTest(a.settings));
    std::vector<FaceDiff> diff;
    Comparison comparison = compareAtEye(prepared, a, culledA, b, measurement.culled, measurement.eye, diff);
    scene.setFaceComparison(diff, clusterCountWarning(comparison));
    return comparison;
}

void showTestDrawing(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters, int cluster,
                     const EyeMeasurement& measurement) {
    if (cluster < 0 || cluster >= int(clusters.bounds.count())) {
        scene.setTestDrawing({});
        return;
    }
    scene.setTestDrawing(makeTestDrawing(cullingInput(prepared, clusters), uint32_t(cluster), measurement.eye,
                                         measurement.statistics.test));
}

}  // namespace conescope
