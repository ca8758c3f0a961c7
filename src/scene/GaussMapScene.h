// The Gauss-map inspector's picture: a cluster's face normals as points on the unit sphere, the cap of
// every cone method around them (average, seed-sphere, minimal, meshopt; the displayed one filled),
// the octagon test's eight-sided cone around the displayed method's axis, and the test's view vector v with its horizon, the great circle bounding the hemisphere n.v > 0
// where every normal of a back-facing cluster lies. A cone test culls when the cap clears the
// horizon by the margin, which is why the smallest cap (the minimal cone) culls most. VTK only.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/ClusterBounds.h"
#include "core/CullTestGeometry.h"
#include "scene/SceneLegend.h"
#include "scene/SceneTypes.h"

class vtkActor;
class vtkCamera;
class vtkImageData;
class vtkRenderer;

namespace conescope {

// The colour each cone method's cap is drawn in.
Rgb coneMethodColour(ConeMethod method);

// One sub-group's cone of K cones per cluster, and its verdict from the eye.
struct SubGroupCap {
    ConeOfNormals cone;
    size_t triangles = 0;
    bool culled = false;
};
// The colour sub-group `index`'s rim is drawn in (up to 8).
Rgb subGroupCapColour(size_t index);

class GaussMapScene {
public:
    GaussMapScene();
    ~GaussMapScene();
    GaussMapScene(const GaussMapScene&) = delete;
    GaussMapScene& operator=(const GaussMapScene&) = delete;

    // Shows `map` of cluster `cluster`, with the cap of `displayed` filled; nullopt clears the picture.
    void show(const std::optional<GaussMap>& map, ConeMethod displayed, int cluster = -1);
    bool hasMap() const;
    // After show(): the cluster's K sub-group cones as rims on the sphere, each with its verdict in the
    // legend; empty hides them.
    void showSubGroups(const std::vector<SubGroupCap>& caps);
    size_t subGroupRimsShown() const;

    void addTo(vtkRenderer* renderer) const;
    void removeFrom(vtkRenderer* renderer) const;
    // Looks at the unit sphere from the side of the displayed cap, with v's horizon in view.
    void placeCamera(vtkCamera* camera) const;
    const SceneLegend& legend() const;
    // The legend's size for a view this many pixels high (SceneLegend::setScale).
    void fitLegend(int viewHeight, double pixelRatio = 1.0);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Renders the Gauss map alone into an RGB image (multisampling off), as renderToImage does for the
// cluster scene. Needs an X display.
vtkSmartPointer<vtkImageData> renderGaussMapToImage(const GaussMapScene& scene, int width, int height);

}  // namespace conescope
