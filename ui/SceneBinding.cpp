#include "SceneBinding.h"

namespace conescope {

std::map<Layer, bool> firstLookLayers() {
    std::map<Layer, bool> layers;
    for (Layer layer : allLayers()) layers[layer] = layer != Layer::Normals && layer != Layer::Spheres;
    return layers;
}

std::unique_ptr<ClusterScene> makeScene(const PreparedMesh& prepared, const ClusterSet& clusters) {
    return std::make_unique<ClusterScene>(prepared.mesh(), prepared.world, prepared.faces, clusters.partition,
                                          clusters.bounds);
}

void showMeasurement(ClusterScene& scene, const PreparedMesh& prepared, const EyeMeasurement& measurement) {
    scene.setClusterDecisions(measurement.culled, allBackFacingClusters(measurement));
    scene.setEye(measurement.eye, glm::dvec3(prepared.box.center()));
}

void showFaceFacing(ClusterScene& scene, const PreparedMesh& prepared, const Eye& eye) {
    scene.setFaceFacing(classifyFaces(prepared.mesh(), prepared.world, prepared.faces, eye));
}

}  // namespace conescope
