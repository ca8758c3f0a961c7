// Layer::Highlight: the picked cluster's outline, half see-through cone, box and sphere in one bright colour,
// shown whatever the Cones / Boxes / Spheres layers say.
#pragma once

#include "scene/SceneLayer.h"

namespace conescope {

class HighlightLayer : public SceneLayer {
public:
    explicit HighlightLayer(const SceneData& data);

    // Outline first: the layer's main actor.
    std::vector<vtkActor*> actors() const override { return {outline_, cone_, box_, sphere_}; }
    bool hasContent() const override { return cluster_ >= 0; }
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;

    // -1 = none. Throws std::out_of_range for an id outside [-1, K).
    void setCluster(int cluster);
    int cluster() const { return cluster_; }

private:
    vtkSmartPointer<vtkActor> outline_, cone_, box_, sphere_;
    int cluster_ = -1;
};

}  // namespace conescope
