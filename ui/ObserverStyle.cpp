#include "ObserverStyle.h"

#include <vtkObjectFactory.h>

namespace conescope {

vtkStandardNewMacro(ObserverStyle);

}  // namespace conescope
