#include "io/MeshReader.h"

#include <algorithm>
#include <new>
#include <vector>

#include <vtkAlgorithm.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include "io/ClassicLocale.h"
#include "io/FileChecks.h"
#include "io/GltfReader.h"
#include "io/HeaderChecks.h"
#include "io/ObjFormat.h"
#include "io/OffFormat.h"
#include "io/PlyFormat.h"
#include "io/PolyDataConversion.h"
#include "io/PositionMerging.h"
#include "io/VtkMessageCapture.h"

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

// The reader for a VTK-handled extension, pointed at the file (for .vtp, at its patched text), after
// the structural checks of HeaderChecks.h: VTK 9.1's readers trust their input and crash on some
// damaged files, so each file is checked before VTK sees it.
vtkSmartPointer<vtkAlgorithm> makeVtkReader(const std::string& path, const std::string& extension) {
    if (extension == ".stl") {
        checkStlFile(path);
        vtkSmartPointer<vtkSTLReader> reader = vtkSmartPointer<vtkSTLReader>::New();
        reader->SetFileName(path.c_str());
        // Its merging drops every triangle two of whose corners merge; mergeEqualPositions merges
        // instead and keeps them (see there).
        reader->MergingOff();
        return reader;
    }
    if (extension == ".vtp") {
        vtkSmartPointer<vtkXMLPolyDataReader> reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
        if (!reader->CanReadFile(path.c_str())) throw MeshReadError(path + ": not a VTK XML PolyData (.vtp) file");
        reader->SetInputString(prepareVtpForVtk(path));
        reader->ReadFromInputStringOn();
        return reader;
    }
    // .vtk: the legacy format holds any dataset type; we only take polygonal data.
    vtkSmartPointer<vtkPolyDataReader> reader = vtkSmartPointer<vtkPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    if (!reader->IsFilePolyData()) throw MeshReadError(path + ": not a legacy VTK file with POLYDATA");
    checkLegacyVtkFile(path);
    return reader;
}

std::string describeFailure(const VtkMessageCapture& capture, vtkAlgorithm* reader) {
    std::string messages = capture.summary();
    if (!messages.empty()) return messages;
    unsigned long code = reader ? reader->GetErrorCode() : static_cast<unsigned long>(vtkErrorCode::NoError);
    if (code != vtkErrorCode::NoError) return vtkErrorCode::GetStringFromErrorCode(code);
    return "the VTK reader failed without a message";
}

Mesh readWithVtk(const std::string& path, const std::string& extension) {
    ScopedClassicNumericLocale classicNumbers;
    VtkMessageCapture capture;
    vtkSmartPointer<vtkAlgorithm> reader = makeVtkReader(path, extension);
    if (capture.hasErrors()) throw MeshReadError(path + ": " + describeFailure(capture, reader));
    capture.watch(reader);
    capture.watch(reader->GetExecutive());
    reader->Update();
    if (capture.hasErrors() || reader->GetErrorCode() != vtkErrorCode::NoError)
        throw MeshReadError(path + ": " + describeFailure(capture, reader));
    vtkPolyData* polyData = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
    if (!polyData || polyData->GetNumberOfPoints() == 0) {
        std::string warnings = capture.summary();
        throw MeshReadError(path + ": no points" + (warnings.empty() ? "" : " (" + warnings + ")"));
    }
    if (polyData->GetNumberOfPolys() + polyData->GetNumberOfStrips() == 0)
        throw MeshReadError(path + ": no faces (" + std::to_string(polyData->GetNumberOfPoints()) + " points, " +
                            std::to_string(polyData->GetNumberOfLines()) + " lines, no polygons)");
    try {
        return meshFromPolyData(polyData);
    } catch (const std::runtime_error& error) {
        throw MeshReadError(path + ": " + error.what());
    }
}

// What a reader gets besides the path: where to leave notes and whom to tell its progress.
struct ReadContext {
    std::vector<std::string>& notes;
    const ProgressCallback& progress;
};

Mesh readByExtension(const std::string& path, const std::string& extension, ReadContext& context) {
    if (extension == ".off") return readOff(path);
    if (extension == ".obj") return readObj(path, context.notes, context.progress);
    if (extension == ".ply") return readPly(path, context.notes, context.progress);
    if (extension == ".gltf" || extension == ".glb") return readGltf(path, context.notes, context.progress);
    return readWithVtk(path, extension);
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
    ReadContext context{file.notes, progress};
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
    if (mesh.faceCount() == 0) throw MeshReadError(path + ": no faces");
    try {
        validateMesh(mesh);
    } catch (const std::runtime_error& error) {
        throw MeshReadError(path + ": " + error.what());
    }
    // Clusters never cross components, so vertices a file splits at one position (at normal or
    // texture seams, or a corner per face as STL and glTF store them) would cut the surface apart
    // and make every builder look perfect. Vertices are positions, as OBJ's `v` entries are.
    const size_t merged = mergeEqualPositions(mesh);
    const bool cornersPerFace = extension == ".stl" || extension == ".gltf" || extension == ".glb";
    if (merged > 0 && !cornersPerFace)
        file.notes.push_back("merged " + std::to_string(merged) + " vertices into others at the same position (the file splits "
                             "them, e.g. at normal or texture seams), so faces meeting there are neighbours");
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
