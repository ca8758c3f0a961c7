#include "io/MeshReader.h"

#include <algorithm>
#include <new>
#include <vector>

#include "io/FileChecks.h"
#include "io/ObjFormat.h"
#include "io/OffFormat.h"
#include "io/PlyFormat.h"
#include "io/PositionMerging.h"
#include "io/FormatModules.h"

namespace conescope {

namespace {

struct MeshFormat {
    const char* extension;
    const char* filterLabel;
};

// Order is the order of the GUI's file filter.
const MeshFormat meshFormats[] = {
    {".off", "OFF"}, {".ply", "PLY"}, {".obj", "Wavefront OBJ"},
    {".stl", "STL"}, {".vtp", "VTK XML PolyData"}, {".vtk", "VTK legacy"},
    {".gltf", "glTF 2.0"}, {".glb", "glTF 2.0 binary"},
};

std::string supportedExtensionList() {
    std::string list;
    for (const MeshFormat& format : meshFormats) list += (list.empty() ? "" : " ") + std::string(format.extension);
    return list;
}

// What a reader gets besides the path: where to leave notes, whom to tell its progress, and where to
// keep the positions it read wider than float (PositionMerging.h).
struct ReadContext {
    std::vector<std::string>& notes;
    const ProgressCallback& progress;
    std::vector<uint64_t>& exactKeys;
};

Mesh readByExtension(const std::string& path, const std::string& extension, ReadContext& context) {
    if (extension == ".off") return readOff(path, &context.exactKeys);
    if (extension == ".obj") return readObj(path, context.notes, context.progress, &context.exactKeys);
    if (extension == ".ply") return readPly(path, context.notes, context.progress, &context.exactKeys);
    // glTF positions are float32 already.
    if (extension == ".gltf" || extension == ".glb") return gltfFormat().read(path, context.notes, context.progress);
    return vtkFormats().read(path, extension, context.exactKeys);
}

// What every mesh goes through after its reader: at least one face, validateMesh, and vertices at equal
// positions merged. `cornersPerFace`: the format stores a corner per face, so merging is no news; a
// position lost to rounding always is.
void finishMesh(MeshFile& file, const std::string& path, bool cornersPerFace, const std::vector<uint64_t>& exactKeys) {
    Mesh& mesh = file.mesh;
    if (mesh.faceCount() == 0) throw MeshReadError(path + ": no faces");
    try {
        validateMesh(mesh);
    } catch (const std::runtime_error& error) {
        throw MeshReadError(path + ": " + error.what());
    }
    // Clusters never cross components, so vertices a file splits at one position (at normal or
    // texture seams, or a corner per face as STL and glTF store them) would cut the surface apart
    // and make every builder look perfect. Vertices are positions, as OBJ's `v` entries are.
    const size_t vertices = mesh.positions.size();
    const MergedPositions merge = mergeEqualPositions(mesh, exactKeys);
    const size_t sameInFile = merge.merged - merge.lostPositions;
    if (sameInFile > 0 && !cornersPerFace)
        file.notes.push_back("merged " + std::to_string(sameInFile) + " vertices into others at the same position (the file splits "
                             "them, e.g. at normal or texture seams), so faces meeting there are neighbours");
    if (merge.lostPositions > 0) file.notes.push_back(lostPositionsWarning(mesh, vertices, merge));
}

}  // namespace

Mesh readMesh(const std::string& path) { return readMeshFile(path).mesh; }

MeshFile readMeshFile(const std::string& path, const ProgressCallback& progress) {
    std::string extension = lowerCaseExtension(path);
    if (!hasSupportedMeshExtension(path))
        throw MeshReadError(path + ": unsupported file extension " +
                            (extension.empty() ? std::string("(none)") : quotedForMessage(extension)) +
                            "; supported: " + supportedExtensionList());
    requireReadableFile(path);
    MeshFile file;
    Mesh& mesh = file.mesh;
    std::vector<uint64_t> exactKeys;
    ReadContext context{file.notes, progress, exactKeys};
    try {
        mesh = readByExtension(path, extension, context);
    } catch (const MeshReadError&) {
        throw;
    } catch (const OperationCancelled&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw MeshReadError(path + ": out of memory while reading (corrupt counts or a very large file)");
    } catch (const std::exception& error) {
        throw MeshReadError(path + ": " + error.what());
    }
    finishMesh(file, path, extension == ".stl" || extension == ".gltf" || extension == ".glb", exactKeys);
    return file;
}

MeshFile meshFromArrays(Mesh mesh, const std::string& name, const std::vector<glm::dvec3>& exactPositions) {
    std::vector<uint64_t> exactKeys;
    if (exactPositions.size() == mesh.positions.size())
        for (const glm::dvec3& position : exactPositions) addExactPosition(&exactKeys, position);
    MeshFile file{std::move(mesh), {}};
    finishMesh(file, name, false, exactKeys);
    return file;
}

std::vector<std::string> supportedMeshExtensions() {
    std::vector<std::string> extensions;
    for (const MeshFormat& format : meshFormats) extensions.push_back(format.extension);
    return extensions;
}

bool hasSupportedMeshExtension(const std::string& path) {
    std::string extension = lowerCaseExtension(path);
    return std::any_of(std::begin(meshFormats), std::end(meshFormats),
                       [&](const MeshFormat& format) { return extension == format.extension; });
}

std::string meshFileFilter() {
    std::string all, each;
    for (const MeshFormat& format : meshFormats) {
        std::string pattern = std::string("*") + format.extension;
        all += (all.empty() ? "" : " ") + pattern;
        each += std::string(";;") + format.filterLabel + " (" + pattern + ")";
    }
    return "Meshes (" + all + ")" + each + ";;All files (*)";
}

}  // namespace conescope
