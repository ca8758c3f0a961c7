// Layer::Eye: the cull eye's marker, and the camera that looks from the eye. A perspective eye is a
// ball at its position with a cone opening towards the point it looks at and the line of sight; an
// orthographic eye is an arrow along its direction, outside the mesh bounds.
#pragma once

#include <glm/glm.hpp>

#include "core/Views.h"
#include "scene/SceneLayer.h"

class vtkCamera;

namespace conescope {

class EyeLayer : public SceneLayer {
public:
    explicit EyeLayer(const SceneData& data);

    std::vector<vtkActor*> actors() const override { return {marker_}; }
    bool hasContent() const override { return hasEye_; }
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;
    // The marker is not a cluster's: picking it finds none.
    int clusterOfCell(vtkActor*, vtkIdType) const override { return -1; }

    // Rebuilds the marker for the eye looking at lookAt.
    void setEye(const Eye& eye, const glm::dvec3& lookAt);
    bool hasEye() const { return hasEye_; }
    const Eye& eye() const { return eye_; }  // Eye{} before setEye

    // Perspective eyes from the position towards lookAt, orthographic eyes with a parallel projection
    // along the direction; near and far planes and the view angle fitted to the mesh bounds.
    void applyToCamera(vtkCamera* camera) const;

private:
    vtkSmartPointer<vtkActor> marker_;
    bool hasEye_ = false;
    Eye eye_;
    glm::dvec3 lookAt_{0.0};
};

}  // namespace conescope
