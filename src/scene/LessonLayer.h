// Layer::Lesson: what a lesson step shows of the picked cluster in 3D (core/Lesson.h), V1 up:
//   1 its face normals as arrows on its faces;
//   2 the arrows slid to one point above the cluster, their tips on the Gauss sphere;
//   3 the cone that holds them, around V1 with half-angle alpha, and the other cone's rim beside it
//     (the average cone beside the minimal one, or the minimal beside any other);
//   4 the bound the test uses: the apex and its lines to the cluster's outline, the bounding sphere,
//     the box's corners or the vertices, over the cluster's faces drawn see-through;
//   5, 6 the bound again (the test layer draws the eye, the view vector and the region);
//   7 the cluster and its partner (the nearest the same eye decides the other way), each outlined,
//     with its axis V1 and its view vector from the eye.
// A cluster without a cone gets no axis and no apex. Step 0 draws nothing. Also what each step shows besides (lessonLayers) and where it looks from
// (lessonCamera), for the window and the headless pictures alike.
#pragma once

#include <map>
#include <optional>

#include "core/Lesson.h"
#include "scene/SceneLayer.h"

namespace conescope {

struct LessonDrawing {
    int step = 0;                  // 1 .. kLessonStepCount; 0 = none
    std::optional<Lesson> lesson;  // present whenever step > 0
};

// The Gauss sphere of step 2 floats above the cluster along V1, clear of the surface.
double gaussSphereRadius(const Lesson& lesson);
glm::dvec3 gaussSphereCentre(const Lesson& lesson);

// The layers a step talks about (all others hidden) and the face colouring it needs: the clusters
// first, the decision when the eye comes in (step 5), the loss classes for the verdict (step 6).
std::map<Layer, bool> lessonLayers(int step);
FaceColoring lessonColouring(int step);

// Where a step looks from, V1 pointing up: at the cluster (and the Gauss sphere) from the side, at
// the cluster and the eye together for the test (step 5), at the cluster's faces for the verdict.
struct CameraPlacement {
    glm::dvec3 focalPoint{0.0};
    glm::dvec3 position{0.0, 0.0, 1.0};
    glm::dvec3 viewUp{0.0, 1.0, 0.0};
};
CameraPlacement lessonCamera(const Lesson& lesson, int step, double viewAngleDegrees);

class LessonLayer : public SceneLayer {
public:
    explicit LessonLayer(const SceneData& data);

    std::vector<vtkActor*> actors() const override;
    bool hasContent() const override { return drawing_.step > 0 && drawing_.lesson.has_value(); }
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;
    // Arrows, spheres and bounds are no part of the cluster's surface: picking finds none.
    int clusterOfCell(vtkActor*, vtkIdType) const override { return -1; }

    // Throws std::out_of_range for a lesson on a cluster the scene does not have.
    void setDrawing(const LessonDrawing& drawing);
    const LessonDrawing& drawing() const { return drawing_; }

private:
    void drawGaussSphere(const Lesson& lesson, bool withCones);
    void drawBound(const Lesson& lesson);
    void drawSideBySide(const Lesson& lesson);

    vtkSmartPointer<vtkActor> outline_, faces_, faceArrows_, gaussSphere_, gaussArrows_, tips_, cone_, coneRim_, otherRim_, axis_,
        bound_, boundPoints_, partnerOutline_, views_;
    LessonDrawing drawing_;
};

}  // namespace conescope
