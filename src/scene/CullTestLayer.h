// Layer::Test: the picked cluster's cull test drawn in 3D for the current eye. The cone axis V1 from
// the sphere centre, the point the view vector aims at (the apex, or the sphere centre), the view
// vector from the eye, the region of eye positions from which the test culls the cluster
// (translucent, core/CullTestGeometry.h: a round cone or funnel, the octagon test's pyramid), and
// the points a vertex or box test looks at, coloured by their verdict, box corners numbered as in
// the picked-cluster panel.
#pragma once

#include "core/Culling.h"
#include "core/CullTestGeometry.h"
#include "scene/SceneLayer.h"

class vtkActor2D;

namespace conescope {

// What the layer draws: one cluster's test from one eye.
struct CullTestDrawing {
    int cluster = -1;                 // -1: nothing
    CullTest test = kDefaultTest;
    Eye eye;
    CullExplanation why;
    Sphere sphere;                    // the cluster's bounding sphere
    CullRegion region;
};
// explainCull and cullRegion for the drawing; the region reaches eight sphere radii or to the eye,
// whichever is nearer (four radii for an orthographic eye).
CullTestDrawing makeTestDrawing(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test);
// The point the drawing's view vector aims at: the apex for a perspective apex or octagon test, else
// the sphere centre.
glm::dvec3 testViewTarget(const CullTestDrawing& drawing, const Sphere& sphere);

class CullTestLayer : public SceneLayer {
public:
    explicit CullTestLayer(const SceneData& data);

    // Region first: the layer's main actor.
    std::vector<vtkActor*> actors() const override;
    std::vector<vtkProp*> overlays() const override;
    bool hasContent() const override { return drawing_.cluster >= 0; }
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;
    // The drawing is about one cluster, but its parts are not the cluster's surface: picking finds none.
    int clusterOfCell(vtkActor*, vtkIdType) const override { return -1; }

    // Throws std::out_of_range for a cluster outside [-1, K).
    void setDrawing(const CullTestDrawing& drawing);
    const CullTestDrawing& drawing() const { return drawing_; }

private:
    vtkSmartPointer<vtkActor> region_, regionOutline_, axis_, view_, target_, points_;
    vtkSmartPointer<vtkActor2D> labels_;
    CullTestDrawing drawing_;
};

}  // namespace conescope
