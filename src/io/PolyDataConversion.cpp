#include "io/PolyDataConversion.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "io/PositionMerging.h"

namespace conescope {

namespace {

uint32_t checkedPointIndex(vtkIdType id) {
    if (id < 0 || static_cast<uint64_t>(id) > std::numeric_limits<uint32_t>::max())
        throw std::runtime_error("cell uses point id " + std::to_string(id) + ", outside the 32-bit index range");
    return static_cast<uint32_t>(id);
}

// For every face of the mesh, the vtkPolyData cell it came from (cell ids run verts, lines,
// polys, strips), so per-cell arrays can be carried over face by face.
using SourceCells = std::vector<vtkIdType>;

// Calls visit(cellIndex, size, points) for each cell of `cells` (may be null), in order.
template <typename Visit>
void forEachCell(vtkCellArray* cells, Visit visit) {
    if (!cells) return;
    vtkSmartPointer<vtkCellArrayIterator> cell = vtk::TakeSmartPointer(cells->NewIterator());
    vtkIdType cellIndex = 0;
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell(), ++cellIndex) {
        vtkIdType size = 0;
        const vtkIdType* points = nullptr;
        cell->GetCurrentCell(size, points);
        visit(cellIndex, size, points);
    }
}

void appendPolygons(vtkPolyData* polyData, Mesh& mesh, SourceCells& sourceCells) {
    const vtkIdType firstCell = polyData->GetNumberOfVerts() + polyData->GetNumberOfLines();
    std::vector<uint32_t> face;
    forEachCell(polyData->GetPolys(), [&](vtkIdType cellIndex, vtkIdType size, const vtkIdType* points) {
        face.clear();
        for (vtkIdType k = 0; k < size; ++k) face.push_back(checkedPointIndex(points[k]));
        // Faces with < 3 points are kept so validateMesh reports them instead of hiding file damage.
        mesh.addFace(face.data(), face.size());
        sourceCells.push_back(firstCell + cellIndex);
    });
}

// Strip (p0 p1 p2 p3 ...) has triangles (p0 p1 p2), (p2 p1 p3), (p2 p3 p4), ...: every odd
// triangle swaps its first two points so all keep the strip's orientation.
void appendStripTriangles(vtkPolyData* polyData, Mesh& mesh, SourceCells& sourceCells) {
    const vtkIdType firstCell = polyData->GetNumberOfVerts() + polyData->GetNumberOfLines() + polyData->GetNumberOfPolys();
    forEachCell(polyData->GetStrips(), [&](vtkIdType cellIndex, vtkIdType size, const vtkIdType* points) {
        for (vtkIdType k = 0; k + 2 < size; ++k) {
            uint32_t a = checkedPointIndex(points[k]), b = checkedPointIndex(points[k + 1]),
                     c = checkedPointIndex(points[k + 2]);
            if (a == b || b == c || a == c) continue;  // stitching triangle between strip runs
            if (k % 2 == 0)
                mesh.addFace({a, b, c});
            else
                mesh.addFace({b, a, c});
            sourceCells.push_back(firstCell + cellIndex);
        }
    });
}

void copyFaceArrays(vtkPolyData* polyData, const SourceCells& sourceCells, Mesh& mesh) {
    vtkCellData* cellData = polyData->GetCellData();
    if (!cellData) return;
    for (int i = 0; i < cellData->GetNumberOfArrays(); ++i) {
        vtkDataArray* array = cellData->GetArray(i);  // null for string and other non-numeric arrays
        if (!array || array->GetNumberOfComponents() != 1 || !array->GetName() || !*array->GetName()) continue;
        if (array->GetNumberOfTuples() != polyData->GetNumberOfCells()) continue;
        std::vector<double> values(sourceCells.size());
        for (size_t face = 0; face < sourceCells.size(); ++face) values[face] = array->GetTuple1(sourceCells[face]);
        mesh.faceArrays[array->GetName()] = std::move(values);
    }
}

void readModelMatrix(vtkPolyData* polyData, Mesh& mesh) {
    vtkFieldData* fieldData = polyData->GetFieldData();
    vtkDataArray* array = fieldData ? fieldData->GetArray(modelMatrixArrayName) : nullptr;
    if (!array || array->GetNumberOfValues() != 16) return;
    // 16 values as one 16-component tuple (what we write) or as 16 single values.
    int components = array->GetNumberOfComponents();
    for (int index = 0; index < 16; ++index)
        mesh.model[index / 4][index % 4] = array->GetComponent(index / components, index % components);
}

bool isIntegerValued(const std::vector<double>& values) {
    for (double value : values)
        if (!(std::trunc(value) == value && std::abs(value) <= std::numeric_limits<int>::max())) return false;
    return true;
}

vtkSmartPointer<vtkDataArray> cellArrayFromValues(const std::string& name, const std::vector<double>& values) {
    vtkSmartPointer<vtkDataArray> array;
    if (isIntegerValued(values))
        array = vtkSmartPointer<vtkIntArray>::New();
    else
        array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    array->SetNumberOfComponents(1);
    array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
    for (size_t i = 0; i < values.size(); ++i) array->SetTuple1(static_cast<vtkIdType>(i), values[i]);
    return array;
}

}  // namespace

