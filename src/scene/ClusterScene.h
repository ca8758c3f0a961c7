// The VTK picture of one partition: the mesh coloured per cluster, cull decisions, cluster borders,
// normal cones, face normals, AABBs, bounding spheres, the cull eye and a picked cluster. Every number
// comes from src/core; the scene only turns it into geometry and colours.
//
// Colouring goes through lookup tables on one per-face int array "cluster_id", so a new eye only
// rewrites K table entries (K = cluster count), never a per-face array: the scene stays interactive
// on meshes of a million triangles.
//
// Each layer is one small class (SceneLayer.h) that owns its actors; the scene holds the shared data
// once (SceneData.h) and forwards to the layers.
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
#include "core/Comparison.h"
#include "core/Culling.h"
#include "core/Mesh.h"
#include "core/Partition.h"
#include "core/Views.h"
#include "scene/ClusterPalette.h"
#include "scene/LessonLayer.h"
#include "scene/SceneLegend.h"
#include "scene/SceneTypes.h"
#include "scene/CullTestLayer.h"

class vtkActor;
class vtkCamera;
class vtkLookupTable;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

namespace conescope {

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
    // What happened to each face from the eye (core faceLosses). Writes the per-face "loss" array.
    void setFaceLoss(const std::vector<FaceLoss>& loss);
    // The A/B comparison per face for the eye (core faceDiff); empty clears it. Writes the per-face
    // "comparison" array. `warning` (clusterCountWarning) goes into the legend when not empty.
    void setFaceComparison(const std::vector<FaceDiff>& comparison, const std::string& warning = {});
    // K cones per cluster from the eye for the sub-group colouring (FacesLayer::setSubGroups); K = 0: none.
    void setSubGroups(const std::vector<uint8_t>& groupOfFace, const std::vector<uint8_t>& culledGroups, uint32_t cones);
    // The cull map's per-cluster shares (ClusterSet::cullMap) for the fraction colourings, and which
    // clusters have a cone at all. Rewrites K table entries. Throws std::invalid_argument on a size mismatch.
    void setClusterFractions(const std::vector<double>& cullFraction, const std::vector<double>& oracleFraction,
                             const std::vector<uint8_t>& cullable);

    // Per cluster its LOD level, group and cut class for the LOD colourings. Rewrites K table entries.
    // Throws std::invalid_argument on a size mismatch.
    void setClusterLod(const ClusterLodClasses& lod);

    // The picked cluster's test in 3D (Layer::Test; makeTestDrawing); a drawing with cluster -1 clears it.
    // Throws std::out_of_range for a cluster outside [-1, K).
    void setTestDrawing(const CullTestDrawing& drawing);
    const CullTestDrawing& testDrawing() const;

    // A lesson step's picture of its cluster (Layer::Lesson); step 0 clears it. Throws
    // std::out_of_range for a cluster outside [0, K).
    void setLessonDrawing(const LessonDrawing& drawing);
    const LessonDrawing& lessonDrawing() const;

    // Places the eye marker: for a perspective eye a sphere at the position with a cone pointing at
    // lookAt; for an orthographic eye an arrow along eye.direction outside the mesh bounds, aimed at
    // lookAt. Shows the Eye layer's actor if the layer is visible.
    void setEye(const Eye& eye, const glm::dvec3& lookAt);
    bool hasEye() const;
    const Eye& eye() const;  // Eye{} before setEye

    // -1 = none. Outlines the cluster's faces and draws its cone (half see-through), box and sphere bright.
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
    // Entries follow the visible layers and the colouring (SceneLegend.h).
    const SceneLegend& legend() const;
    // The legend's size for a view this many pixels high: smaller in a small view (SceneLegend::setScale).
    void fitLegend(int viewHeight, double pixelRatio = 1.0);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace conescope
