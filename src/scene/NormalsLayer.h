// Layer::Normals: face normals as arrows at (a regular subset of) the face centroids. The glyph filter
// only runs once the layer is shown, so a hidden layer costs nothing on a large mesh.
#pragma once

#include "scene/SceneLayer.h"

class vtkGlyph3D;

namespace conescope {

class NormalsLayer : public SceneLayer {
public:
    // faces and partition: as given to the scene; at most maxNormalArrows arrows, degenerate faces skipped.
    NormalsLayer(const SceneData& data, const FaceGeometry& faces, const Partition& partition);

    std::vector<vtkActor*> actors() const override { return {actor_}; }
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;

private:
    vtkSmartPointer<vtkPolyData> centroids_;  // points with vectors "normal" and point array cluster_id
    vtkSmartPointer<vtkGlyph3D> arrows_;
    vtkSmartPointer<vtkActor> actor_;
};

}  // namespace conescope
