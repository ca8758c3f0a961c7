// The cross-section dock: seed 000's figure for the picked cluster and the current eye, in the plane
// of the cone axis V1 and the view vector v, true to the shown test (core crossSectionOf of the
// session's lesson, drawn by scene/CrossSectionScene), its title and caption as text around it. Also writes the
// figure as a PNG with a JSON of what it drew beside it.
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
    // The texts the view drew at its last render, with their boxes in device pixels.
    const std::vector<CrossSectionLabel>& drawnLabels() const { return scene_.labels(); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void fit();

    QVTKOpenGLNativeWidget* view_ = nullptr;
    QLabel* title_ = nullptr;
    QLabel* caption_ = nullptr;
    vtkSmartPointer<vtkRenderer> renderer_;
    CrossSectionScene scene_;
};

// The cross-section of the session's lesson (its picked cluster, eye and test). Throws
// std::runtime_error without a lesson.
CrossSection crossSectionOf(const Session& session);

// The figure of the session's lesson as a PNG of width x height pixels, caption included (a fresh
// scene, off screen), and beside it (X.png -> X.json) what it drew (io/CrossSectionIO.h). Throws
// std::runtime_error without a lesson or when a file cannot be written.
void writeCrossSectionPng(const Session& session, const QString& path, int width = 960, int height = 720);

}  // namespace conescope
