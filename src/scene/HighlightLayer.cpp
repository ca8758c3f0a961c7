#include "scene/HighlightLayer.h"

#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include "scene/SceneGeometry.h"

namespace conescope {

HighlightLayer::HighlightLayer(const SceneData& data)
    : SceneLayer(data), outline_(lineActor(plainMapper(emptyPolyData()), 4.0)), cone_(actorFor(plainMapper(emptyPolyData()))),
      box_(lineActor(plainMapper(emptyPolyData()), 3.0)), sphere_(lineActor(plainMapper(emptyPolyData()), 2.5)) {
    for (vtkActor* actor : actors()) setColour(actor, SceneColours::highlight);
    // Half see-through: the cluster's faces and its test's drawing stay visible behind its cone.
    cone_->GetProperty()->SetOpacity(0.5);
}

void HighlightLayer::addLegendEntries(FaceColoring, std::vector<LegendEntry>& entries) const {
    entries.push_back({"picked cluster " + std::to_string(cluster_), {SceneColours::highlight}});
}

void HighlightLayer::setCluster(int cluster) {
    const size_t clusterCount = data_.palette.size();
    if (cluster < -1 || cluster >= int(clusterCount))
        throw std::out_of_range("setHighlightedCluster: cluster " + std::to_string(cluster) + " of " + std::to_string(clusterCount));
    cluster_ = cluster;
    if (cluster < 0) {
        for (vtkActor* actor : actors()) setInput(actor, emptyPolyData());
    } else {
        const ClusterBounds& bounds = data_.bounds;
        const uint32_t* faces = bounds.faces.faces.data() + bounds.faces.starts[cluster];
        const size_t count = bounds.faces.starts[cluster + 1] - bounds.faces.starts[cluster];
        setInput(outline_, polyDataFrom(clusterOutline(data_.mesh, faces, count, cluster), CellKind::Lines, data_.points));
        GlyphGeometry cone, box, sphere;
        appendCone(cone, bounds.cones[cluster], bounds.spheres[cluster], cluster, coneSegments, data_.coneFallbackLength());
        appendBox(box, bounds.boxes[cluster], cluster);
        appendSphere(sphere, bounds.spheres[cluster], cluster, sphereSegments);
        setInput(cone_, polyDataFrom(cone, CellKind::Polygons));
        setInput(box_, polyDataFrom(box, CellKind::Lines));
        setInput(sphere_, polyDataFrom(sphere, CellKind::Lines));
    }
    applyVisibility();
}

}  // namespace conescope
