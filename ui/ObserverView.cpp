#include "ObserverView.h"

#include <algorithm>
#include <cmath>

#include <QHelpEvent>
#include <QFontMetricsF>
#include <QToolTip>

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkHandleWidget.h>
#include <vtkPointHandleRepresentation3D.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "ObserverStyle.h"
#include "scene/ClusterScene.h"

namespace conescope {

namespace {

// A press and release closer than this (pixels) is a click: pick instead of rotate.
constexpr int clickTolerance = 3;

vtkSmartPointer<vtkPointHandleRepresentation3D> eyeHandleRepresentation() {
    auto representation = vtkSmartPointer<vtkPointHandleRepresentation3D>::New();
    representation->AllOff();
    representation->SetHandleSize(40);
    representation->GetProperty()->SetColor(SceneColours::eye[0], SceneColours::eye[1], SceneColours::eye[2]);
    representation->GetProperty()->SetLineWidth(2.0);
    representation->GetSelectedProperty()->SetColor(SceneColours::highlight[0], SceneColours::highlight[1],
                                                    SceneColours::highlight[2]);
    representation->GetSelectedProperty()->SetLineWidth(3.0);
    // Its world size follows the camera it was last drawn with (a fixed size in pixels): counted in
    // ResetCamera it would keep the scale of the previous mesh.
    representation->UseBoundsOff();
    return representation;
}

}  // namespace

ObserverView::ObserverView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
    setObjectName(QStringLiteral("observerView"));
    renderer_ = vtkSmartPointer<vtkRenderer>::New();
    renderer_->SetBackground(0.12, 0.13, 0.16);
    renderer_->SetBackground2(0.28, 0.30, 0.36);
    renderer_->GradientBackgroundOn();
    renderWindow()->AddRenderer(renderer_);
    vtkNew<ObserverStyle> style;
    interactor()->SetInteractorStyle(style);

    picker_ = vtkSmartPointer<vtkCellPicker>::New();
    picker_->SetTolerance(0.0005);
    // The trackball style grabs the focus on a press, after which only focus holders and passive
    // observers hear the release: watch the clicks passively (they never change the event's course).
    clickObserver_ = vtkSmartPointer<vtkCallbackCommand>::New();
    clickObserver_->SetClientData(this);
    clickObserver_->SetCallback([](vtkObject*, unsigned long event, void* view, void*) {
        auto* self = static_cast<ObserverView*>(view);
        if (event == vtkCommand::LeftButtonPressEvent)
            self->onLeftButtonPress();
        else
            self->onLeftButtonRelease();
    });
    clickObserver_->PassiveObserverOn();
    interactor()->AddObserver(vtkCommand::LeftButtonPressEvent, clickObserver_);
    interactor()->AddObserver(vtkCommand::LeftButtonReleaseEvent, clickObserver_);
    cameraObserver_ = renderer_->GetActiveCamera()->AddObserver(vtkCommand::ModifiedEvent, this, &ObserverView::onCameraModified);

    // A caption (a replay's): centred at the top, on a dark band so it reads over any mesh.
    caption_ = vtkSmartPointer<vtkTextActor>::New();
    vtkTextProperty* text = caption_->GetTextProperty();
    text->SetFontSize(20);
    text->SetFontFamilyToArial();
    text->SetJustificationToCentered();
    text->SetVerticalJustificationToTop();
    text->SetColor(1.0, 1.0, 1.0);
    text->SetBackgroundColor(0.0, 0.0, 0.0);
    text->SetBackgroundOpacity(0.6);
    text->SetFrame(false);
    caption_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    caption_->GetPositionCoordinate()->SetValue(0.5, 0.97);
    caption_->SetVisibility(false);
    caption_->PickableOff();
    renderer_->AddViewProp(caption_);

    eyeHandleRepresentation_ = eyeHandleRepresentation();
    eyeHandle_ = vtkSmartPointer<vtkHandleWidget>::New();
    eyeHandle_->SetInteractor(interactor());
    eyeHandle_->SetRepresentation(eyeHandleRepresentation_);
    eyeHandle_->AddObserver(vtkCommand::InteractionEvent, this, &ObserverView::onHandleMoved);
}

