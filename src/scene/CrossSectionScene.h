// The cross-section's picture (core/CrossSection.h drawn by CrossSectionFigure.h) on white: a title
// above, the figure with every label placed where nothing else is drawn (LabelPlacement.h), the
// caption below. Laid out in pixels for one picture size at a time (fitTo); its texts and their
// boxes are kept for the export's JSON.
#pragma once

#include <memory>
#include <optional>
#include <vector>

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

    // Shows `section`; nullopt shows only a note to pick a cluster. Drawn at the next fitTo.
    void show(const std::optional<CrossSection>& section);
    bool hasSection() const;
    // Lays the picture out for width x height pixels at `dpi` (72 times the screen's pixel ratio:
    // text and lines that much larger): the figure, the caption wrapped to the width, the labels placed.
    void fitTo(int widthPixels, int heightPixels, int dpi = 72);
    // Without the title and the caption, where they are shown as words beside the picture.
    void setCaptionVisible(bool visible);
    // Without any text: the shapes alone (to check that no label lies on one).
    void setTextVisible(bool visible);

    void addTo(vtkRenderer* renderer);
    void removeFrom(vtkRenderer* renderer);
    // A parallel camera that maps the picture's pixels one to one (the figure is laid out in pixels).
    void placeCamera(vtkCamera* camera) const;

    // Every text the last fitTo drew (title, labels, caption) and its box; labels that found no free
    // spot are left out and listed by leftOut.
    const std::vector<CrossSectionLabel>& labels() const;
    const std::vector<std::string>& leftOut() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Lays the scene out for, and renders it alone into, an RGB image of that size (multisampling off).
// Needs an X display.
vtkSmartPointer<vtkImageData> renderCrossSectionToImage(CrossSectionScene& scene, int width, int height, int dpi = 72);

}  // namespace conescope
