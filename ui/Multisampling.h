// How many samples per pixel the views ask for. A GPU smooths edges with 8 at no visible cost; a
// software renderer (Mesa's llvmpipe under Xvfb or a remote desktop) pays for every sample on every
// pixel, more than doubling each frame (docs/benchmarks.md, eye step), so it gets none.
#pragma once

namespace conescope {

// CONESCOPE_SAMPLES (a whole number) when set; else 0 on a software renderer, VTK's 8 on others.
// Needs a QGuiApplication; asks a throwaway GL context for its renderer's name.
int viewMultisamples();

// viewMultisamples() for every VTK window made afterwards.
void applyViewMultisamples();

}  // namespace conescope
