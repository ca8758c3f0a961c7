// Mesh <-> vtkPolyData. Separate from MeshReader.h so code that only reads files needs no VTK headers.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/Mesh.h"

class vtkPolyData;

namespace conescope {

// Name of the field-data array (16 doubles, column-major like glm) that carries Mesh::model through
// VTK files; written only when the model matrix is not the identity.
inline const char* const modelMatrixArrayName = "model_matrix";

// Polygons become faces as they are; triangle strips are split into triangles (dropping the
// zero-area joints that repeat a point); vertices and lines are ignored. Every named 1-component
// numeric cell-data array (e.g. "cluster_id") is copied into faceArrays, following the faces
// (a strip's value goes to each of its triangles). Does not call validateMesh. Throws
// std::runtime_error if a point id is negative or does not fit 32 bits. polyData may be null
// (gives an empty mesh). Points wider than float leave a key each in `exactKeys` when given
// (PositionMerging.h).
Mesh meshFromPolyData(vtkPolyData* polyData, std::vector<uint64_t>* exactKeys = nullptr);

// Float points, one polygon cell per face, every faceArray as cell data (integer-valued arrays as
// vtkIntArray, so ParaView treats cluster ids as categories; others as vtkDoubleArray), and the model
// matrix as field data when it is not the identity.
vtkSmartPointer<vtkPolyData> polyDataFromMesh(const Mesh& mesh);

}  // namespace conescope
