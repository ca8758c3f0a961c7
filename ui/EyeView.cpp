#include "EyeView.h"

#include <vtkActor.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "scene/ClusterScene.h"

namespace conescope {

EyeView::EyeView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
    setObjectName(QStringLiteral("eyeView"));
    renderer_ = vtkSmartPointer<vtkRenderer>::New();
    renderer_->SetBackground(0.10, 0.10, 0.12);
    renderWindow()->AddRenderer(renderer_);
    // The eye's view is what the eye sees: no camera interaction of its own.
    interactor()->SetInteractorStyle(nullptr);
}

void EyeView::showScene(const ClusterScene& scene) {
    if (clustersActor_) renderer_->RemoveActor(clustersActor_);
    clustersActor_ = scene.makeVisibleClustersActor();
    renderer_->AddActor(clustersActor_);
}

void EyeView::showEye(const ClusterScene& scene) {
    scene.applyEyeToCamera(renderer_->GetActiveCamera());
    renderer_->ResetCameraClippingRange();
}

void EyeView::render() {
    if (isVisible()) renderWindow()->Render();
}

}  // namespace conescope
