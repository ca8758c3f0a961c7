#include "CrossSectionView.h"

#include <stdexcept>

#include <QLabel>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "Session.h"
#include "core/CrossSection.h"
#include "scene/SceneRendering.h"

namespace conescope {

CrossSectionView::CrossSectionView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("crossSectionView"));
    view_ = new QVTKOpenGLNativeWidget(this);
    view_->setMinimumSize(120, 100);
    renderer_ = vtkSmartPointer<vtkRenderer>::New();
    renderer_->SetBackground(1.0, 1.0, 1.0);
    view_->renderWindow()->AddRenderer(renderer_);
    // A figure to read, not to turn: no camera interaction.
    view_->interactor()->SetInteractorStyle(nullptr);
    scene_.setCaptionVisible(false);
    scene_.addTo(renderer_);
    caption_ = new QLabel(this);
    caption_->setWordWrap(true);
    caption_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The figure takes the room; the words under it in a smaller hand.
    QFont small = caption_->font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    caption_->setFont(small);
    const QString help = tr("Seed 000's figure for the picked cluster: the plane that holds the cone axis V1 and the view "
                            "vector v. Red: the face normals; green: the cone's boundary lines at the half-angle alpha from "
                            "V1; dark red: V1 and v; blue: the line perpendicular to V1, at the angle B = 90 - alpha from the "
                            "boundary lines. The cluster is culled when v lies in the shaded wedge.");
    view_->setToolTip(help);
    view_->setWhatsThis(help);
    caption_->setWhatsThis(help);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(view_, 1);
    layout->addWidget(caption_);
}

void CrossSectionView::showLesson(const Session& session) {
    const Lesson* lesson = session.lesson();
    if (!lesson) {
        scene_.show(std::nullopt);
        caption_->setText(tr("Pick a cluster to see its normals, its cone and the view vector in one plane."));
    } else {
        const CrossSection section = crossSectionOf(*lesson);
        scene_.show(section);
        caption_->setText(QString::fromStdString(section.caption));
    }
    render();
}

void CrossSectionView::render() {
    if (!isVisible()) return;
    const int width = view_->width(), height = view_->height();
    scene_.fitTo(width, height);
    scene_.placeCamera(renderer_->GetActiveCamera(), height > 0 ? double(width) / double(height) : 1.0);
    view_->renderWindow()->Render();
}

QString CrossSectionView::caption() const { return caption_->text(); }

void writeCrossSectionPng(const Session& session, const QString& path, int size) {
    if (!session.lesson()) throw std::runtime_error("no cluster is picked: the cross-section is the picked cluster's");
    CrossSectionScene scene;
    scene.show(crossSectionOf(*session.lesson()));
    writePng(renderCrossSectionToImage(scene, size, size), path.toStdString());
}

}  // namespace conescope
