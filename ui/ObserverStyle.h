// The observer's trackball camera without VTK's one-letter key bindings ('e'/'q' would end the
// event loop, 'w'/'s' switch every actor to wireframe/surface, '3' stereo): the window's actions own
// the keyboard, so a key does what the help dialog says and nothing else.
#pragma once

#include <vtkInteractorStyleTrackballCamera.h>

namespace conescope {

class ObserverStyle : public vtkInteractorStyleTrackballCamera {
public:
    static ObserverStyle* New();
    vtkTypeMacro(ObserverStyle, vtkInteractorStyleTrackballCamera);

    void OnChar() override {}
    void OnKeyPress() override {}
};

}  // namespace conescope
