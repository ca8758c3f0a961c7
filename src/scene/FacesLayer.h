// Layer::Faces: the mesh polydata, coloured by cluster, by cull decision or per face by the oracle.
#pragma once

#include <vector>

#include "core/Culling.h"
#include "scene/SceneLayer.h"

namespace conescope {

class FacesLayer : public SceneLayer {
public:
    explicit FacesLayer(const SceneData& data);

    std::vector<vtkActor*> actors() const override { return {actor_}; }
    // Switches the mapper between the cluster_id array (palette or decision table) and the facing array.
    void recolour(FaceColoring coloring) override;
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;

    // The oracle's per-face result (classifyFaces) into the mesh's "facing" array.
    // Throws std::invalid_argument on a size mismatch.
    void setFaceFacing(const std::vector<Facing>& facing);

private:
    vtkSmartPointer<vtkPolyDataMapper> mapper_;
    vtkSmartPointer<vtkActor> actor_;
    bool hasFacing_ = false;
};

}  // namespace conescope
