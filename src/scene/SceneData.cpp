#include "scene/SceneData.h"

#include <stdexcept>

#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include "scene/SceneGeometry.h"

namespace conescope {

void checkSceneInput(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                     const Partition& partition, const ClusterBounds& bounds) {
    const size_t faceCount = mesh.faceCount();
    if (world.size() != mesh.positions.size() || faces.normals.size() != faceCount ||
        faces.centroids.size() != faceCount || partition.clusterOfFace.size() != faceCount ||
        bounds.count() != partition.clusterCount || bounds.spheres.size() != bounds.count() ||
        bounds.boxes.size() != bounds.count() || bounds.faces.starts.size() != size_t(partition.clusterCount) + 1)
        throw std::invalid_argument("ClusterScene: mesh, world positions, face geometry, partition and cluster bounds do not match");
    for (uint32_t cluster : partition.clusterOfFace)
        if (cluster >= partition.clusterCount) throw std::invalid_argument("ClusterScene: a face has a cluster id out of range");
}

SceneData::SceneData(const Mesh& mesh, const std::vector<glm::vec3>& world, const Partition& partition,
                     const ClusterBounds& bounds)
    : clusterOfFace(partition.clusterOfFace), bounds(bounds), palette(clusterPalette(clusterAdjacency(mesh, partition))),
      worldBox(computeAabb(world)), meanEdge(meanEdgeLength(mesh, world)), points(pointsFrom(world)),
      meshData(meshPolyData(mesh, points, partition)), facing(vtkSmartPointer<vtkUnsignedCharArray>::New()),
      loss(vtkSmartPointer<vtkUnsignedCharArray>::New()), comparison(vtkSmartPointer<vtkUnsignedCharArray>::New()),
      subGroup(vtkSmartPointer<vtkUnsignedCharArray>::New()),
      tables(palette) {
    this->mesh.faceStarts = mesh.faceStarts;
    this->mesh.faceVertices = mesh.faceVertices;
    facing->SetName(facingArrayName);
    facing->SetNumberOfTuples(vtkIdType(mesh.faceCount()));
    facing->FillValue(3);
    meshData->GetCellData()->AddArray(facing);
    loss->SetName(lossArrayName);
    loss->SetNumberOfTuples(vtkIdType(mesh.faceCount()));
    loss->FillValue(4);
    meshData->GetCellData()->AddArray(loss);
    comparison->SetName(comparisonArrayName);
    comparison->SetNumberOfTuples(vtkIdType(mesh.faceCount()));
    comparison->FillValue(4);
    meshData->GetCellData()->AddArray(comparison);
    subGroup->SetName(subGroupArrayName);
    subGroup->SetNumberOfComponents(3);
    subGroup->SetNumberOfTuples(vtkIdType(mesh.faceCount()));
    subGroup->FillValue(204);  // SceneColours::undecided until sub-groups are set
    meshData->GetCellData()->AddArray(subGroup);
}

}  // namespace conescope
