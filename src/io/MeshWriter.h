// Writing meshes, mainly to export a partition (a "cluster_id" per face) for ParaView or for
// reading back. Free of VTK types like MeshReader.h.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/Mesh.h"

namespace conescope {

// Thrown when a mesh cannot be written: invalid mesh, bad extra array, unsupported extension,
// or an I/O failure. what() starts with the file path.
class MeshWriteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Text OFF that readMesh reads back exactly (shortest round-trip float formatting, independent of
// the C locale). OFF stores neither per-face arrays nor the model matrix: positions are written in
// model space. Throws MeshWriteError.
void writeOff(const Mesh& mesh, const std::string& path);

// Writes by extension (case-insensitive):
//   .vtp  VTK XML PolyData (binary, compressed)  - faceArrays and extraFaceArrays as cell data,
//   .vtk  VTK legacy binary                      - the same,
//         both keep a non-identity model matrix as field data "model_matrix" (see
//         PolyDataConversion.h), so readMesh gives back the same Mesh,
//   .ply  binary PLY                              - geometry only,
//   .off  as writeOff                             - geometry only.
// extraFaceArrays (e.g. {"cluster_id", ...}) are added to the mesh's own faceArrays, replacing any of
// the same name; each must have one value per face. Throws MeshWriteError.
void writePolyData(const Mesh& mesh, const std::string& path,
                   const std::map<std::string, std::vector<double>>& extraFaceArrays = {});

// Lower-case extensions writePolyData accepts: {".vtp", ".vtk", ".ply", ".off"}.
std::vector<std::string> writableMeshExtensions();

}  // namespace conescope