ObserverView::~ObserverView() {
    renderer_->GetActiveCamera()->RemoveObserver(cameraObserver_);
    interactor()->RemoveObserver(clickObserver_);
    eyeHandle_->Off();
}

void ObserverView::showScene(const ClusterScene* previous, const ClusterScene& current) {
    if (previous) previous->removeFrom(renderer_);
    current.addTo(renderer_);
}

void ObserverView::placeEyeHandle(const glm::dvec3& position, bool show) {
    double world[3] = {position.x, position.y, position.z};
    eyeHandleRepresentation_->SetWorldPosition(world);
    // The representation sizes itself for the camera only when it was modified: a new place or a new
    // camera (a new mesh, Reset) must not keep the size it had for the previous one.
    eyeHandleRepresentation_->Modified();
    if (show) handleShown_ = true;
    eyeHandle_->SetEnabled(handleShown_ && !following_);
}

void ObserverView::setFollowing(bool following) {
    following_ = following;
    eyeHandle_->SetEnabled(handleShown_ && !following_);
}

glm::dvec3 ObserverView::cameraPosition() const {
    double position[3];
    renderer_->GetActiveCamera()->GetPosition(position);
    return {position[0], position[1], position[2]};
}

glm::dvec3 observerDirection(const glm::dvec3& center, const glm::dvec3& eye, bool fromBehind) {
    glm::dvec3 direction = eye - center;
    if (!(glm::length(direction) > 0.0)) direction = {0.0, 0.0, 1.0};
    direction = glm::normalize(direction);
    glm::dvec3 side = glm::cross(glm::dvec3(0.0, 1.0, 0.0), direction);
    if (glm::length(side) < 1e-6) side = glm::cross(glm::dvec3(1.0, 0.0, 0.0), direction);
    side = glm::normalize(side);
    const double turn = glm::radians(fromBehind ? 160.0 : 110.0);
    return glm::normalize(std::cos(turn) * direction - std::sin(turn) * side + glm::dvec3(0.0, 0.35, 0.0));
}

void ObserverView::lookAtMesh(const glm::dvec3& center, const glm::dvec3& eye, bool fromBehind) {
    vtkCamera* camera = renderer_->GetActiveCamera();
    const glm::dvec3 from = center + observerDirection(center, eye, fromBehind);
    camera->SetFocalPoint(center.x, center.y, center.z);
    camera->SetPosition(from.x, from.y, from.z);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer_->ResetCamera();
}

