// Pipeline results -> the scene's setters, shared by the window and the headless screenshot so both
// draw the same picture for the same eye.
#pragma once

#include <map>
#include <memory>

#include "core/Comparison.h"
#include "core/Pipeline.h"
#include "scene/ClusterScene.h"

namespace conescope {

// A first look shows the faces coloured by decision, the cluster borders and the eye: cones, boxes,
// normals and spheres hide the mesh, so they wait for their keys. The window and the headless
// screenshot start with these.
std::map<Layer, bool> firstLookLayers();

std::unique_ptr<ClusterScene> makeScene(const PreparedMesh& prepared, const ClusterSet& clusters);

// The decisions of the measured eye (culled, and all-back-facing from the oracle), the eye marker
// looking at the mesh centre, and the cull map's fractions for the measured test.
void showMeasurement(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters,
                     const EyeMeasurement& measurement);

// The per-face colourings that depend on the eye, for the colouring shown: the oracle's facing
// (classifyFaces) or the loss classes (faceLosses). Nothing for the others: classifying every face
// at every eye move is left to the colourings that show it.
// K cones per cluster (K > 1; else nothing) of the clusters from the eye into the sub-group colouring:
// what the headless screenshot draws; the window keeps its split with the orbit (Session).
void showSubGroupsFromEye(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters, uint32_t cones, const Eye& eye);

void showEyeColouring(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters,
                      const EyeMeasurement& measurement, FaceColoring coloring);

// A (`a`, pinned or from --compare) against B (the scene's clusters, measured from the eye with the
// test of b.settings): A's decisions from that eye with the test of a.settings, the per-face diff and
// the cluster-count warning into the scene. Returns the eye's comparison, for the statistics.
Comparison showComparison(ClusterScene& scene, const PreparedMesh& prepared, const ClusterConfiguration& a,
                          const ClusterConfiguration& b, const EyeMeasurement& measurement);

// The picked cluster's test from the measured eye (Layer::Test); cluster -1 clears it.
void showTestDrawing(ClusterScene& scene, const PreparedMesh& prepared, const ClusterSet& clusters, int cluster,
                     const EyeMeasurement& measurement);

}  // namespace conescope
