#include "scene/BordersLayer.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>

#include "scene/SceneGeometry.h"

namespace conescope {

BordersLayer::BordersLayer(const SceneData& data, const Mesh& mesh, const Partition& partition)
    : SceneLayer(data), lines_(polyDataFrom(borderEdges(mesh, partition), CellKind::Lines, data.points)),
      actor_(lineActor(plainMapper(lines_), 1.5)) {
    setColour(actor_, SceneColours::border);
}

void BordersLayer::addLegendEntries(FaceColoring, std::vector<LegendEntry>& entries) const {
    entries.push_back({"cluster borders", {SceneColours::border}});
}

}  // namespace conescope
