// Layer::Legend: what the colours mean, for the visible layers. One row per entry, a swatch and its
// label beside it with a gap; an entry with a scale (a continuous colouring) is its label over a
// colour bar with the scale's ends written at its ends. Laid out in pixels from the view's lower left
// corner, so it has the same size in any window; the text is white on a dark, half see-through box.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "scene/SceneLayer.h"

class vtkActor2D;
class vtkPolyData;
class vtkProp;
class vtkPropAssembly;
class vtkTextActor;

namespace conescope {

class SceneLegend {
public:
    SceneLegend();
    ~SceneLegend();

    // Replaces the entries; an empty legend is hidden.
    void show(const std::vector<LegendEntry>& entries);
    void setVisible(bool visible);
    bool visible() const { return visible_; }
    // Drawn: visible and with entries.
    bool drawn() const;
    const std::vector<LegendEntry>& entries() const { return entries_; }
    // Everything it draws, as one prop for a renderer.
    vtkProp* prop() const;

    // Where it draws, in display pixels {x0, y0, x1, y1}: the box, and per drawn text its rectangle
    // and per swatch or colour bar its rectangle (what the tests check for overlaps).
    using Rectangle = std::array<double, 4>;
    struct Placed {
        std::string text;
        Rectangle box;
    };
    Rectangle box() const { return box_; }
    const std::vector<Placed>& texts() const { return texts_; }
    const std::vector<Rectangle>& swatches() const { return swatches_; }

private:
    void addText(const std::string& text, double x, double centreY, int fontSize);
    void addColours(const std::vector<Rgb>& colours, const Rectangle& where);

    std::vector<LegendEntry> entries_;
    bool visible_ = false;
    vtkSmartPointer<vtkPropAssembly> assembly_;
    vtkSmartPointer<vtkActor2D> background_, colours_;
    vtkSmartPointer<vtkPolyData> backgroundData_, colourData_;
    std::vector<vtkSmartPointer<vtkTextActor>> textActors_;
    Rectangle box_{0.0, 0.0, 0.0, 0.0};
    std::vector<Placed> texts_;
    std::vector<Rectangle> swatches_;
};

}  // namespace conescope
