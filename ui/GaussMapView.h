// The Gauss-map inspector dock: the picked cluster's normals on the unit sphere with the cap of every
// cone method and the test's view vector (scene/GaussMapScene.h), for the current eye. The camera
// turns with the mouse around the sphere; a new pick places it again.
#pragma once

#include <QVTKOpenGLNativeWidget.h>

#include <vtkSmartPointer.h>

#include "scene/GaussMapScene.h"

class vtkRenderer;

namespace conescope {

class Session;

class GaussMapView : public QVTKOpenGLNativeWidget {
    Q_OBJECT
public:
    explicit GaussMapView(QWidget* parent = nullptr);

    // The session's picked cluster for its current eye and test; nothing picked clears the picture.
    // `newPick` places the camera again.
    void showPick(const Session& session, bool newPick);
    const GaussMapScene& scene() const { return scene_; }
    // Renders when the view is on screen.
    void render();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    vtkSmartPointer<vtkRenderer> renderer_;
    GaussMapScene scene_;
};

}  // namespace conescope
