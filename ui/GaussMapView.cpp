#include "GaussMapView.h"

#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "Session.h"

namespace conescope {

GaussMapView::GaussMapView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
    setObjectName(QStringLiteral("gaussMapView"));
    renderer_ = vtkSmartPointer<vtkRenderer>::New();
    renderer_->SetBackground(0.12, 0.13, 0.16);
    renderWindow()->AddRenderer(renderer_);
    interactor()->SetInteractorStyle(vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New());
    scene_.addTo(renderer_);
    scene_.placeCamera(renderer_->GetActiveCamera());
}

void GaussMapView::showPick(const Session& session, bool newPick) {
    const ClusterScene* clusterScene = session.scene();
    const int cluster = session.pickedCluster();
    if (!clusterScene || cluster < 0 || !session.preparedMesh() || !session.clusters() ||
        clusterScene->testDrawing().cluster != cluster) {
        scene_.show(std::nullopt, displayedCone(session.settings()));
    } else {
        // The eye's explanation is the test layer's: the same view vector the observer view draws.
        scene_.show(gaussMapOf(*session.preparedMesh(), *session.clusters(), uint32_t(cluster), clusterScene->testDrawing().why),
                    session.clusters()->bounds.coneMethod, cluster);
        // With K cones per cluster, each sub-group's cone and its verdict from the eye.
        std::vector<SubGroupCap> caps;
        if (const std::optional<SubGroupsFromEye> fromEye = session.subGroupsFromEye())
            for (const SubGroupVerdict& verdict : subGroupVerdicts(*fromEye->multi, uint32_t(cluster), fromEye->culled, fromEye->facing))
                caps.push_back({fromEye->multi->cones[verdict.group], verdict.triangles, verdict.culled});
        scene_.showSubGroups(caps);
    }
    if (newPick) scene_.placeCamera(renderer_->GetActiveCamera());
    render();
}

void GaussMapView::resizeEvent(QResizeEvent* event) {
    // Fitted before the base class draws the frame at the new size (as ObserverView::resizeEvent).
    scene_.fitLegend(height(), devicePixelRatioF());
    QVTKOpenGLNativeWidget::resizeEvent(event);
}

void GaussMapView::render() {
    if (isVisible()) renderWindow()->Render();
}

}  // namespace conescope
