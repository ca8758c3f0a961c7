// How long the last eye step took on the GUI thread, part by part: the readout of View > Show frame
// times and the figures of tests/ui/EyeStepBench.cpp (docs/benchmarks.md).
#pragma once

#include <QString>

namespace conescope {

struct EyeStepTimes {
    double cullAndScene = 0.0;  // the core's cull of every cluster, the scene's colours and test layer, the lesson
    double panels = 0.0;        // statistics, picked cluster and status line
    double gaussMap = 0.0;      // the Gauss map's new view vector, drawn
    double observerView = 0.0;  // the 3D view drawn
    double eyeView = 0.0;       // the eye's own view drawn (when its dock shows)
    double total() const { return cullAndScene + panels + gaussMap + observerView + eyeView; }
};

// One line: the total and each part in milliseconds.
QString describe(const EyeStepTimes& times);

}  // namespace conescope
