#include "scene/GlyphLayer.h"

#include <utility>

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include "scene/SceneGeometry.h"

namespace conescope {

GlyphLayer::GlyphLayer(const SceneData& data, vtkSmartPointer<vtkPolyData> glyphs, double lineWidth, std::string legendLabel)
    : SceneLayer(data), glyphs_(std::move(glyphs)), mapper_(cellArrayMapper(glyphs_, clusterIdArrayName, data.tables.palette)),
      actor_(lineWidth > 0.0 ? lineActor(mapper_, lineWidth) : actorFor(mapper_)), legendLabel_(std::move(legendLabel)) {}

void GlyphLayer::recolour(FaceColoring coloring) { mapper_->SetLookupTable(data_.tables.forGlyphs(coloring)); }

void GlyphLayer::addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const {
    entries.push_back({legendLabel_, glyphLegendColours(coloring, data_.tables.hasLod())});
}

GlyphLayer conesLayer(const SceneData& data) {
    auto cones = polyDataFrom(coneGlyphs(data.bounds, coneSegments, data.coneFallbackLength()), CellKind::Polygons);
    GlyphLayer layer(data, cones, 0.0, "normal cones" + countLabel(size_t(cones->GetNumberOfCells() / coneSegments)));
    layer.actors().front()->GetProperty()->SetOpacity(coneOpacity);
    return layer;
}

GlyphLayer boxesLayer(const SceneData& data) {
    return GlyphLayer(data, polyDataFrom(boxGlyphs(data.bounds), CellKind::Lines), 1.5, "cluster AABBs");
}

GlyphLayer spheresLayer(const SceneData& data) {
    return GlyphLayer(data, polyDataFrom(sphereGlyphs(data.bounds, sphereSegments), CellKind::Lines), 1.0, "bounding spheres");
}

}  // namespace conescope
