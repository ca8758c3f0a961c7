// The observer's view: the interactive trackball camera on a gradient background, showing a
// ClusterScene and the cull eye's 3D handle. A click (press and release without a drag) asks for a
// pick, the handle reports where it was dragged, and while following, the camera reports where it
// moved. It holds no scene and no eye of its own: the window hands them in.
#pragma once

#include <functional>

#include <QPoint>
#include <QVTKOpenGLNativeWidget.h>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include "core/Mesh.h"
#include "scene/LessonLayer.h"

class vtkCallbackCommand;
class vtkCellPicker;
class vtkHandleWidget;
class vtkObject;
class vtkPointHandleRepresentation3D;
class vtkRenderer;
class vtkTextActor;

namespace conescope {

class ClusterScene;

// Where the observer looks at a mesh from (a unit vector from its centre) for an eye at `eye`: turned
// well past the eye's side (110 degrees from it, a little from above), so the culled clusters, which
// face away from the eye, show beside the drawn ones; `fromBehind`: nearly opposite the eye (160
// degrees), where the culled side faces the observer (and where A and B differ).
glm::dvec3 observerDirection(const glm::dvec3& center, const glm::dvec3& eye, bool fromBehind);

class ObserverView : public QVTKOpenGLNativeWidget {
    Q_OBJECT
public:
    explicit ObserverView(QWidget* parent = nullptr);
    ~ObserverView() override;

    // Takes the previous scene's actors out (when there is one) and puts the current one's in.
    void showScene(const ClusterScene* previous, const ClusterScene& current);
    // Puts the eye's handle at `position`; `show` also switches it on (it is off until a mesh is shown).
    // Its size in pixels becomes a size in the world with the camera it is placed with: place it again
    // after the camera moved far (a new mesh, Reset).
    void placeEyeHandle(const glm::dvec3& position, bool show = false);
    // While following, cameraMoved() reports every change of the camera.
    // While the eye follows the camera the handle would sit on the camera and fill the view: hidden.
    void setFollowing(bool following);

    glm::dvec3 cameraPosition() const;
    // Looks at the mesh centre from observerDirection, the whole mesh and the eye in the picture.
    void lookAtMesh(const glm::dvec3& center, const glm::dvec3& eye, bool fromBehind = false);
    // Looks at `box` from the side of `from`, the box in the middle with some of its surroundings:
    // how a chosen cluster is framed.
    void frameBox(const Aabb& box, const glm::dvec3& from);
    // Puts the camera there (a lesson step's framing); the view angle stays.
    void placeCamera(const CameraPlacement& placement);
    double viewAngle() const;
    // The angle a picture must fit in both ways: the vertical one, or the horizontal one when narrower.
    double fittingViewAngle() const;

    // Qt's widget coordinates (top-left origin, logical pixels) to VTK's display coordinates and back.
    QPoint displayPointOf(const QPoint& viewPosition) const;
    QPoint viewPositionOf(const glm::dvec3& world) const;
    // The cluster of `scene` under a display point, or -1.
    int clusterAt(const ClusterScene& scene, const QPoint& display);

    void render();
    // A line of text centred over the top of the view; empty hides it.
    void setCaption(const QString& text);
    QString caption() const;
    // Where a tooltip over the view comes from: the text for a point (VTK display coordinates), empty
    // for none (the legend's entries explain themselves through it).
    void setToolTipSource(std::function<QString(const QPoint& display)> source) { toolTipSource_ = std::move(source); }

signals:
    void clicked(const QPoint& display);
    void cameraMoved(const glm::dvec3& position);
    void eyeHandleMoved(const glm::dvec3& position);
    // The view's size changed (its legend is fitted to it), sent before the frame at that size is drawn.
    void resized();

protected:
    bool event(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    // The caption's font size: the whole line within the view's width.
    void fitCaption(int viewWidth);
    void onLeftButtonPress();
    void onLeftButtonRelease();
    void onCameraModified(vtkObject* caller, unsigned long event, void* data);
    void onHandleMoved(vtkObject* caller, unsigned long event, void* data);

    vtkSmartPointer<vtkRenderer> renderer_;
    vtkSmartPointer<vtkCellPicker> picker_;
    vtkSmartPointer<vtkCallbackCommand> clickObserver_;
    unsigned long cameraObserver_ = 0;
    int pressPosition_[2] = {0, 0};
    bool following_ = false;
    bool handleShown_ = false;  // placeEyeHandle has shown it (a mesh is there)
    vtkSmartPointer<vtkHandleWidget> eyeHandle_;
    vtkSmartPointer<vtkTextActor> caption_;
    vtkSmartPointer<vtkPointHandleRepresentation3D> eyeHandleRepresentation_;
    std::function<QString(const QPoint&)> toolTipSource_;
};

}  // namespace conescope
