// What every layer of a ClusterScene reads and none owns: the mesh polydata with its per-face arrays,
// the partition's bounds, the cluster palette and the lookup tables. ClusterScene holds it once and
// hands the layers a const reference. Only the scene rewrites the tables' decision entries, and only the
// faces layer the mesh's facing array.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include "core/ClusterBounds.h"
#include "core/Mesh.h"
#include "core/Partition.h"
#include "scene/ClusterTables.h"

namespace conescope {

// Segments of the cone and sphere glyphs (the layers' and the picked cluster's alike).
constexpr int coneSegments = 32;
constexpr int sphereSegments = 24;

// Throws std::invalid_argument unless world and faces come from mesh, partition covers its faces with
// ids below its cluster count and bounds has one entry per cluster.
void checkSceneInput(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                     const Partition& partition, const ClusterBounds& bounds);

struct SceneData {
    // Arguments as checkSceneInput accepts them; copies what it keeps, they may go away afterwards.
    SceneData(const Mesh& mesh, const std::vector<glm::vec3>& world, const Partition& partition, const ClusterBounds& bounds);
    // The layers and the tables keep references into it.
    SceneData(const SceneData&) = delete;
    SceneData& operator=(const SceneData&) = delete;

    // Radius of the mesh's bounding sphere, never zero: the scale of markers and fallbacks.
    double sceneRadius() const { return std::max(double(worldBox.halfDiagonal()), 1e-12); }
    // Slant length of a cone glyph around a zero-radius sphere.
    double coneFallbackLength() const { return std::max(meanEdge, 1e-6 * sceneRadius()); }

    Mesh mesh;  // faces only (positions are in `points`, world space)
    std::vector<uint32_t> clusterOfFace;
    ClusterBounds bounds;
    std::vector<Rgb> palette;
    Aabb worldBox;
    double meanEdge = 0.0;

    vtkSmartPointer<vtkPoints> points;       // world positions, shared by the mesh, the borders and the outline
    vtkSmartPointer<vtkPolyData> meshData;   // one polygon per face; cell arrays cluster_id, facing, loss and comparison
    vtkSmartPointer<vtkUnsignedCharArray> facing;  // meshData's "facing" array
    vtkSmartPointer<vtkUnsignedCharArray> loss;    // meshData's "loss" array
    vtkSmartPointer<vtkUnsignedCharArray> comparison;  // meshData's "comparison" array
    vtkSmartPointer<vtkUnsignedCharArray> subGroup;    // meshData's "sub_group" array, RGB
    ClusterTables tables;
};

}  // namespace conescope
