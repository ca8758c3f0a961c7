#include "scene/SceneLayer.h"

#include <algorithm>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProp.h>
#include <vtkProperty.h>

namespace conescope {

int SceneLayer::clusterOfCell(vtkActor* actor, vtkIdType cellId) const { return clusterIdOfCell(actor, cellId); }

void SceneLayer::setVisible(bool visible) {
    visible_ = visible;
    applyVisibility();
}

bool SceneLayer::owns(vtkActor* actor) const {
    const std::vector<vtkActor*> ours = actors();
    return std::find(ours.begin(), ours.end(), actor) != ours.end();
}

void SceneLayer::applyVisibility() {
    for (vtkActor* actor : actors()) actor->SetVisibility(visible_ && hasContent());
    for (vtkProp* overlay : overlays()) overlay->SetVisibility(visible_ && hasContent());
}

int clusterIdOfCell(vtkActor* actor, vtkIdType cellId) {
    if (!actor || cellId < 0 || !actor->GetMapper()) return -1;
    auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputAsDataSet());
    if (!data || cellId >= data->GetNumberOfCells()) return -1;
    if (auto* ids = vtkIntArray::SafeDownCast(data->GetCellData()->GetArray(clusterIdArrayName))) return ids->GetValue(cellId);
    // Glyphs made by vtkGlyph3D carry the id on their points.
    if (auto* ids = vtkIntArray::SafeDownCast(data->GetPointData()->GetArray(clusterIdArrayName))) {
        vtkIdType pointCount = 0;
        const vtkIdType* pointIds = nullptr;
        data->GetCellPoints(cellId, pointCount, pointIds);
        if (pointCount > 0) return ids->GetValue(pointIds[0]);
    }
    return -1;
}

vtkSmartPointer<vtkPolyDataMapper> cellArrayMapper(vtkPolyData* input, const char* arrayName, vtkLookupTable* table) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(input);
    mapper->ScalarVisibilityOn();
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(arrayName);
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOff();
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
    return mapper;
}

vtkSmartPointer<vtkPolyDataMapper> plainMapper(vtkPolyData* input) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(input);
    mapper->ScalarVisibilityOff();
    return mapper;
}

vtkSmartPointer<vtkActor> actorFor(vtkMapper* mapper) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

vtkSmartPointer<vtkActor> lineActor(vtkMapper* mapper, double width) {
    auto actor = actorFor(mapper);
    actor->GetProperty()->SetLineWidth(float(width));
    actor->GetProperty()->LightingOff();
    return actor;
}

void setColour(vtkActor* actor, const Rgb& colour) { actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]); }

vtkSmartPointer<vtkPolyData> emptyPolyData() {
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(vtkSmartPointer<vtkPoints>::New());
    return polyData;
}

vtkSmartPointer<vtkPolyData> pointPolyData(const std::vector<glm::dvec3>& positions, double scale) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    for (const glm::dvec3& p : positions) {
        const vtkIdType id = points->InsertNextPoint(scale * p.x, scale * p.y, scale * p.z);
        vertices->InsertNextCell(1, &id);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetVerts(vertices);
    return data;
}

vtkSmartPointer<vtkActor> pointsActor(const Rgb& colour, double size) {
    auto actor = actorFor(plainMapper(emptyPolyData()));
    setColour(actor, colour);
    actor->GetProperty()->SetPointSize(float(size));
    actor->GetProperty()->RenderPointsAsSpheresOn();
    return actor;
}

void setInput(vtkActor* actor, vtkPolyData* data) { vtkMapper::SafeDownCast(actor->GetMapper())->SetInputDataObject(data); }

std::string countLabel(size_t n) { return " (" + std::to_string(n) + ")"; }

std::vector<Rgb> clusterLegendColours() { return std::vector<Rgb>(baseHues().begin(), baseHues().begin() + 4); }

std::vector<Rgb> fractionBarColours() {
    std::vector<Rgb> colours;
    for (int i = 0; i < 64; ++i) colours.push_back(fractionRamp((i + 0.5) / 64.0));
    return colours;
}

std::vector<Rgb> fractionLegendColours() {
    std::vector<Rgb> colours;
    for (int i = 0; i < 6; ++i) colours.push_back(fractionRamp(i / 5.0));
    return colours;
}

// Glyphs take the faces' cluster colours, or the decision colours in decision mode.
std::vector<Rgb> glyphLegendColours(FaceColoring coloring, bool lodShown) {
    if (coloring == FaceColoring::CullDecision || coloring == FaceColoring::Loss || coloring == FaceColoring::Comparison)
        return {SceneColours::culled, SceneColours::missedCull, SceneColours::drawn};
    if (coloring == FaceColoring::CullFraction || coloring == FaceColoring::OracleFraction) return fractionLegendColours();
    if (!lodShown) return clusterLegendColours();
    if (coloring == FaceColoring::LodCut) return {SceneColours::cutDrawn, SceneColours::cutCoarser, SceneColours::cutFiner};
    if (coloring == FaceColoring::LodLevel) return {lodLevelColour(0), lodLevelColour(1), lodLevelColour(2), lodLevelColour(3)};
    return clusterLegendColours();
}

}  // namespace conescope
