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
    setSubGroups({}, {}, 0);
}

void FacesLayer::recolour(FaceColoring coloring) {
    // The sub-group colours are written per face; every other colouring maps ids through a table.
    if (coloring == FaceColoring::SubGroup)
        mapper_->SetColorModeToDirectScalars();
    else
        mapper_->SetColorModeToMapScalars();
    if (coloring == FaceColoring::FaceFacing) {
        mapper_->SelectColorArray(facingArrayName);
        mapper_->SetLookupTable(data_.tables.facing);
    } else if (coloring == FaceColoring::Loss) {
        mapper_->SelectColorArray(lossArrayName);
        mapper_->SetLookupTable(data_.tables.loss);
    } else if (coloring == FaceColoring::Comparison) {
        mapper_->SelectColorArray(comparisonArrayName);
        mapper_->SetLookupTable(data_.tables.comparison);
    } else if (coloring == FaceColoring::SubGroup) {
        mapper_->SelectColorArray(subGroupArrayName);
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
    } else if (coloring == FaceColoring::SubGroup) {
        if (subGroupCones_ == 0) {
            entries.push_back({"no sub-groups (choose 2, 4 or 8 cones per cluster): clusters", clusterLegendColours()});
            return;
        }
        std::vector<Rgb> shades;
        for (uint32_t i = 0; i < subGroupCones_; ++i) shades.push_back(subGroupShade(data_.palette.empty() ? Rgb{0.3, 0.5, 0.8} : data_.palette[0], i, subGroupCones_));
        entries.push_back({"sub-groups, " + std::to_string(subGroupCones_) + " a cluster: shades of its colour", shades});
        entries.push_back({"sub-group culled from the eye" + countLabel(subGroupsCulled_) + ", " + std::to_string(subGroupTrianglesCulled_) + " tris",
                           {SceneColours::culled}});
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

Rgb subGroupShade(const Rgb& colour, uint32_t index, uint32_t cones) {
    // From darker to lighter than the cluster's colour, evenly: neighbours inside a cluster differ.
    const double t = cones > 1 ? double(index) / double(cones - 1) : 0.5;
    Rgb shade;
    for (int k = 0; k < 3; ++k)
        shade[k] = t < 0.5 ? colour[k] * (0.35 + 1.3 * t) : colour[k] + (1.0 - colour[k]) * 1.3 * (t - 0.5);
    return shade;
}

void FacesLayer::setSubGroups(const std::vector<uint8_t>& groupOfFace, const std::vector<uint8_t>& culledGroups, uint32_t cones) {
    const size_t faceCount = data_.clusterOfFace.size();
    if (cones > 0 && (groupOfFace.size() != faceCount || culledGroups.size() != data_.bounds.count() * cones))
        throw std::invalid_argument("setSubGroups: expected " + std::to_string(faceCount) + " faces and " +
                                    std::to_string(data_.bounds.count() * cones) + " sub-groups");
    subGroupCones_ = cones;
    subGroupsCulled_ = subGroupTrianglesCulled_ = 0;
    for (uint8_t culled : culledGroups) subGroupsCulled_ += culled ? 1 : 0;
    uint8_t* rgb = data_.subGroup->GetPointer(0);
    for (size_t f = 0; f < faceCount; ++f) {
        const uint32_t c = data_.clusterOfFace[f];
        Rgb colour = data_.palette[c];  // without sub-groups, the clusters
        if (cones > 0) {
            const bool culled = culledGroups[size_t(c) * cones + groupOfFace[f]] != 0;
            colour = culled ? SceneColours::culled : subGroupShade(data_.palette[c], groupOfFace[f], cones);
            if (culled) subGroupTrianglesCulled_ += data_.mesh.faceSize(f) - 2;
        }
        for (int k = 0; k < 3; ++k) rgb[3 * f + k] = uint8_t(std::clamp(colour[k], 0.0, 1.0) * 255.0 + 0.5);
    }
    data_.subGroup->Modified();
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
