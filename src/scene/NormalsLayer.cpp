#include "scene/NormalsLayer.h"

#include <algorithm>

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3D.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>

#include "scene/SceneGeometry.h"

namespace conescope {

namespace {

// Every stride-th non-degenerate face: its centroid as a point, its normal as the point's vector.
vtkSmartPointer<vtkPolyData> faceCentroids(const FaceGeometry& faces, const Partition& partition) {
    const size_t faceCount = partition.clusterOfFace.size();
    const size_t stride = std::max<size_t>(1, (faceCount + maxNormalArrows - 1) / maxNormalArrows);
    std::vector<glm::vec3> centroids;
    auto directions = vtkSmartPointer<vtkFloatArray>::New();
    directions->SetName("normal");
    directions->SetNumberOfComponents(3);
    auto clusterIds = vtkSmartPointer<vtkIntArray>::New();
    clusterIds->SetName(clusterIdArrayName);
    for (size_t f = 0; f < faceCount; f += stride) {
        if (faces.degenerate.size() == faceCount && faces.degenerate[f]) continue;
        centroids.push_back(glm::vec3(faces.centroids[f]));
        const glm::vec3 normal(faces.normals[f]);
        directions->InsertNextTuple3(normal.x, normal.y, normal.z);
        clusterIds->InsertNextValue(int(partition.clusterOfFace[f]));
    }
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(pointsFrom(centroids));
    polyData->GetPointData()->SetVectors(directions);
    polyData->GetPointData()->AddArray(clusterIds);
    return polyData;
}

}  // namespace

NormalsLayer::NormalsLayer(const SceneData& data, const FaceGeometry& faces, const Partition& partition)
    : SceneLayer(data), centroids_(faceCentroids(faces, partition)), arrows_(vtkSmartPointer<vtkGlyph3D>::New()) {
    auto arrow = vtkSmartPointer<vtkArrowSource>::New();
    arrow->SetTipResolution(6);
    arrow->SetShaftResolution(4);
    arrows_->SetInputData(centroids_);
    arrows_->SetSourceConnection(arrow->GetOutputPort());
    arrows_->SetVectorModeToUseVector();
    arrows_->OrientOn();
    arrows_->SetScaleModeToDataScalingOff();
    arrows_->SetScaleFactor(0.6 * (data.meanEdge > 0 ? data.meanEdge : data.sceneRadius() * 0.05));
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(arrows_->GetOutputPort());
    mapper->ScalarVisibilityOff();
    actor_ = actorFor(mapper);
    setColour(actor_, SceneColours::normals);
}

void NormalsLayer::addLegendEntries(FaceColoring, std::vector<LegendEntry>& entries) const {
    entries.push_back({"face normals", {SceneColours::normals}});
}

}  // namespace conescope
