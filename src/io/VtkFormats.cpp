// The VTK side of conescope_io, built into libconescope_vtk_formats.so (FormatModules.h): VTK's
// readers behind the checks of HeaderChecks.h, and VTK's writers, with VTK's messages captured.
#include "io/FormatModules.h"

#include <vtkAlgorithm.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "io/ClassicLocale.h"
#include "io/HeaderChecks.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"
#include "io/PolyDataConversion.h"
#include "io/VtkMessageCapture.h"

namespace conescope {

namespace {

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

Mesh readWithVtk(const std::string& path, const std::string& extension, std::vector<uint64_t>& exactKeys) {
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
        return meshFromPolyData(polyData, &exactKeys);
    } catch (const std::runtime_error& error) {
        throw MeshReadError(path + ": " + error.what());
    }
}

// Runs any VTK writer (the XML writers do not share vtkWriter's base) with its messages captured.
template <class Writer>
void runVtkWriter(Writer* writer, vtkPolyData* polyData, const std::string& path) {
    ScopedClassicNumericLocale classicNumbers;
    VtkMessageCapture capture;
    capture.watch(writer);
    capture.watch(writer->GetExecutive());
    writer->SetFileName(path.c_str());
    writer->SetInputData(polyData);
    int written = writer->Write();
    if (!written || capture.hasErrors()) {
        std::string reason = capture.summary();
        throw MeshWriteError(path + ": cannot write file" + (reason.empty() ? "" : " (" + reason + ")"));
    }
}

void writeWithVtk(const Mesh& mesh, const std::string& path, const std::string& extension) {
    vtkSmartPointer<vtkPolyData> polyData = polyDataFromMesh(mesh);
    if (extension == ".vtp") {
        vtkNew<vtkXMLPolyDataWriter> writer;
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();  // raw binary: smaller than base64, and exact
        return runVtkWriter(writer.Get(), polyData, path);
    }
    if (extension == ".vtk") {
        vtkNew<vtkPolyDataWriter> writer;
        writer->SetFileTypeToBinary();  // ASCII legacy output rounds floats
        return runVtkWriter(writer.Get(), polyData, path);
    }
    vtkNew<vtkPLYWriter> writer;
    writer->SetFileTypeToBinary();
    runVtkWriter(writer.Get(), polyData, path);
}

}  // namespace

extern "C" const VtkFormats* conescope_vtk_formats() {
    static const VtkFormats formats{readWithVtk, writeWithVtk};
    return &formats;
}

}  // namespace conescope
