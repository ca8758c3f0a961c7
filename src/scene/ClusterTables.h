// The scene's lookup tables. Every colour goes through them on one per-face int array "cluster_id"
// (or "facing"), so a new eye or a new colouring rewrites K table entries (K = cluster count), never a
// per-face array: the scene stays interactive on meshes of a million triangles.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <vtkLookupTable.h>
#include <vtkSmartPointer.h>

#include "scene/SceneTypes.h"

namespace conescope {

// How many clusters fall in each decision class (setDecisions), for the legend.
struct DecisionCounts {
    size_t culled = 0, wronglyCulled = 0, missed = 0, drawn = 0;
};

class ClusterTables {
public:
    // clusterColours: the palette, one colour per cluster; kept by reference, it must outlive the tables.
    explicit ClusterTables(const std::vector<Rgb>& clusterColours);

    // One value per cluster each (1 = true): rewrites the decision and visible-clusters entries.
    // Throws std::invalid_argument on a size mismatch. Entry colour: culled && allBackFacing -> culled,
    // culled && !allBackFacing -> wronglyCulled, !culled && allBackFacing -> missedCull, otherwise drawn.
    void setDecisions(const std::vector<uint8_t>& culled, const std::vector<uint8_t>& allBackFacing);
    // Every cluster undecided and visible in the eye view.
    void clearDecisions();
    bool hasDecisions() const { return hasDecisions_; }
    const DecisionCounts& decisionCounts() const { return counts_; }

    // Per cluster, the cull map's shares (CullMap.h) on the fraction ramp, 0 .. maxClusterFraction;
    // clusters without a cone (cullable 0) in the uncullable colour on the cull-fraction table.
    // Throws std::invalid_argument on a size mismatch.
    void setFractions(const std::vector<double>& cullFraction, const std::vector<double>& oracleFraction,
                      const std::vector<uint8_t>& cullable);
    bool hasFractions() const { return hasFractions_; }
    size_t uncullableClusters() const { return uncullable_; }

    // Per cluster its LOD level, group and cut class (ClusterLodClasses) into the LOD tables. Throws
    // std::invalid_argument on a size mismatch.
    void setLod(const ClusterLodClasses& lod);
    bool hasLod() const { return hasLod_; }
    size_t lodLevelCount() const { return lodLevels_; }
    size_t lodGroupCount() const { return lodGroups_; }
    const std::array<size_t, 3>& lodCutCounts() const { return lodCutCounts_; }

    // The table the per-cluster glyphs are coloured with: the decisions in decision and loss mode,
    // the fraction in fraction modes, the LOD tables in LOD modes once set, else the palette.
    vtkLookupTable* forGlyphs(FaceColoring coloring) const;

    vtkSmartPointer<vtkLookupTable> palette;   // K entries: the cluster palette
    vtkSmartPointer<vtkLookupTable> decision;  // K entries: decision colours
    vtkSmartPointer<vtkLookupTable> visible;   // K entries: palette, alpha 0 when culled
    vtkSmartPointer<vtkLookupTable> facing;    // 4 entries: one per Facing value and "not classified"
    vtkSmartPointer<vtkLookupTable> cullFraction, oracleFraction;  // K entries each: the fraction ramp
    vtkSmartPointer<vtkLookupTable> loss;      // 5 entries: one per FaceLoss value and "not measured"
    vtkSmartPointer<vtkLookupTable> comparison;  // 5 entries: one per FaceDiff value and "not compared"
    vtkSmartPointer<vtkLookupTable> lodLevel, lodGroup, lodCut;  // K entries each: the LOD colourings

private:
    void fill(const std::vector<uint8_t>* culled, const std::vector<uint8_t>* allBackFacing);

    const std::vector<Rgb>& colours_;
    DecisionCounts counts_;
    bool hasDecisions_ = false;
    bool hasFractions_ = false;
    size_t uncullable_ = 0;
    bool hasLod_ = false;
    size_t lodLevels_ = 0, lodGroups_ = 0;
    std::array<size_t, 3> lodCutCounts_{};
};

}  // namespace conescope
