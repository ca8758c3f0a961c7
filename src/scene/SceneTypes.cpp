#include "scene/SceneTypes.h"

namespace conescope {

const std::vector<Layer>& allLayers() {
    static const std::vector<Layer> layers = {Layer::Faces, Layer::Borders, Layer::Cones,     Layer::Normals, Layer::Boxes,
                                              Layer::Spheres, Layer::Eye,   Layer::Highlight, Layer::Legend};
    return layers;
}

std::string toString(Layer layer) {
    switch (layer) {
    case Layer::Faces: return "faces";
    case Layer::Borders: return "borders";
    case Layer::Cones: return "cones";
    case Layer::Normals: return "normals";
    case Layer::Boxes: return "boxes";
    case Layer::Spheres: return "spheres";
    case Layer::Eye: return "eye";
    case Layer::Highlight: return "highlight";
    case Layer::Legend: return "legend";
    }
    return "unknown";
}

std::string toString(FaceColoring coloring) {
    switch (coloring) {
    case FaceColoring::Cluster: return "cluster";
    case FaceColoring::CullDecision: return "decision";
    case FaceColoring::FaceFacing: return "facing";
    }
    return "unknown";
}

}  // namespace conescope
