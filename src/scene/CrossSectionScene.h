// The textbook cross-section's picture (core/CrossSection.h), in seed 000's colours on white: face
// normals red, the cone's boundary lines green, the axis V1 and the view vector v dark red, the
// line perpendicular to the axis dark blue; the angles alpha and B marked, the wedge of view vectors
// the test culls from shaded, the octagon test's section gold. A title above, the caption below.
#pragma once

#include <memory>
#include <optional>

#include <vtkSmartPointer.h>

#include "core/CrossSection.h"

class vtkCamera;
class vtkImageData;
class vtkRenderer;

namespace conescope {

class CrossSectionScene {
public:
    CrossSectionScene();
    ~CrossSectionScene();
    CrossSectionScene(const CrossSectionScene&) = delete;
    CrossSectionScene& operator=(const CrossSectionScene&) = delete;

    // Shows `section`; nullopt shows only a note to pick a cluster.
    void show(const std::optional<CrossSection>& section);
    bool hasSection() const;
    // The text sized for a picture of this many pixels (smaller in a small view) and the caption broken
    // into lines that fit its width.
    void fitTo(int widthPixels, int heightPixels);
    // Hidden where the caption is shown as words beside the picture.
    void setCaptionVisible(bool visible);

    void addTo(vtkRenderer* renderer) const;
    void removeFrom(vtkRenderer* renderer) const;
    // A parallel camera on the figure, room left below it for the caption when that is shown; `aspect`
    // is width / height.
    void placeCamera(vtkCamera* camera, double aspect) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Renders the cross-section alone into an RGB image (multisampling off), fitted to its size. Needs
// an X display.
vtkSmartPointer<vtkImageData> renderCrossSectionToImage(CrossSectionScene& scene, int width, int height);

}  // namespace conescope
