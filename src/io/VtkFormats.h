// The formats read and written through VTK (reading STL, VTP and legacy VTK; writing VTP, legacy
// VTK and PLY), in a module of their own, libconescope_vtk_formats.so, opened the first time a
// file needs it. Linking VTK cost every conescope-cli run about 10 ms of loading and relocating its
// libraries before main (more than all the work on a mesh of a few thousand triangles), for
// formats most runs never touch. Internal to conescope_io: MeshReader.h and MeshWriter.h are the
// interface.
#pragma once

#include <string>

#include "core/Mesh.h"

namespace conescope {

struct VtkFormats {
    // A mesh from an .stl, .vtp or .vtk file, after the checks of HeaderChecks.h; throws
    // MeshReadError naming the file.
    Mesh (*read)(const std::string& path, const std::string& extension);
    // Writes .vtp, .vtk or .ply; throws MeshWriteError naming the file.
    void (*write)(const Mesh& mesh, const std::string& path, const std::string& extension);
};

// The module's formats, opened on first use (next to the executable, in ../lib/conescope, or where
// the build made it). Throws std::runtime_error saying where it looked when it cannot be opened.
const VtkFormats& vtkFormats();

// The module's entry point.
extern "C" const VtkFormats* conescope_vtk_formats();

}  // namespace conescope
