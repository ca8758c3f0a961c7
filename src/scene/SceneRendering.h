// Headless rendering of a ClusterScene into an image or a PNG file: used by `conescope --screenshot`
// and by the image-baseline tests. Needs an X display (run under xvfb-run without one).
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include "scene/ClusterPalette.h"

class vtkCamera;
class vtkImageData;
class vtkRenderer;

namespace conescope {

class ClusterScene;

struct RenderOptions {
    int width = 1280;
    int height = 800;
    // Observer camera. Unset focal point: the centre of the mesh bounds. Unset position: far enough
    // that the mesh's bounding sphere fills the view angle, from 60 degrees to the side of the cull eye
    // if the scene has one (setEye: the border between drawn and culled clusters faces the observer),
    // else from +z, looking along Eye{}.direction.
    std::optional<glm::dvec3> cameraPosition;
    std::optional<glm::dvec3> focalPoint;
    glm::dvec3 viewUp{0.0, 1.0, 0.0};
    // With an unset position, fit the cull eye (a perspective one) into the picture with the mesh.
    bool frameEye = false;
    // With an unset position, look from the side facing away from the cull eye (60 degrees off the
    // opposite of its direction): where the back faces are, and so what culling is about.
    bool fromBehind = false;
    double viewAngleDegrees = 30.0;
    Rgb background{0.12, 0.13, 0.16};
    // Render what the cull eye sees instead of the observer view: camera from applyEyeToCamera, only
    // the visible-clusters actor (culled clusters removed). Needs setEye.
    bool fromEye = false;
    // The window's dots per inch: 72 (VTK's default) times the screen's device pixel ratio, as the
    // app's view sets it on a HiDPI screen (text is drawn that much larger).
    int dpi = 72;
};

// Points the options' camera at the scene's test drawing (setTestDrawing): the picked cluster seen from
// the side of its view vector, close enough that the cluster, its axis and its cull region fill the
// picture. Leaves the options alone when nothing is drawn.
void frameTestDrawing(const ClusterScene& scene, RenderOptions& options);

// The default observer camera for these options (what an unset cameraPosition / focalPoint means).
void placeObserverCamera(const ClusterScene& scene, const RenderOptions& options, vtkCamera* camera);

// Throws std::runtime_error ("rendering needs an X display; run under xvfb-run") without a DISPLAY.
void requireDisplay();
// Renders the renderer alone in an off-screen window of that size into an RGB image, multisampling off.
vtkSmartPointer<vtkImageData> renderOffScreen(vtkRenderer* renderer, int width, int height, int dpi = 72);

// Renders into an RGB image of options.width x options.height (multisampling off, so the pixels are
// the same on every run of the same driver). Throws std::runtime_error when there is no X display
// ("rendering needs an X display; run under xvfb-run") or the window cannot be made.
vtkSmartPointer<vtkImageData> renderToImage(const ClusterScene& scene, const RenderOptions& options);

// An image as PNG. Throws std::runtime_error naming the path if it cannot be written.
void writePng(vtkImageData* image, const std::string& path);

// renderToImage, then PNG. Throws std::runtime_error naming the path if it cannot be written.
void renderToPng(const ClusterScene& scene, const RenderOptions& options, const std::string& path);

}  // namespace conescope
