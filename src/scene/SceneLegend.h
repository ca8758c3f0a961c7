// Layer::Legend: what the colours mean, for the visible layers. Placed and sized in pixels, so its
// text has the same size in any window; each symbol is a small polydata whose RGB cell scalars are the
// colours (several bars for "a colour per cluster"), the text is white.
#pragma once

#include <vector>

#include <vtkSmartPointer.h>

#include "scene/SceneLayer.h"

class vtkLegendBoxActor;

namespace conescope {

class SceneLegend {
public:
    SceneLegend();

    // Replaces the entries; an empty legend is hidden.
    void show(const std::vector<LegendEntry>& entries);
    void setVisible(bool visible);
    bool visible() const { return visible_; }
    vtkLegendBoxActor* actor() const { return actor_; }

private:
    vtkSmartPointer<vtkLegendBoxActor> actor_;
    bool visible_ = false;
};

}  // namespace conescope
