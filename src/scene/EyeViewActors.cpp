#include "scene/EyeViewActors.h"

#include <algorithm>

#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkShaderProperty.h>

#include "scene/SceneLayer.h"

namespace conescope {

vtkSmartPointer<vtkActor> EyeViewActors::makeActor() {
    auto actor = actorFor(cellArrayMapper(data_.meshData, clusterIdArrayName, data_.tables.visible));
    actor->GetProperty()->SetInterpolationToFlat();
    // The table has alpha 0 only to mark culled clusters: keep the actor in the opaque pass and drop
    // those fragments, instead of sorting a million translucent triangles.
    actor->ForceOpaqueOn();
    actor->GetShaderProperty()->AddFragmentShaderReplacement(
        "//VTK::Color::Impl", true, "//VTK::Color::Impl\n  if (opacity <= 0.0) { discard; }\n", false);
    made_.erase(std::remove_if(made_.begin(), made_.end(), [](const vtkWeakPointer<vtkActor>& a) { return !a; }), made_.end());
    made_.push_back(actor.Get());
    return actor;
}

bool EyeViewActors::owns(vtkActor* actor) const {
    return std::any_of(made_.begin(), made_.end(), [&](const vtkWeakPointer<vtkActor>& made) { return made.GetPointer() == actor; });
}

}  // namespace conescope
