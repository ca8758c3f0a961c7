// Layer::Faces: the mesh polydata, coloured by cluster, by cull decision, by a cluster's cull map
// fraction, or per face by the oracle or by what happened to it from the eye (its loss class).
#pragma once

#include <array>
#include <vector>

#include "core/Culling.h"
#include "core/Comparison.h"
#include "core/Pipeline.h"
#include "scene/SceneLayer.h"

namespace conescope {

// Sub-group `index` of `cones` in a cluster of this colour: from darker to lighter shades.
Rgb subGroupShade(const Rgb& colour, uint32_t index, uint32_t cones);

class FacesLayer : public SceneLayer {
public:
    explicit FacesLayer(const SceneData& data);

    std::vector<vtkActor*> actors() const override { return {actor_}; }
    // Switches the mapper between the cluster_id array (palette or decision table) and the facing array.
    void recolour(FaceColoring coloring) override;
    void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const override;

    // The oracle's per-face result (classifyFaces) into the mesh's "facing" array.
    // Throws std::invalid_argument on a size mismatch.
    void setFaceFacing(const std::vector<Facing>& facing);
    // The eye's per-face loss classes (faceLosses) into the mesh's "loss" array, counted for the legend
    // in faces. Throws std::invalid_argument on a size mismatch.
    void setFaceLoss(const std::vector<FaceLoss>& loss);
    // Per face the A/B comparison for the eye (core faceDiff), counted in triangles for the legend,
    // with the cluster-count warning if any; empty: nothing compared. Throws std::invalid_argument on
    // a size mismatch.
    void setFaceComparison(const std::vector<FaceDiff>& comparison, const std::string& warning);
    // K cones per cluster from the eye: each face's sub-group within its cluster (0 to K - 1) and each
    // sub-group's verdict (cluster * K + index, 1 = culled). K = 0: no K-cone record. Throws
    // std::invalid_argument on a size mismatch.
    void setSubGroups(const std::vector<uint8_t>& groupOfFace, const std::vector<uint8_t>& culledGroups, uint32_t cones);

private:
    // The LOD colourings' entries: the level bar, the groups, or the cut's three classes.
    void addLodLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const;

    vtkSmartPointer<vtkPolyDataMapper> mapper_;
    vtkSmartPointer<vtkActor> actor_;
    bool hasFacing_ = false;
    bool hasLoss_ = false;
    std::array<size_t, 4> lossCounts_{};
    bool hasComparison_ = false;
    std::array<size_t, 4> comparisonTriangles_{};
    std::string comparisonWarning_;
    uint32_t subGroupCones_ = 0;
    size_t subGroupsCulled_ = 0, subGroupTrianglesCulled_ = 0;
};

}  // namespace conescope
