// Layer::Borders: edges between faces of different clusters and open edges, as dark lines on the
// mesh's own points.
#pragma once

#include "scene/SceneLayer.h"

namespace conescope {

class BordersLayer : public SceneLayer {
public:
    // mesh and partition: as given to the scene (the edges are found once, here).
    BordersLayer(const SceneData& data, const Mesh& mesh, const Partition& partition);

    std::vector<vtkActor*> actors() const override { return {actor_}; }
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;

    vtkPolyData* lines() const { return lines_; }  // cell array cluster_id = cluster of one adjacent face

private:
    vtkSmartPointer<vtkPolyData> lines_;
    vtkSmartPointer<vtkActor> actor_;
};

}  // namespace conescope
