// The names and colours every part of the scene shares: the layers, the face colourings, the fixed
// legend colours and the names of the per-cell arrays.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/ClusterPalette.h"

namespace conescope {

// Name of the per-face cluster index on the mesh polydata and of the per-cell cluster index on every
// per-cluster glyph polydata (cones, boxes, spheres).
inline const char* const clusterIdArrayName = "cluster_id";
// Per-face Facing value (0 front, 1 back, 2 degenerate, 3 not classified yet), written by setFaceFacing.
inline const char* const facingArrayName = "facing";
// Per-face FaceLoss value (core/Pipeline.h: 0 visible, 1 culled, 2 test loss, 3 partition loss; 4 not
// measured yet), written by setFaceLoss.
inline const char* const lossArrayName = "loss";
// Per-face A/B comparison for the eye (core FaceDiff: 0 culled by neither, 1 by A only, 2 by B only,
// 3 by both; 4 not compared), written by setFaceComparison.
inline const char* const comparisonArrayName = "comparison";
// Per-face colour (RGB) of the sub-group colouring: shades of the cluster's colour, the culled grey,
// written by setSubGroups.
inline const char* const subGroupArrayName = "sub_group";

// Switchable parts of the scene. Default visibility: Faces, Borders, Cones, Eye, Highlight, Test, Legend, Lesson on;
// Normals, Boxes, Spheres off.
enum class Layer {
    Faces,      // the mesh, coloured as FaceColoring says
    Borders,    // edges between faces of different clusters, and open edges (one line polydata)
    Cones,      // one translucent cone per cullable cluster: apex at the sphere centre, opening along the
                // axis with exactly the cone's half-angle, slant length = sphere radius
    Normals,    // face normals as arrows at face centroids, 0.6 x the mean edge length (a regular subset
                // on large meshes); the arrows are only built once the layer is shown
    Boxes,      // cluster AABBs as wire boxes, 12 lines per cluster
    Spheres,    // bounding spheres as three orthogonal circles per cluster
    Eye,        // the cull eye marker (after setEye)
    Highlight,  // the picked cluster (after setHighlightedCluster): outline, half see-through cone, box and sphere,
                // shown whatever the Cones / Boxes / Spheres layers say
    Test,       // the picked cluster's cull test in 3D (setTestDrawing): axis, view vector, cull region, points
    Legend,     // what the colours mean, for the visible layers
    Lesson,     // a lesson step's picture of the picked cluster (setLessonDrawing): normals, Gauss sphere, cone, bound
};
const std::vector<Layer>& allLayers();
std::string toString(Layer);  // "faces", "borders", "cones", "normals", "boxes", "spheres", "eye", ...

// How the faces (and the per-cluster glyphs) are coloured.
enum class FaceColoring {
    Cluster,       // the cluster palette: neighbouring clusters differ
    CullDecision,  // per cluster: culled / missed cull / drawn (setClusterDecisions)
    FaceFacing,    // per face, from the oracle: front / back / degenerate (setFaceFacing); glyphs keep the palette
    CullFraction,  // per cluster, the share of directions the test culls it from (setClusterFractions)
    OracleFraction,  // per cluster, the share from which every face faces away (setClusterFractions)
    Loss,          // per face for the eye: visible / culled / test loss / partition loss (setFaceLoss)
    Comparison,    // per face for the eye: culled by A only / B only / both / neither (setFaceComparison)
    // A level or cut of a cluster LOD hierarchy (setClusterLod; before it every cluster is undecided):
    LodLevel,      // per cluster its level, lodLevelColour: coarse levels stand out on a cut
    LodGroup,      // per cluster its group (the clusters simplified together), the cluster palette by group
    LodCut,        // per cluster whether the cut from the eye draws it, or a coarser or a finer level there
    SubGroup,      // per face its sub-group of K cones per cluster, culled ones from the eye grey (setSubGroups)
};
const std::vector<FaceColoring>& allFaceColorings();
std::string toString(FaceColoring);

// What the LOD colourings show per cluster (ClusterScene::setClusterLod). `cut`: 0 the cut from the
// eye draws the cluster, 1 a coarser level is drawn there (its group's error is small enough), 2 a
// finer one (its own error is not).
struct ClusterLodClasses {
    std::vector<uint32_t> level, group;  // group: its colour index (kNoGroup-free: the top's own id)
    std::vector<uint8_t> cut;
    size_t levelCount = 0;
};
enum class LodCutClass : uint8_t { Drawn = 0, CoarserDrawn = 1, FinerDrawn = 2 };

// The colours the legend lists, fixed so screenshots of different runs compare. Each means one
// thing: no two of the colours one legend can list together are alike (tested).
struct SceneColours {
    // Light enough to stand out on the dark background, neutral enough not to read as drawn.
    static constexpr Rgb culled{0.62, 0.62, 0.66};         // cluster culled by the test
    static constexpr Rgb missedCull{1.00, 0.55, 0.05};     // drawn although every face is back-facing
    static constexpr Rgb drawn{0.25, 0.50, 0.95};          // drawn, has a front-facing face
    static constexpr Rgb wronglyCulled{0.95, 0.05, 0.05};  // culled although a face is front-facing (a bug)
    static constexpr Rgb undecided{0.80, 0.80, 0.80};      // no decision set yet
    static constexpr Rgb front{0.35, 0.65, 1.00};
    static constexpr Rgb back{0.55, 0.15, 0.15};
    static constexpr Rgb degenerate{0.95, 0.75, 0.55};  // tan: yellow is the picked cluster
    static constexpr Rgb unclassified{0.80, 0.80, 0.80};
    static constexpr Rgb border{0.08, 0.08, 0.08};
    static constexpr Rgb normals{0.55, 1.00, 0.25};     // lime: green is the test's region of eyes
    static constexpr Rgb lessonNormal{0.85, 0.12, 0.10};  // a lesson's normals: red, as in seed 000's figure
    static constexpr Rgb gaussSphere{0.55, 0.58, 0.65};   // the Gauss sphere, in the Gauss map and the lesson alike
    static constexpr Rgb normalTip{0.95, 0.95, 0.95};     // a normal's tip on it (and the lesson's cone axis)
    static constexpr Rgb eye{0.95, 0.10, 0.85};         // magenta: the cull eye, and nothing else
    static constexpr Rgb viewVector{0.00, 1.00, 0.70};  // turquoise: v, from the eye (and on the Gauss map)
    static constexpr Rgb highlight{1.00, 0.95, 0.15};
    static constexpr Rgb partner{0.55, 1.00, 0.25};          // lime: the cluster a lesson sets beside the picked one
    static constexpr Rgb uncullable{0.45, 0.12, 0.40};       // no cone: never culled, whatever the eye
    // The loss classes: a back face drawn because of the test, because of the partition.
    static constexpr Rgb testLoss{1.00, 0.55, 0.05};
    static constexpr Rgb partitionLoss{0.55, 0.25, 0.95};  // violet
    // The A/B comparison: culled by one configuration only, by both, by neither.
    static constexpr Rgb onlyA{1.00, 0.50, 0.05};
    static constexpr Rgb onlyB{0.15, 0.75, 0.95};
    static constexpr Rgb culledByBoth{0.62, 0.62, 0.66};
    static constexpr Rgb culledByNeither{0.36, 0.38, 0.46};
    // The LOD cut colouring: drawn by the cut from the eye, a coarser level drawn there, a finer one.
    static constexpr Rgb cutDrawn{0.20, 0.45, 1.00};  // blue, as a drawn cluster
    static constexpr Rgb cutCoarser{0.55, 0.35, 0.15};
    static constexpr Rgb cutFiner{0.45, 0.80, 0.95};
};
// A LOD level's colour: eight fixed hues from level 0 (green) through warm to cool, repeating above.
Rgb lodLevelColour(size_t level);
// The colour ramp of the fraction colourings at t in [0, 1] (dark blue through teal to yellow), and
// the largest fraction a cluster can have: (1 - sin 0) / 2, a flat cluster.
Rgb fractionRamp(double t);
constexpr double maxClusterFraction = 0.5;

// Opacity of the cone glyphs (the highlighted cluster's cone: 0.5).
constexpr double coneOpacity = 0.35;
// The normals layer draws at most this many arrows: every k-th face on larger meshes.
constexpr size_t maxNormalArrows = 100000;

}  // namespace conescope
