// Formats whose libraries are large, each in a module of its own that is opened the first time a
// file needs it: VTK (reading STL, VTP and legacy VTK; writing VTP, legacy VTK and PLY) in
// libconescope_vtk_formats.so, and assimp, which decodes glTF's data, in
// libconescope_gltf_format.so. Linking them cost every conescope-cli run their loading before main:
// about 10 ms for VTK's libraries and 1.5 ms for assimp's, more than all the work on a mesh of a
// few thousand triangles, for formats most runs never touch. Internal to conescope_io: MeshReader.h
// and MeshWriter.h are the interface.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/Mesh.h"
#include "core/Progress.h"

namespace conescope {

struct VtkFormats {
    // A mesh from an .stl, .vtp or .vtk file, after the checks of HeaderChecks.h; throws
    // MeshReadError naming the file. Points stored wider than float leave their keys in `exactKeys`
    // (PositionMerging.h).
    Mesh (*read)(const std::string& path, const std::string& extension, std::vector<uint64_t>& exactKeys);
    // Writes .vtp, .vtk or .ply; throws MeshWriteError naming the file.
    void (*write)(const Mesh& mesh, const std::string& path, const std::string& extension);
};

struct GltfFormat {
    // readGltf (GltfReader.h).
    Mesh (*read)(const std::string& path, std::vector<std::string>& notes, const ProgressCallback& progress);
};

// The modules' formats, each opened on first use (next to the executable, in ../lib/conescope, or
// where the build made it). Throw std::runtime_error saying where they looked when they cannot.
const VtkFormats& vtkFormats();
const GltfFormat& gltfFormat();

// The modules' entry points.
extern "C" const VtkFormats* conescope_vtk_formats();
extern "C" const GltfFormat* conescope_gltf_format();

}  // namespace conescope
