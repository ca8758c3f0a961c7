#include "scene/SceneRendering.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include "scene/ClusterScene.h"

namespace conescope {

void placeObserverCamera(const ClusterScene& scene, const RenderOptions& options, vtkCamera* camera) {
    const std::array<double, 6> bounds = scene.meshBounds();
    glm::dvec3 low(bounds[0], bounds[2], bounds[4]), high(bounds[1], bounds[3], bounds[5]);
    // The sphere the picture fits: the mesh's, or the mesh's and the eye's together.
    if (options.frameEye && scene.hasEye() && !scene.eye().orthographic) {
        low = glm::min(low, scene.eye().position);
        high = glm::max(high, scene.eye().position);
    }
    const glm::dvec3 center = 0.5 * (low + high);
    const double radius = std::max(0.5 * glm::distance(low, high), 1e-12);

    glm::dvec3 focal = options.focalPoint.value_or(center);
    glm::dvec3 position;
    if (options.cameraPosition) {
        position = *options.cameraPosition;
    } else {
        // From the eye's side but 60 degrees off it, so the border between drawn and culled clusters
        // faces the observer; without an eye, from +z.
        glm::dvec3 from(0.0, 0.0, 1.0);
        if (scene.hasEye()) {
            const Eye& eye = scene.eye();
            glm::dvec3 towardsEye = eye.orthographic ? -eye.direction : eye.position - center;
            if (glm::length(towardsEye) > 0.0) {
                towardsEye = glm::normalize(towardsEye);
                glm::dvec3 side = glm::cross(towardsEye, options.viewUp);
                if (glm::length(side) < 1e-6) side = glm::cross(towardsEye, glm::dvec3(1, 0, 0));
                side = glm::normalize(side);
                from = glm::normalize((options.fromBehind ? -0.5 : 0.5) * towardsEye + std::sqrt(0.75) * side);
            }
        }
        // Far enough that the bounding sphere fills the view angle.
        const double halfAngle = 0.5 * options.viewAngleDegrees * M_PI / 180.0;
        position = focal + from * (radius / std::sin(halfAngle));
    }
    camera->ParallelProjectionOff();
    camera->SetViewAngle(options.viewAngleDegrees);
    camera->SetPosition(position.x, position.y, position.z);
    camera->SetFocalPoint(focal.x, focal.y, focal.z);
    camera->SetViewUp(options.viewUp.x, options.viewUp.y, options.viewUp.z);
    camera->OrthogonalizeViewUp();
}

void frameTestDrawing(const ClusterScene& scene, RenderOptions& options) {
    const CullTestDrawing& drawing = scene.testDrawing();
    if (drawing.cluster < 0) return;
    const glm::dvec3 focus = drawing.sphere.center;
    // Across the view vector, a little from behind the eye: the funnel in profile, the faces in view.
    glm::dvec3 side = glm::cross(drawing.why.view, options.viewUp);
    if (glm::length(side) < 1e-6) side = glm::cross(drawing.why.view, glm::dvec3(1, 0, 0));
    const glm::dvec3 from = glm::normalize(glm::normalize(side) - 0.6 * drawing.why.view);
    const double halfAngle = 0.5 * options.viewAngleDegrees * M_PI / 180.0;
    const double radius = 2.5 * std::max(drawing.sphere.radius, 1e-9);
    options.focalPoint = focus;
    options.cameraPosition = focus + from * (radius / std::sin(halfAngle));
}

void requireDisplay() {
    // Without a display an off-screen window aborts the process inside VTK's X code: fail clearly first.
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) throw std::runtime_error("rendering needs an X display; run under xvfb-run");
}

vtkSmartPointer<vtkImageData> renderOffScreen(vtkRenderer* renderer, int width, int height, int dpi) {
    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetDPI(dpi);
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(width, height);
    window->AddRenderer(renderer);
    window->Render();

    auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(grab->GetOutput());
    window->RemoveRenderer(renderer);
    window->Finalize();
    return image;
}

vtkSmartPointer<vtkImageData> renderToImage(const ClusterScene& scene, const RenderOptions& options) {
    requireDisplay();
    if (options.width <= 0 || options.height <= 0)
        throw std::runtime_error("rendering needs a positive image size, got " + std::to_string(options.width) + "x" +
                                 std::to_string(options.height));
    if (options.fromEye && !scene.hasEye()) throw std::runtime_error("rendering from the cull eye needs an eye (setEye)");

    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetBackground(options.background[0], options.background[1], options.background[2]);
    vtkSmartPointer<vtkActor> eyeView;
    if (options.fromEye) {
        eyeView = scene.makeVisibleClustersActor();
        renderer->AddActor(eyeView);
        scene.applyEyeToCamera(renderer->GetActiveCamera());
    } else {
        scene.addTo(renderer);
        placeObserverCamera(scene, options, renderer->GetActiveCamera());
        renderer->ResetCameraClippingRange();
    }

    vtkSmartPointer<vtkImageData> image = renderOffScreen(renderer, options.width, options.height, options.dpi);
    // Leave the scene's actors free for another renderer.
    if (!options.fromEye) scene.removeFrom(renderer);
    return image;
}

void renderToPng(const ClusterScene& scene, const RenderOptions& options, const std::string& path) {
    writePng(renderToImage(scene, options), path);
}

void writePng(vtkImageData* image, const std::string& path) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New();
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    writer->Write();
    if (writer->GetErrorCode() != 0) throw std::runtime_error("could not write the image " + path);
}

}  // namespace conescope
