// The dock that shows the mesh as the cull eye sees it: the scene's clusters with the culled ones
// removed, through a camera set from the eye. No camera interaction of its own.
#pragma once

#include <QVTKOpenGLNativeWidget.h>

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace conescope {

class ClusterScene;

class EyeView : public QVTKOpenGLNativeWidget {
    Q_OBJECT
public:
    explicit EyeView(QWidget* parent = nullptr);

    // Replaces the clusters shown by those of `scene` (its visible-clusters actor).
    void showScene(const ClusterScene& scene);
    // Looks from the scene's eye (after its decisions were set).
    void showEye(const ClusterScene& scene);
    // Renders when the view is on screen.
    void render();

private:
    vtkSmartPointer<vtkRenderer> renderer_;
    vtkSmartPointer<vtkActor> clustersActor_;
};

}  // namespace conescope
