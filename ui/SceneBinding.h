// Pipeline results -> the scene's setters, shared by the window and the headless screenshot so both
// draw the same picture for the same eye.
#pragma once

#include <map>
#include <memory>

#include "core/Pipeline.h"
#include "scene/ClusterScene.h"

namespace conescope {

// A first look shows clusters, cones and boxes; normals and spheres crowd the view, so they wait
// for their keys. The window and the headless screenshot start with these.
std::map<Layer, bool> firstLookLayers();

std::unique_ptr<ClusterScene> makeScene(const PreparedMesh& prepared, const ClusterSet& clusters);

// The decisions of the measured eye (culled, and all-back-facing from the oracle) and the eye
// marker looking at the mesh centre.
void showMeasurement(ClusterScene& scene, const PreparedMesh& prepared, const EyeMeasurement& measurement);

// The oracle's per-face facing from this eye (classifyFaces), for the face-facing colouring.
void showFaceFacing(ClusterScene& scene, const PreparedMesh& prepared, const Eye& eye);

}  // namespace conescope
