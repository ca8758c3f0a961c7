#include "CrossSectionView.h"

#include <cmath>
#include <stdexcept>

#include <QEvent>
#include <QFileInfo>
#include <QLabel>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "Session.h"
#include "core/CrossSection.h"
#include "io/CrossSectionIO.h"
#include "io/JsonWriter.h"
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
    view_->installEventFilter(this);
    scene_.setCaptionVisible(false);
    scene_.addTo(renderer_);
    // The title and the caption as words around the picture, which then holds only the figure.
    title_ = new QLabel(this);
    title_->setWordWrap(true);
    QFont bold = title_->font();
    bold.setBold(true);
    title_->setFont(bold);
    caption_ = new QLabel(this);
    caption_->setWordWrap(true);
    caption_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The figure takes the room; the words under it in a smaller hand.
    QFont small = caption_->font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    caption_->setFont(small);
    const QString help = tr("Seed 000's figure for the picked cluster, in the plane (the page) that holds the cone axis V1 and the "
                            "view vector v. Red: each face normal at its angle to V1, with bars outside the circle counting them; "
                            "green: the cone, its half-angle alpha; blue band: the view vectors from which the shown test culls, "
                            "with B = 90 - alpha measured from V1 and what the test's bound takes off it; dark red: V1 and v "
                            "(for the box and vertex tests every point's view vector, the lowest as v). The small figure beside "
                            "it shows the eye and the point v runs to. The cluster is culled when v lies in the band.");
    view_->setToolTip(help);
    view_->setWhatsThis(help);
    caption_->setWhatsThis(help);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(title_);
    layout->addWidget(view_, 1);
    layout->addWidget(caption_);
}

CrossSection crossSectionOf(const Session& session) {
    const Lesson* lesson = session.lesson();
    if (!lesson || !session.preparedMesh() || !session.clusters())
        throw std::runtime_error("no cluster is picked: the cross-section is the picked cluster's");
    return crossSectionOf(*lesson, cullingInput(*session.preparedMesh(), *session.clusters()));
}

void CrossSectionView::showLesson(const Session& session) {
    if (!session.lesson()) {
        scene_.show(std::nullopt);
        title_->clear();
        caption_->setText(tr("Pick a cluster to see its normals, its cone and the view vector in one plane."));
    } else {
        const CrossSection section = crossSectionOf(session);
        scene_.show(section);
        title_->setText(QString::fromStdString(section.title));
        caption_->setText(QString::fromStdString(section.caption));
    }
    render();
}

void CrossSectionView::fit() {
    // The render window's pixels and dots per inch as the widget sets them on a HiDPI screen.
    const double ratio = view_->devicePixelRatioF();
    const int width = int(std::lround(view_->width() * ratio)), height = int(std::lround(view_->height() * ratio));
    if (width <= 0 || height <= 0) return;
    const int dpi = view_->enableHiDPI() ? int(std::lround(view_->unscaledDPI() * ratio)) : view_->unscaledDPI();
    scene_.fitTo(width, height, dpi);
    scene_.placeCamera(renderer_->GetActiveCamera());
}

void CrossSectionView::render() {
    if (!isVisible()) return;
    fit();
    view_->renderWindow()->Render();
}

bool CrossSectionView::eventFilter(QObject* watched, QEvent* event) {
    // A new size lays the figure out anew before the widget paints it.
    if (watched == view_ && event->type() == QEvent::Resize) fit();
    return QWidget::eventFilter(watched, event);
}

QString CrossSectionView::caption() const { return caption_->text(); }

void writeCrossSectionPng(const Session& session, const QString& path, int width, int height) {
    const CrossSection section = crossSectionOf(session);
    CrossSectionScene scene;
    scene.show(section);
    writePng(renderCrossSectionToImage(scene, width, height), path.toStdString());
    const QFileInfo png(path);
    const QString json = png.suffix().compare(QStringLiteral("png"), Qt::CaseInsensitive) == 0
                             ? png.path() + QLatin1Char('/') + png.completeBaseName() + QStringLiteral(".json")
                             : path + QStringLiteral(".json");
    writeJsonFile(crossSectionToJson(section, scene.labels(), scene.leftOut(), width, height), json.toStdString());
}

}  // namespace conescope