Mesh meshFromPolyData(vtkPolyData* polyData, std::vector<uint64_t>* exactKeys) {
    Mesh mesh;
    if (!polyData) return mesh;
    vtkPoints* points = polyData->GetPoints();
    vtkIdType pointCount = points ? points->GetNumberOfPoints() : 0;
    if (static_cast<uint64_t>(pointCount) > std::numeric_limits<uint32_t>::max())
        throw std::runtime_error(std::to_string(pointCount) + " points exceed the 32-bit index range");
    // Float points lose nothing to rounding: only wider ones need their keys.
    if (points && points->GetDataType() == VTK_FLOAT) exactKeys = nullptr;
    mesh.positions.resize(static_cast<size_t>(pointCount));
    for (vtkIdType i = 0; i < pointCount; ++i) {
        double point[3];
        points->GetPoint(i, point);
        const glm::dvec3 position(point[0], point[1], point[2]);
        mesh.positions[static_cast<size_t>(i)] = glm::vec3(position);
        addExactPosition(exactKeys, position);
    }
    SourceCells sourceCells;
    appendPolygons(polyData, mesh, sourceCells);
    appendStripTriangles(polyData, mesh, sourceCells);
    copyFaceArrays(polyData, sourceCells, mesh);
    readModelMatrix(polyData, mesh);
    return mesh;
}

vtkSmartPointer<vtkPolyData> polyDataFromMesh(const Mesh& mesh) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.positions.size()));
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
    }
    vtkNew<vtkCellArray> polygons;
    polygons->AllocateExact(static_cast<vtkIdType>(mesh.faceCount()), static_cast<vtkIdType>(mesh.faceVertices.size()));
    std::vector<vtkIdType> face;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        face.assign(mesh.faceBegin(f), mesh.faceBegin(f) + mesh.faceSize(f));
        polygons->InsertNextCell(static_cast<vtkIdType>(face.size()), face.data());
    }
    vtkSmartPointer<vtkPolyData> polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetPolys(polygons);
    for (const auto& [name, values] : mesh.faceArrays) polyData->GetCellData()->AddArray(cellArrayFromValues(name, values));
    if (mesh.model != glm::dmat4(1.0)) {
        vtkNew<vtkDoubleArray> model;
        model->SetName(modelMatrixArrayName);
        model->SetNumberOfComponents(16);
        model->SetNumberOfTuples(1);
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) model->SetComponent(0, column * 4 + row, mesh.model[column][row]);
        polyData->GetFieldData()->AddArray(model);
    }
    return polyData;
}

}  // namespace conescope
