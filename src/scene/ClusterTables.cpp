#include "scene/ClusterTables.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <vtkLookupTable.h>

#include "core/Culling.h"

namespace conescope {

namespace {

// A table of `count` colours for integer values 0 .. count-1: the range is widened by half a step on
// each side so value v falls in the middle of entry v.
vtkSmartPointer<vtkLookupTable> indexedTable(size_t count) {
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(vtkIdType(std::max<size_t>(count, 1)));
    table->SetTableRange(-0.5, double(std::max<size_t>(count, 1)) - 0.5);
    return table;
}

void setEntry(vtkLookupTable* table, size_t index, const Rgb& colour, double alpha = 1.0) {
    table->SetTableValue(vtkIdType(index), colour[0], colour[1], colour[2], alpha);
}

}  // namespace

ClusterTables::ClusterTables(const std::vector<Rgb>& clusterColours)
    : palette(indexedTable(clusterColours.size())), decision(indexedTable(clusterColours.size())),
      visible(indexedTable(clusterColours.size())), facing(indexedTable(4)), cullFraction(indexedTable(clusterColours.size())),
      oracleFraction(indexedTable(clusterColours.size())), loss(indexedTable(5)), comparison(indexedTable(5)),
      lodLevel(indexedTable(clusterColours.size())), lodGroup(indexedTable(clusterColours.size())), lodCut(indexedTable(clusterColours.size())),
      colours_(clusterColours) {
    for (size_t c = 0; c < colours_.size(); ++c) setEntry(palette, c, colours_[c]);
    fill(nullptr, nullptr);
    setEntry(facing, size_t(Facing::Front), SceneColours::front);
    setEntry(facing, size_t(Facing::Back), SceneColours::back);
    setEntry(facing, size_t(Facing::Degenerate), SceneColours::degenerate);
    setEntry(facing, 3, SceneColours::unclassified);
    for (size_t c = 0; c < colours_.size(); ++c)
        for (vtkLookupTable* table : {cullFraction.Get(), oracleFraction.Get(), lodLevel.Get(), lodGroup.Get(), lodCut.Get()})
            setEntry(table, c, SceneColours::undecided);
    // The loss classes in the decision colours: the same meaning per face as per cluster.
    setEntry(loss, 0, SceneColours::drawn);
    setEntry(loss, 1, SceneColours::culled);
    setEntry(loss, 2, SceneColours::testLoss);
    setEntry(loss, 3, SceneColours::partitionLoss);
    setEntry(loss, 4, SceneColours::unclassified);
    setEntry(comparison, 0, SceneColours::culledByNeither);
    setEntry(comparison, 1, SceneColours::onlyA);
    setEntry(comparison, 2, SceneColours::onlyB);
    setEntry(comparison, 3, SceneColours::culledByBoth);
    setEntry(comparison, 4, SceneColours::unclassified);
}

void ClusterTables::setFractions(const std::vector<double>& cull, const std::vector<double>& oracle,
                                 const std::vector<uint8_t>& cullable) {
    const size_t clusterCount = colours_.size();
    if (cull.size() != clusterCount || oracle.size() != clusterCount || cullable.size() != clusterCount)
        throw std::invalid_argument("setClusterFractions: expected " + std::to_string(clusterCount) + " values per array");
    uncullable_ = 0;
    for (size_t c = 0; c < clusterCount; ++c) {
        uncullable_ += !cullable[c];
        setEntry(cullFraction, c, cullable[c] ? fractionRamp(cull[c] / maxClusterFraction) : SceneColours::uncullable);
        setEntry(oracleFraction, c, fractionRamp(oracle[c] / maxClusterFraction));
    }
    cullFraction->Modified();
    oracleFraction->Modified();
    hasFractions_ = true;
}

void ClusterTables::setLod(const ClusterLodClasses& lod) {
    const size_t clusterCount = colours_.size();
    if (lod.level.size() != clusterCount || lod.group.size() != clusterCount || lod.cut.size() != clusterCount)
        throw std::invalid_argument("setClusterLod: expected " + std::to_string(clusterCount) + " values per array");
    static const Rgb cutColours[] = {SceneColours::cutDrawn, SceneColours::cutCoarser, SceneColours::cutFiner};
    lodCutCounts_ = {};
    std::vector<uint32_t> groups;
    for (size_t c = 0; c < clusterCount; ++c) {
        setEntry(lodLevel, c, lodLevelColour(lod.level[c]));
        // Groups in the palette's hues, by their number: neighbouring groups mostly differ.
        setEntry(lodGroup, c, colourOfClass(lod.group[c] % uint32_t(baseHues().size())));
        setEntry(lodCut, c, cutColours[std::min<uint8_t>(lod.cut[c], 2)]);
        ++lodCutCounts_[std::min<uint8_t>(lod.cut[c], 2)];
        groups.push_back(lod.group[c]);
    }
    std::sort(groups.begin(), groups.end());
    lodGroups_ = size_t(std::unique(groups.begin(), groups.end()) - groups.begin());
    lodLevels_ = lod.levelCount;
    for (vtkLookupTable* table : {lodLevel.Get(), lodGroup.Get(), lodCut.Get()}) table->Modified();
    hasLod_ = true;
}

void ClusterTables::setDecisions(const std::vector<uint8_t>& culled, const std::vector<uint8_t>& allBackFacing) {
    const size_t clusterCount = colours_.size();
    if (culled.size() != clusterCount || allBackFacing.size() != clusterCount)
        throw std::invalid_argument("setClusterDecisions: expected " + std::to_string(clusterCount) +
                                    " values per array, got " + std::to_string(culled.size()) + " and " +
                                    std::to_string(allBackFacing.size()));
    fill(&culled, &allBackFacing);
    hasDecisions_ = true;
}

void ClusterTables::clearDecisions() {
    fill(nullptr, nullptr);
    hasDecisions_ = false;
}

vtkLookupTable* ClusterTables::forGlyphs(FaceColoring coloring) const {
    switch (coloring) {
    case FaceColoring::CullDecision:
    case FaceColoring::Loss:
    case FaceColoring::Comparison: return decision;
    case FaceColoring::CullFraction: return cullFraction;
    case FaceColoring::OracleFraction: return oracleFraction;
    // Without a LOD level or cut the clusters keep their palette.
    case FaceColoring::LodLevel: return hasLod_ ? lodLevel : palette;
    case FaceColoring::LodGroup: return hasLod_ ? lodGroup : palette;
    case FaceColoring::LodCut: return hasLod_ ? lodCut : palette;
    case FaceColoring::Cluster:
    case FaceColoring::SubGroup:
    case FaceColoring::FaceFacing: return palette;
    }
    return palette;
}

// Without decisions (nullptr) every cluster is undecided and keeps its palette colour in the eye view.
void ClusterTables::fill(const std::vector<uint8_t>* culled, const std::vector<uint8_t>* allBackFacing) {
    counts_ = {};
    for (size_t c = 0; c < colours_.size(); ++c) {
        if (!culled) {
            setEntry(decision, c, SceneColours::undecided);
            setEntry(visible, c, colours_[c]);
            continue;
        }
        const bool isCulled = (*culled)[c] != 0, back = (*allBackFacing)[c] != 0;
        const Rgb& colour = isCulled ? (back ? SceneColours::culled : SceneColours::wronglyCulled)
                                     : (back ? SceneColours::missedCull : SceneColours::drawn);
        (isCulled ? (back ? counts_.culled : counts_.wronglyCulled) : (back ? counts_.missed : counts_.drawn))++;
        setEntry(decision, c, colour);
        // Alpha 0 removes the cluster from the eye's view (discarded in the fragment shader).
        setEntry(visible, c, colours_[c], isCulled ? 0.0 : 1.0);
    }
    decision->Modified();
    visible->Modified();
}

}  // namespace conescope
