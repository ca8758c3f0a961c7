// The VTK picture of one partition: the mesh coloured per cluster, cull decisions, cluster borders,
// normal cones, face normals, AABBs, bounding spheres, the cull eye and a picked cluster. Every number
// comes from src/core; the scene only turns it into geometry and colours.
//
// Colouring goes through lookup tables on one per-face int array "cluster_id", so a new eye only
// rewrites K table entries (K = cluster count), never a per-face array: the scene stays interactive
// on meshes of a million triangles.
//
// No Qt here: the GUI adds the actors to its renderers (addTo) and calls the setters; the CLI and the
// tests render headlessly through SceneRendering.h.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include "core/ClusterBounds.h"
#include "core/Culling.h"
#include "core/Mesh.h"
#include "core/Partition.h"
#include "core/Views.h"
#include "scene/ClusterPalette.h"

class vtkActor;
class vtkCamera;
class vtkLegendBoxActor;
class vtkLookupTable;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

namespace conescope {

// Name of the per-face cluster index on the mesh polydata and of the per-cell cluster index on every
// per-cluster glyph polydata (cones, boxes, spheres).
inline const char* const clusterIdArrayName = "cluster_id";
// Per-face Facing value (0 front, 1 back, 2 degenerate, 3 not classified yet), written by setFaceFacing.
inline const char* const facingArrayName = "facing";

// Switchable parts of the scene. Default visibility: Faces, Borders, Cones, Eye, Highlight, Legend on;
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
    Highlight,  // the picked cluster (after setHighlightedCluster): outline, opaque cone, box and sphere,
                // shown whatever the Cones / Boxes / Spheres layers say
    Legend,     // what the colours mean, for the visible layers
};
const std::vector<Layer>& allLayers();
std::string toString(Layer);  // "faces", "borders", "cones", "normals", "boxes", "spheres", "eye", ...

// How the faces (and the per-cluster glyphs) are coloured.
enum class FaceColoring {
    Cluster,       // the cluster palette: neighbouring clusters differ
    CullDecision,  // per cluster: culled / missed cull / drawn (setClusterDecisions)
    FaceFacing,    // per face, from the oracle: front / back / degenerate (setFaceFacing); glyphs keep the palette
};
std::string toString(FaceColoring);

// The colours the legend lists, fixed so screenshots of different runs compare.
struct SceneColours {
    static constexpr Rgb culled{0.30, 0.30, 0.32};         // cluster culled by the test
    static constexpr Rgb missedCull{1.00, 0.55, 0.05};     // drawn although every face is back-facing
    static constexpr Rgb drawn{0.25, 0.50, 0.95};          // drawn, has a front-facing face
    static constexpr Rgb wronglyCulled{0.95, 0.05, 0.05};  // culled although a face is front-facing (a bug)
    static constexpr Rgb undecided{0.80, 0.80, 0.80};      // no decision set yet
    static constexpr Rgb front{0.35, 0.65, 1.00};
    static constexpr Rgb back{0.55, 0.15, 0.15};
    static constexpr Rgb degenerate{1.00, 0.85, 0.10};
    static constexpr Rgb unclassified{0.80, 0.80, 0.80};
    static constexpr Rgb border{0.08, 0.08, 0.08};
    static constexpr Rgb normals{0.10, 0.75, 0.30};
    static constexpr Rgb eye{0.95, 0.10, 0.85};
    static constexpr Rgb highlight{1.00, 0.95, 0.15};
};
// Opacity of the cone glyphs (the highlighted cluster's cone is opaque).
constexpr double coneOpacity = 0.35;
// The normals layer draws at most this many arrows: every k-th face on larger meshes.
constexpr size_t maxNormalArrows = 100000;

class ClusterScene {
public:
    // world and faces must come from mesh (worldPositions, computeFaceGeometry), bounds from the same
    // partition (computeClusterBounds). Copies what it needs: the arguments may go away afterwards.
    // Throws std::invalid_argument if the sizes do not match.
    ClusterScene(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                 const Partition& partition, const ClusterBounds& bounds);
    ~ClusterScene();
    ClusterScene(const ClusterScene&) = delete;
    ClusterScene& operator=(const ClusterScene&) = delete;
    // A moved-from scene may only be destroyed or assigned to.
    ClusterScene(ClusterScene&&) noexcept;
    ClusterScene& operator=(ClusterScene&&) noexcept;

