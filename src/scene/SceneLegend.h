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

// The legend's scale for a view `height` pixels high: full size from 600 pixels up, down to 3/4.
double legendScaleFor(int height);
// The same for a legend of `rows` rows, smaller still (down to 0.7) where it would take more than a
// quarter of the view's height: a long legend must not cover the picture it explains.
double legendScaleFor(int height, size_t rows);

class SceneLegend {
public:
    SceneLegend();
    ~SceneLegend();

    // Replaces the entries; an empty legend is hidden.
    void show(const std::vector<LegendEntry>& entries);
    // Every size (text, rows, swatches) times `scale`: a small view gets a smaller legend. 1 by default.
    // `pixelRatio` is the view's device pixels per widget pixel: VTK draws the text at 72 dpi times it
    // (HiDPI), so the box, rows and swatches are laid out that much larger too.
    void setScale(double scale, double pixelRatio = 1.0);
    // setScale(legendScaleFor(viewHeight, rows)) now and whenever the entries change.
    void fitTo(int viewHeight, double pixelRatio = 1.0);
    double scale() const { return scale_; }
    double pixelRatio() const { return pixelRatio_; }
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
    void layOut(const std::vector<LegendEntry>& entries);
    bool laidOut_ = false;
    void addText(const std::string& text, double x, double centreY, double fontSize);
    void addColours(const std::vector<Rgb>& colours, const Rectangle& where);

    std::vector<LegendEntry> entries_;
    bool visible_ = false;
    double scale_ = 1.0;
    double pixelRatio_ = 1.0;
    int viewHeight_ = 0;  // fitTo's, 0 before
    vtkSmartPointer<vtkPropAssembly> assembly_;
    vtkSmartPointer<vtkActor2D> background_, colours_;
    vtkSmartPointer<vtkPolyData> backgroundData_, colourData_;
    std::vector<vtkSmartPointer<vtkTextActor>> textActors_;
    Rectangle box_{0.0, 0.0, 0.0, 0.0};
    std::vector<Placed> texts_;
    std::vector<Rectangle> swatches_;
};

}  // namespace conescope
