// Layer::Cones, Layer::Boxes and Layer::Spheres: one glyph per cluster (normal cone, AABB, bounding
// sphere), each cell carrying its cluster id, coloured through the palette or the decision table.
#pragma once

#include <string>

#include "scene/SceneLayer.h"

namespace conescope {

class GlyphLayer : public SceneLayer {
public:
    // glyphs: a polydata with a cluster_id cell array; lineWidth 0 draws surfaces instead of lines.
    GlyphLayer(const SceneData& data, vtkSmartPointer<vtkPolyData> glyphs, double lineWidth, std::string legendLabel);

    std::vector<vtkActor*> actors() const override { return {actor_}; }
    // The glyphs follow the faces' cluster or decision colours (the palette while faces show facing).
    void recolour(FaceColoring coloring) override;
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;

    vtkPolyData* glyphs() const { return glyphs_; }

private:
    vtkSmartPointer<vtkPolyData> glyphs_;
    vtkSmartPointer<vtkPolyDataMapper> mapper_;
    vtkSmartPointer<vtkActor> actor_;
    std::string legendLabel_;
};

// Translucent cones of the cullable clusters (see Layer::Cones).
GlyphLayer conesLayer(const SceneData& data);
// 12 lines per cluster, in cluster order.
GlyphLayer boxesLayer(const SceneData& data);
// Three circles per cluster.
GlyphLayer spheresLayer(const SceneData& data);

}  // namespace conescope
