#include "scene/FacesLayer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

namespace conescope {

FacesLayer::FacesLayer(const SceneData& data)
    : SceneLayer(data), mapper_(cellArrayMapper(data.meshData, clusterIdArrayName, data.tables.palette)),
      actor_(actorFor(mapper_)) {
    actor_->GetProperty()->SetInterpolationToFlat();
}

void FacesLayer::recolour(FaceColoring coloring) {
    if (coloring == FaceColoring::FaceFacing) {
        mapper_->SelectColorArray(facingArrayName);
        mapper_->SetLookupTable(data_.tables.facing);
    } else if (coloring == FaceColoring::Loss) {
        mapper_->SelectColorArray(lossArrayName);
        mapper_->SetLookupTable(data_.tables.loss);
    } else if (coloring == FaceColoring::Comparison) {
        mapper_->SelectColorArray(comparisonArrayName);
        mapper_->SetLookupTable(data_.tables.comparison);
    } else {
        mapper_->SelectColorArray(clusterIdArrayName);
        mapper_->SetLookupTable(data_.tables.forGlyphs(coloring));
    }
}

void FacesLayer::addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const {
    if (coloring == FaceColoring::Cluster) {
        entries.push_back({"clusters" + countLabel(data_.palette.size()), clusterLegendColours()});
    } else if (coloring == FaceColoring::CullDecision) {
        const DecisionCounts& counts = data_.tables.decisionCounts();
        if (!data_.tables.hasDecisions()) {
            entries.push_back({"no cull decision yet", {SceneColours::undecided}});
        } else {
            entries.push_back({"culled" + countLabel(counts.culled), {SceneColours::culled}});
            entries.push_back({"missed cull: all back" + countLabel(counts.missed), {SceneColours::missedCull}});
            entries.push_back({"drawn: front faces" + countLabel(counts.drawn), {SceneColours::drawn}});
            if (counts.wronglyCulled)
                entries.push_back({"culled with front faces" + countLabel(counts.wronglyCulled), {SceneColours::wronglyCulled}});
        }
    } else if (coloring == FaceColoring::CullFraction || coloring == FaceColoring::OracleFraction) {
        const bool cull = coloring == FaceColoring::CullFraction;
        if (!data_.tables.hasFractions()) {
            entries.push_back({"no cull map yet", {SceneColours::undecided}});
            return;
        }
        entries.push_back({std::string(cull ? "cull fraction: share of views the test culls from" : "oracle fraction: share of views all faces face away"),
                           fractionBarColours(), std::array<double, 2>{0.0, maxClusterFraction}});
        if (cull) entries.push_back({"uncullable: no cone" + countLabel(data_.tables.uncullableClusters()), {SceneColours::uncullable}});
    } else if (coloring == FaceColoring::LodLevel || coloring == FaceColoring::LodGroup || coloring == FaceColoring::LodCut) {
        addLodLegendEntries(coloring, entries);
    } else if (coloring == FaceColoring::Loss) {
        if (!hasLoss_) entries.push_back({"no eye measured yet", {SceneColours::unclassified}});
        entries.push_back({"culled back face" + countLabel(lossCounts_[1]), {SceneColours::culled}});
        entries.push_back({"lost to the test" + countLabel(lossCounts_[2]), {SceneColours::testLoss}});
        entries.push_back({"lost to the partition" + countLabel(lossCounts_[3]), {SceneColours::partitionLoss}});
        entries.push_back({"visible or degenerate" + countLabel(lossCounts_[0]), {SceneColours::drawn}});
    } else if (coloring == FaceColoring::Comparison) {
        if (!hasComparison_) {
            entries.push_back({"no A to compare with (pin one)", {SceneColours::unclassified}});
            return;
        }
        const auto triangles = [](size_t n) { return " (" + std::to_string(n) + " tris)"; };
        entries.push_back({"culled by A only" + triangles(comparisonTriangles_[1]), {SceneColours::onlyA}});
        entries.push_back({"culled by B only" + triangles(comparisonTriangles_[2]), {SceneColours::onlyB}});
        entries.push_back({"culled by both" + triangles(comparisonTriangles_[3]), {SceneColours::culledByBoth}});
        entries.push_back({"culled by neither" + triangles(comparisonTriangles_[0]), {SceneColours::culledByNeither}});
        // Unequal cluster counts: the comparison is not fair, and the picture says so.
        if (!comparisonWarning_.empty())
            entries.push_back({"unequal cluster counts: see the statistics", {SceneColours::wronglyCulled}});
    } else {
        if (!hasFacing_) entries.push_back({"faces not classified yet", {SceneColours::unclassified}});
        entries.push_back({"front-facing face", {SceneColours::front}});
        entries.push_back({"back-facing face", {SceneColours::back}});
        entries.push_back({"degenerate face", {SceneColours::degenerate}});
    }
}

void FacesLayer::addLodLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const {
    const ClusterTables& tables = data_.tables;
    if (!tables.hasLod()) {
        entries.push_back({"clusters" + countLabel(data_.palette.size()) + ", no LOD level or cut shown", clusterLegendColours()});
        return;
    }
    if (coloring == FaceColoring::LodLevel) {
        // A bar of the levels' colours, level 0 at its left end.
        std::vector<Rgb> colours;
        for (size_t l = 0; l < std::max<size_t>(tables.lodLevelCount(), 1); ++l) colours.push_back(lodLevelColour(l));
        entries.push_back({"LOD level of each cluster", colours, std::array<double, 2>{0.0, double(colours.size() - 1)}});
    } else if (coloring == FaceColoring::LodGroup) {
        entries.push_back({"LOD groups" + countLabel(tables.lodGroupCount()), clusterLegendColours()});
    } else {
        const std::array<size_t, 3>& counts = tables.lodCutCounts();
        entries.push_back({"drawn by the LOD cut" + countLabel(counts[0]), {SceneColours::cutDrawn}});
        entries.push_back({"LOD cut draws a coarser level" + countLabel(counts[1]), {SceneColours::cutCoarser}});
        entries.push_back({"LOD cut draws a finer level" + countLabel(counts[2]), {SceneColours::cutFiner}});
    }
}

void FacesLayer::setFaceFacing(const std::vector<Facing>& facing) {
    const size_t faceCount = data_.clusterOfFace.size();
    if (facing.size() != faceCount)
        throw std::invalid_argument("setFaceFacing: expected " + std::to_string(faceCount) + " faces, got " +
                                    std::to_string(facing.size()));
    static_assert(sizeof(Facing) == 1, "Facing is stored as one byte per face");
    std::copy(reinterpret_cast<const uint8_t*>(facing.data()), reinterpret_cast<const uint8_t*>(facing.data()) + facing.size(),
              data_.facing->GetPointer(0));
    data_.facing->Modified();
    hasFacing_ = true;
}

void FacesLayer::setFaceComparison(const std::vector<FaceDiff>& comparison, const std::string& warning) {
    const size_t faceCount = data_.clusterOfFace.size();
    if (!comparison.empty() && comparison.size() != faceCount)
        throw std::invalid_argument("setFaceComparison: expected " + std::to_string(faceCount) + " faces, got " +
                                    std::to_string(comparison.size()));
    comparisonTriangles_ = {};
    uint8_t* values = data_.comparison->GetPointer(0);
    for (size_t f = 0; f < faceCount; ++f) {
        values[f] = comparison.empty() ? 4 : uint8_t(comparison[f]);
        // Triangles, as the comparison's statistics count them.
        if (!comparison.empty()) comparisonTriangles_[values[f]] += data_.mesh.faceSize(f) - 2;
    }
    data_.comparison->Modified();
    hasComparison_ = !comparison.empty();
    comparisonWarning_ = comparison.empty() ? std::string() : warning;
}

void FacesLayer::setFaceLoss(const std::vector<FaceLoss>& loss) {
    const size_t faceCount = data_.clusterOfFace.size();
    if (loss.size() != faceCount)
        throw std::invalid_argument("setFaceLoss: expected " + std::to_string(faceCount) + " faces, got " + std::to_string(loss.size()));
    lossCounts_ = {};
    uint8_t* values = data_.loss->GetPointer(0);
    for (size_t f = 0; f < faceCount; ++f) {
        values[f] = uint8_t(loss[f]);
        ++lossCounts_[size_t(loss[f]) & 3];
    }
    data_.loss->Modified();
    hasLoss_ = true;
}

}  // namespace conescope
