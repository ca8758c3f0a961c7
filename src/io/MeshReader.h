// Reading meshes from files. Free of VTK types so the CLI, the file builder and tests can use it
// without pulling VTK headers in; VTK is an implementation detail of conescope_io.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/Mesh.h"
#include "core/Progress.h"

namespace conescope {

// Thrown for every file that cannot be turned into a valid Mesh: missing, unreadable, unknown
// extension, malformed, empty ("no faces"), or failing validateMesh. what() always starts with the
// file path, then for OFF the 1-based line ("path:line: what"), then what is wrong.
class MeshReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads .off .obj .ply (own parsers), .stl .vtp .vtk (VTK readers), .gltf .glb (GltfReader.h: the
// default scene in world space, vertices merged by position), choosing by the extension,
// case-insensitively. The result has at least one face and has passed validateMesh; its model
// matrix is the identity unless the file stored one (see PolyDataConversion.h). Per-face scalar
// arrays of VTK files and a PLY face property cluster_id land in Mesh::faceArrays. VTK's own messages are
// captured into the exception instead of being printed. Throws MeshReadError.
Mesh readMesh(const std::string& path);

// A mesh with what its reader noticed but did not refuse, for the user to see: parts that are not
// faces (points, lines) and were skipped, encodings converted, and the like; and, starting with
// "Warning: ", positions the file holds apart that rounding to float32 merged (coordinates far from
// the origin for the mesh's size). One sentence each.
struct MeshFile {
    Mesh mesh;
    std::vector<std::string> notes;
};

// readMesh with the reader's notes. Readers of formats that can be large report progress through
// `progress`; when it returns false the read stops with OperationCancelled (core/Progress.h).
MeshFile readMeshFile(const std::string& path, const ProgressCallback& progress = {});

// A mesh made in memory (the Python module's arrays) checked and merged as readMeshFile does a file's
// mesh after its reader, so the same faces give the same numbers. `name` starts the messages.
// `exactPositions`, the positions before they were rounded to float (one per vertex, when the caller
// had float64), let the notes warn of positions that rounding merged. Throws MeshReadError.
MeshFile meshFromArrays(Mesh mesh, const std::string& name, const std::vector<glm::dvec3>& exactPositions = {});

// Lower-case extensions readMesh accepts, with the dot: {".off", ".ply", ...}.
std::vector<std::string> supportedMeshExtensions();

// True when readMesh would try to read a file of this name (extension check only).
bool hasSupportedMeshExtension(const std::string& path);

// Qt file-dialog filter: "Meshes (*.off *.ply ...);;OFF (*.off);;...;;All files (*)".
std::string meshFileFilter();

}  // namespace conescope