void ObserverView::frameBox(const Aabb& box, const glm::dvec3& from) {
    vtkCamera* camera = renderer_->GetActiveCamera();
    const glm::dvec3 center(box.center());
    glm::dvec3 direction = from - center;
    if (!(glm::length(direction) > 0.0)) direction = {0.0, 0.0, 1.0};
    const glm::dvec3 position = center + glm::normalize(direction);
    camera->SetFocalPoint(center.x, center.y, center.z);
    camera->SetPosition(position.x, position.y, position.z);
    // An up vector along the view would make the camera's frame undefined.
    const glm::dvec3 up = std::abs(glm::normalize(direction).y) > 0.95 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(0.0, 1.0, 0.0);
    camera->SetViewUp(up.x, up.y, up.z);
    double bounds[6] = {box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
    renderer_->ResetCamera(bounds);
    camera->Dolly(0.6);
    renderer_->ResetCameraClippingRange();
    render();
}

void ObserverView::placeCamera(const CameraPlacement& placement) {
    vtkCamera* camera = renderer_->GetActiveCamera();
    camera->SetFocalPoint(placement.focalPoint.x, placement.focalPoint.y, placement.focalPoint.z);
    camera->SetPosition(placement.position.x, placement.position.y, placement.position.z);
    camera->SetViewUp(placement.viewUp.x, placement.viewUp.y, placement.viewUp.z);
    camera->OrthogonalizeViewUp();
    renderer_->ResetCameraClippingRange();
    render();
}

double ObserverView::viewAngle() const { return renderer_->GetActiveCamera()->GetViewAngle(); }

double ObserverView::fittingViewAngle() const {
    // VTK's view angle is the vertical one; a view narrower than tall sees less across.
    const double vertical = viewAngle();
    if (width() <= 0 || height() <= 0 || width() >= height()) return vertical;
    const double halfTangent = std::tan(0.5 * vertical * M_PI / 180.0) * double(width()) / double(height());
    return 2.0 * std::atan(halfTangent) * 180.0 / M_PI;
}

QPoint ObserverView::displayPointOf(const QPoint& viewPosition) const {
    // As QVTKInteractorAdapter converts mouse events.
    const double ratio = devicePixelRatioF();
    const int height = renderWindow()->GetSize()[1];
    return {int(std::lround(viewPosition.x() * ratio)), height - int(std::lround(viewPosition.y() * ratio)) - 1};
}

QPoint ObserverView::viewPositionOf(const glm::dvec3& world) const {
    renderer_->SetWorldPoint(world.x, world.y, world.z, 1.0);
    renderer_->WorldToDisplay();
    double display[3];
    renderer_->GetDisplayPoint(display);
    const double ratio = devicePixelRatioF();
    const int height = renderWindow()->GetSize()[1];
    return {int(std::lround(display[0] / ratio)), int(std::lround((height - 1 - display[1]) / ratio))};
}

int ObserverView::clusterAt(const ClusterScene& scene, const QPoint& display) {
    if (!picker_->Pick(display.x(), display.y(), 0.0, renderer_)) return -1;
    return scene.clusterOfCell(picker_->GetActor(), picker_->GetCellId());
}

void ObserverView::render() { renderWindow()->Render(); }

void ObserverView::setCaption(const QString& text) {
    caption_->SetInput(text.toUtf8().constData());
    caption_->SetVisibility(!text.isEmpty());
    fitCaption(width());
}

void ObserverView::fitCaption(int viewWidth) {
    // As large as 20 points, smaller when the view is too narrow for the whole line.
    constexpr int largest = 20, smallest = 10;
    caption_->GetTextProperty()->SetFontSize(largest);
    const char* input = caption_->GetInput();
    if (!input || !*input || viewWidth <= 0) return;
    // Its width at 20 points, from the font the caption is drawn in, in widget pixels.
    QFont font(QStringLiteral("Arial"));
    font.setPixelSize(largest);
    const double textWidth = QFontMetricsF(font).horizontalAdvance(QString::fromUtf8(input)) + 8.0;
    const double room = 0.94 * viewWidth;
    if (textWidth > room) caption_->GetTextProperty()->SetFontSize(std::max(smallest, int(largest * room / textWidth)));
}

QString ObserverView::caption() const { return caption_->GetVisibility() ? QString::fromUtf8(caption_->GetInput()) : QString(); }

bool ObserverView::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip && toolTipSource_) {
        auto* help = static_cast<QHelpEvent*>(event);
        const QString text = toolTipSource_(displayPointOf(help->pos()));
        if (text.isEmpty()) QToolTip::hideText();
        else QToolTip::showText(help->globalPos(), text, this);
        return true;
    }
    return QVTKOpenGLNativeWidget::event(event);
}

void ObserverView::resizeEvent(QResizeEvent* event) {
    // Before the base class: it draws the frame at the new size, which must have the legend fitted to
    // it (nothing draws again after a dock re-arrangement, so a stale legend would stay on screen).
    emit resized();
    fitCaption(event->size().width());
    QVTKOpenGLNativeWidget::resizeEvent(event);
}

void ObserverView::onLeftButtonPress() { interactor()->GetEventPosition(pressPosition_); }

void ObserverView::onLeftButtonRelease() {
    int position[2];
    interactor()->GetEventPosition(position);
    if (std::abs(position[0] - pressPosition_[0]) > clickTolerance || std::abs(position[1] - pressPosition_[1]) > clickTolerance)
        return;
    emit clicked(QPoint(position[0], position[1]));
}

void ObserverView::onCameraModified(vtkObject*, unsigned long, void*) {
    if (following_) emit cameraMoved(cameraPosition());
}

void ObserverView::onHandleMoved(vtkObject*, unsigned long, void*) {
    double position[3];
    eyeHandleRepresentation_->GetWorldPosition(position);
    emit eyeHandleMoved({position[0], position[1], position[2]});
}

}  // namespace conescope