    // Adds / removes every actor of the observer view (all layers, including the legend; hidden layers
    // are added too, switched off). The scene's actors may be added to one renderer at a time.
    void addTo(vtkRenderer* renderer) const;
    void removeFrom(vtkRenderer* renderer) const;

    void setLayerVisible(Layer layer, bool visible);
    bool layerVisible(Layer layer) const;

    void setFaceColoring(FaceColoring coloring);
    FaceColoring faceColoring() const;

    // One value per cluster each (1 = true). Rewrites the K entries of the decision lookup table and of
    // the visible-clusters table, nothing per face. Throws std::invalid_argument on a size mismatch.
    // Entry colour: culled && allBackFacing -> culled, culled && !allBackFacing -> wronglyCulled,
    // !culled && allBackFacing -> missedCull, otherwise drawn.
    void setClusterDecisions(const std::vector<uint8_t>& culled, const std::vector<uint8_t>& allBackFacing);
    // Back to "no decision": every cluster undecided and visible in the eye view.
    void clearClusterDecisions();
    bool hasClusterDecisions() const;

    // The oracle's per-face result (classifyFaces). Writes the per-face "facing" array.
    void setFaceFacing(const std::vector<Facing>& facing);

    // Places the eye marker: for a perspective eye a sphere at the position with a cone pointing at
    // lookAt; for an orthographic eye an arrow along eye.direction outside the mesh bounds, aimed at
    // lookAt. Shows the Eye layer's actor if the layer is visible.
    void setEye(const Eye& eye, const glm::dvec3& lookAt);
    bool hasEye() const;
    const Eye& eye() const;  // Eye{} before setEye
    glm::dvec3 eyeLookAt() const;

    // -1 = none. Outlines the cluster's faces and draws its cone, box and sphere opaque.
    // Throws std::out_of_range for an id outside [-1, K).
    void setHighlightedCluster(int cluster);
    int highlightedCluster() const;

    // The cluster a picked cell belongs to (vtkCellPicker::GetActor / GetCellId), or -1 if the actor
    // is not one of this scene's per-cluster actors (eye, legend, unknown) or the id is out of range.
    // Works for the faces actor, the visible-clusters actors, borders (the cluster of a face next to
    // the edge), cones, normals, boxes, spheres and the highlight actors.
    int clusterOfCell(vtkActor* pickedActor, vtkIdType cellId) const;

    // A new actor for the eye's own view (a second renderer or window): the same mesh polydata coloured
    // by the cluster palette, with culled clusters removed (lookup-table alpha 0, discarded in the
    // fragment shader, so the actor stays in the opaque pass). setClusterDecisions updates every actor
    // made here through their shared lookup table. Each call makes a new actor (one per renderer).
    vtkSmartPointer<vtkActor> makeVisibleClustersActor() const;

    // Sets a camera to look from the cull eye: perspective eyes from the position towards lookAt,
    // orthographic eyes with a parallel projection along the direction, fitted to the mesh bounds.
    void applyEyeToCamera(vtkCamera* camera) const;

    size_t clusterCount() const;
    size_t faceCount() const;
    // World-space bounds of the mesh: {xmin, xmax, ymin, ymax, zmin, zmax} (VTK order).
    std::array<double, 6> meshBounds() const;
    double meanEdgeLength() const;
    const std::vector<Rgb>& palette() const;

    // Direct access for the GUI and the tests.
    vtkPolyData* meshPolyData() const;      // points, one polygon per face, cell arrays cluster_id, facing
    vtkPolyData* borderPolyData() const;    // lines; cell array cluster_id = cluster of one adjacent face
    vtkPolyData* conePolyData() const;      // triangles; cell array cluster_id
    vtkPolyData* boxPolyData() const;       // lines, 12 per cluster in cluster order; cell array cluster_id
    vtkPolyData* spherePolyData() const;    // lines; cell array cluster_id
    vtkLookupTable* paletteLookupTable() const;         // K entries: the cluster palette
    vtkLookupTable* decisionLookupTable() const;        // K entries: decision colours
    vtkLookupTable* visibleClustersLookupTable() const;  // K entries: palette, alpha 0 when culled
    vtkActor* actor(Layer layer) const;     // the layer's main actor; nullptr for Legend
    // Entries follow the visible layers and the colouring; each symbol is a small polydata whose RGB
    // cell scalars are the colours (several bars for "a colour per cluster"), the text is white.
    vtkLegendBoxActor* legend() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace conescope
