// The cross-section dock: seed 000's figure for the picked cluster and the current eye, in the plane
// of the cone axis V1 and the view vector v (core crossSectionOf of the session's lesson, drawn by
// scene/CrossSectionScene), its caption as text below it. Also writes the figure as a PNG.
#pragma once

#include <QWidget>

#include <vtkSmartPointer.h>

#include "scene/CrossSectionScene.h"

class QLabel;
class QVTKOpenGLNativeWidget;
class vtkRenderer;

namespace conescope {

class Session;

class CrossSectionView : public QWidget {
    Q_OBJECT
public:
    explicit CrossSectionView(QWidget* parent = nullptr);

    void showLesson(const Session& session);
    // Renders when on screen.
    void render();
    QString caption() const;

private:
    QVTKOpenGLNativeWidget* view_ = nullptr;
    QLabel* caption_ = nullptr;
    vtkSmartPointer<vtkRenderer> renderer_;
    CrossSectionScene scene_;
};

// The figure of the session's lesson as a PNG of `size` pixels square, caption included (a fresh
// scene, off screen). Throws std::runtime_error without a lesson or when the file cannot be written.
void writeCrossSectionPng(const Session& session, const QString& path, int size = 640);

}  // namespace conescope
