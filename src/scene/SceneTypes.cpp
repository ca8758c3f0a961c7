#include "scene/SceneTypes.h"

#include <algorithm>

namespace conescope {

const std::vector<Layer>& allLayers() {
    static const std::vector<Layer> layers = {Layer::Faces, Layer::Borders, Layer::Cones,     Layer::Normals, Layer::Boxes,
                                              Layer::Spheres, Layer::Eye,   Layer::Highlight, Layer::Test,
                                              Layer::Legend, Layer::Lesson};
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
    case Layer::Test: return "test";
    case Layer::Legend: return "legend";
    case Layer::Lesson: return "lesson";
    }
    return "unknown";
}

const std::vector<FaceColoring>& allFaceColorings() {
    static const std::vector<FaceColoring> colorings = {FaceColoring::Cluster,      FaceColoring::CullDecision,
                                                        FaceColoring::FaceFacing,   FaceColoring::CullFraction,
                                                        FaceColoring::OracleFraction, FaceColoring::Loss,
                                                        FaceColoring::Comparison,   FaceColoring::LodLevel,
                                                        FaceColoring::LodGroup,     FaceColoring::LodCut,
                                                        FaceColoring::SubGroup};
    return colorings;
}

// Five stops close to viridis: dark where little is culled, bright where much is.
Rgb fractionRamp(double t) {
    static const Rgb stops[] = {{0.27, 0.00, 0.33}, {0.23, 0.32, 0.55}, {0.13, 0.57, 0.55}, {0.37, 0.79, 0.38}, {0.99, 0.91, 0.14}};
    t = std::clamp(t, 0.0, 1.0) * 4.0;
    const int i = std::min(int(t), 3);
    const double f = t - i;
    Rgb colour;
    for (int k = 0; k < 3; ++k) colour[k] = stops[i][k] + (stops[i + 1][k] - stops[i][k]) * f;
    return colour;
}

Rgb lodLevelColour(size_t level) {
    static const Rgb hues[] = {{0.30, 0.75, 0.35}, {0.95, 0.85, 0.30}, {0.95, 0.55, 0.20}, {0.85, 0.25, 0.25},
                               {0.70, 0.25, 0.60}, {0.40, 0.30, 0.75}, {0.25, 0.55, 0.85}, {0.25, 0.75, 0.75}};
    return hues[level % 8];
}

std::string toString(FaceColoring coloring) {
    switch (coloring) {
    case FaceColoring::Cluster: return "cluster";
    case FaceColoring::CullDecision: return "decision";
    case FaceColoring::FaceFacing: return "facing";
    case FaceColoring::CullFraction: return "cull-fraction";
    case FaceColoring::OracleFraction: return "oracle-fraction";
    case FaceColoring::Loss: return "loss";
    case FaceColoring::Comparison: return "compare";
    case FaceColoring::LodLevel: return "lod-level";
    case FaceColoring::LodGroup: return "lod-group";
    case FaceColoring::LodCut: return "lod-cut";
    case FaceColoring::SubGroup: return "sub-group";
    }
    return "unknown";
}

}  // namespace conescope
