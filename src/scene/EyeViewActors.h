// The actors of the eye's own view (a second renderer or window): the mesh polydata coloured by the
// cluster palette with culled clusters removed. Not a layer of the observer view: the scene makes one
// actor per renderer and remembers them only to answer picks on them.
#pragma once

#include <vector>

#include <vtkSmartPointer.h>
#include <vtkType.h>
#include <vtkWeakPointer.h>

#include "scene/SceneData.h"

class vtkActor;

namespace conescope {

class EyeViewActors {
public:
    explicit EyeViewActors(const SceneData& data) : data_(data) {}

    // Culled clusters have lookup-table alpha 0 and are discarded in the fragment shader, so the actor
    // stays in the opaque pass; every actor made here follows the shared visible-clusters table.
    vtkSmartPointer<vtkActor> makeActor();
    // Whether actor is one made here and still alive.
    bool owns(vtkActor* actor) const;

private:
    const SceneData& data_;
    std::vector<vtkWeakPointer<vtkActor>> made_;
};

}  // namespace conescope
