// Good files in every format: counts, face sizes, orientation and per-face arrays come through.
#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include "IoTestSupport.h"
#include "core/MeshChecks.h"
#include "io/MeshReader.h"
#include "io/PolyDataConversion.h"

namespace conescope {
namespace {

using testing::faceNearest;
using testing::formatSamplesDir;
using testing::unitFaceNormal;

struct CubeSample {
    const char* file;
    size_t vertexCount;
    size_t faceCount;
    size_t verticesPerFace;
    bool hasClusterIds;
};

std::string sampleName(const ::testing::TestParamInfo<CubeSample>& info) {
    std::string name = info.param.file;
    std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

// Names the file in test listings instead of dumping the struct's bytes.
void PrintTo(const CubeSample& sample, std::ostream* out) { *out << sample.file; }

class CubeInEveryFormat : public ::testing::TestWithParam<CubeSample> {};

TEST_P(CubeInEveryFormat, HasTheCubesCountsAndOutwardNormals) {
    const CubeSample& sample = GetParam();
    Mesh mesh = readMesh((formatSamplesDir() / sample.file).string());
    EXPECT_EQ(mesh.positions.size(), sample.vertexCount);
    ASSERT_EQ(mesh.faceCount(), sample.faceCount);
    for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_EQ(mesh.faceSize(f), sample.verticesPerFace) << "face " << f;
    EXPECT_EQ(mesh.model, glm::dmat4(1.0));

    // The cube is centred on the origin, so an outward normal points the same way as the face centre.
    size_t top = faceNearest(mesh, {0.0, 0.0, 0.5});
    glm::dvec3 topNormal = unitFaceNormal(mesh, top);
    EXPECT_NEAR(topNormal.x, 0.0, 1e-9);
    EXPECT_NEAR(topNormal.y, 0.0, 1e-9);
    EXPECT_NEAR(topNormal.z, 1.0, 1e-9);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        glm::dvec3 anyVertex(mesh.positions[mesh.faceBegin(f)[0]]);
        EXPECT_GT(glm::dot(unitFaceNormal(mesh, f), anyVertex), 0.0) << "face " << f << " points inward";
    }

    if (sample.hasClusterIds) {
        ASSERT_EQ(mesh.faceArrays.count("cluster_id"), 1u);
        EXPECT_EQ(mesh.faceArrays.at("cluster_id"), (std::vector<double>{0, 0, 1, 1, 2, 2}));
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, CubeInEveryFormat,
                         ::testing::Values(CubeSample{"cube.ply", 8, 6, 4, false},
                                           CubeSample{"cube-binary.ply", 8, 12, 3, false},
                                           CubeSample{"cube.obj", 8, 6, 4, false},
                                           CubeSample{"cube-textured.obj", 8, 6, 4, false},
                                           CubeSample{"cube-ascii.stl", 8, 12, 3, false},
                                           CubeSample{"cube-binary.stl", 8, 12, 3, false},
                                           CubeSample{"cube.vtp", 8, 6, 4, true},
                                           CubeSample{"cube.vtk", 8, 6, 4, true}),
                         sampleName);

TEST(ReadMesh, ReadsEveryFormatUnderACommaDecimalLocale) {
    // Only the C++ part is exercised where no de_DE locale is installed (LOCPATH can supply one).
    testing::ScopedCommaDecimalLocale german;
    for (const char* file : {"cube.ply", "cube-binary.ply", "cube.obj", "cube-ascii.stl", "cube-binary.stl", "cube.vtp", "cube.vtk"}) {
        Mesh mesh = readMesh((formatSamplesDir() / file).string());
        for (const glm::vec3& p : mesh.positions)
            for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(std::abs(p[axis]), 0.5f) << file;
    }
}

TEST(ReadMesh, SkipsCellArraysWithSeveralComponents) {
    // cube.vtp also has a 3-component "face_normal" cell array; faceArrays holds scalars only.
    Mesh mesh = readMesh((formatSamplesDir() / "cube.vtp").string());
    EXPECT_EQ(mesh.faceArrays.count("face_normal"), 0u);
}

TEST(ReadMesh, SplitsTriangleStripsKeepingOrientationAndCellData) {
    Mesh mesh = readMesh((formatSamplesDir() / "cube-strips.vtk").string());
    ASSERT_EQ(mesh.faceCount(), 2u + 8u);  // two quad caps, then eight strip triangles
    EXPECT_EQ(mesh.faceSize(0), 4u);
    EXPECT_EQ(mesh.faceSize(2), 3u);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        glm::dvec3 anyVertex(mesh.positions[mesh.faceBegin(f)[0]]);
        EXPECT_GT(glm::dot(unitFaceNormal(mesh, f), anyVertex), 0.0) << "face " << f << " points inward";
    }
    ASSERT_EQ(mesh.faceArrays.count("part"), 1u);
    EXPECT_EQ(mesh.faceArrays.at("part"), (std::vector<double>{0, 0, 1, 1, 1, 1, 1, 1, 1, 1}));
}

TEST(ReadMesh, ExtensionIsCaseInsensitive) {
    testing::ScratchDirectory scratch;
    std::filesystem::copy_file(formatSamplesDir() / "cube.ply", scratch.path() / "CUBE.PLY");
    std::filesystem::copy_file(testing::datasetsDir() / "cube.off", scratch.path() / "Cube.Off");
    EXPECT_EQ(readMesh(scratch.file("CUBE.PLY")).faceCount(), 6u);
    EXPECT_EQ(readMesh(scratch.file("Cube.Off")).faceCount(), 12u);
}

TEST(ReadMesh, ReadsAClusterIdArrayFromTheBundledVtp) {
    Mesh mesh = readMesh((testing::datasetsDir() / "icosphere-clusters.vtp").string());
    EXPECT_EQ(mesh.positions.size(), 162u);
    ASSERT_EQ(mesh.faceCount(), 320u);
    ASSERT_EQ(mesh.faceArrays.count("cluster_id"), 1u);
    const std::vector<double>& clusterIds = mesh.faceArrays.at("cluster_id");
    std::set<double> distinct(clusterIds.begin(), clusterIds.end());
    EXPECT_EQ(distinct.size(), 20u);
    EXPECT_EQ(*distinct.begin(), 0.0);
    EXPECT_EQ(*distinct.rbegin(), 19.0);
}

TEST(SupportedFormats, ListsEveryReadableExtension) {
    std::vector<std::string> extensions = supportedMeshExtensions();
    for (const char* expected : {".off", ".ply", ".obj", ".stl", ".vtp", ".vtk", ".gltf", ".glb"})
        EXPECT_NE(std::find(extensions.begin(), extensions.end(), expected), extensions.end()) << expected;
    EXPECT_TRUE(hasSupportedMeshExtension("/some/where/Model.STL"));
    EXPECT_FALSE(hasSupportedMeshExtension("notes.txt"));
    EXPECT_FALSE(hasSupportedMeshExtension("no_extension"));
}

TEST(SupportedFormats, FileFilterIsQtStyle) {
    std::string filter = meshFileFilter();
    EXPECT_EQ(filter.rfind("Meshes (*.off *.ply *.obj *.stl *.vtp *.vtk *.gltf *.glb)", 0), 0u) << filter;
    EXPECT_NE(filter.find(";;OFF (*.off)"), std::string::npos) << filter;
    EXPECT_NE(filter.find(";;All files (*)"), std::string::npos) << filter;
}

// Direct conversion tests, without files.

vtkSmartPointer<vtkPolyData> squarePyramid() {
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    points->InsertNextPoint(1, 1, 0);
    points->InsertNextPoint(0, 1, 0);
    points->InsertNextPoint(0.5, 0.5, 1);
    vtkNew<vtkCellArray> polygons;
    vtkIdType base[] = {0, 3, 2, 1};
    polygons->InsertNextCell(4, base);
    for (vtkIdType k = 0; k < 4; ++k) {
        vtkIdType side[] = {k, (k + 1) % 4, 4};
        polygons->InsertNextCell(3, side);
    }
    vtkNew<vtkCellArray> vertices;  // a vertex cell before the polygons shifts the cell ids
    vtkIdType apex = 4;
    vertices->InsertNextCell(1, &apex);
    vtkSmartPointer<vtkPolyData> polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetVerts(vertices);
    polyData->SetPolys(polygons);
    vtkNew<vtkIntArray> clusterIds;
    clusterIds->SetName("cluster_id");
    for (int value : {-1, 10, 11, 11, 12, 12}) clusterIds->InsertNextValue(value);
    polyData->GetCellData()->AddArray(clusterIds);
    vtkNew<vtkStringArray> labels;  // not numeric: must be skipped, not crash
    labels->SetName("label");
    for (int i = 0; i < 6; ++i) labels->InsertNextValue("x");
    polyData->GetCellData()->AddArray(labels);
    return polyData;
}

TEST(PolyDataConversion, TakesPolygonsAndSkipsVertexCells) {
    Mesh mesh = meshFromPolyData(squarePyramid());
    EXPECT_EQ(mesh.positions.size(), 5u);
    ASSERT_EQ(mesh.faceCount(), 5u);
    EXPECT_EQ(mesh.faceSize(0), 4u);
    EXPECT_EQ(mesh.faceArrays.at("cluster_id"), (std::vector<double>{10, 11, 11, 12, 12}));
    EXPECT_EQ(mesh.faceArrays.count("label"), 0u);
    EXPECT_NO_THROW(validateMesh(mesh));
}

TEST(PolyDataConversion, RoundTripsThroughPolyData) {
    Mesh original = meshFromPolyData(squarePyramid());
    original.faceArrays["weight"] = {0.5, 1.25, -3.0, 1e-9, 7.0};
    original.model = glm::dmat4(2.0);
    original.model[3] = glm::dvec4(1.0, 2.0, 3.0, 1.0);
    Mesh copy = meshFromPolyData(polyDataFromMesh(original));
    EXPECT_EQ(copy.positions, original.positions);
    EXPECT_EQ(copy.faceStarts, original.faceStarts);
    EXPECT_EQ(copy.faceVertices, original.faceVertices);
    EXPECT_EQ(copy.faceArrays, original.faceArrays);
    EXPECT_EQ(copy.model, original.model);
}

TEST(PolyDataConversion, IntegerArraysBecomeIntArraysOthersDouble) {
    Mesh mesh = meshFromPolyData(squarePyramid());
    mesh.faceArrays["weight"] = {0.5, 1, 2, 3, 4};
    vtkSmartPointer<vtkPolyData> polyData = polyDataFromMesh(mesh);
    EXPECT_TRUE(vtkIntArray::SafeDownCast(polyData->GetCellData()->GetArray("cluster_id")));
    EXPECT_FALSE(vtkIntArray::SafeDownCast(polyData->GetCellData()->GetArray("weight")));
    EXPECT_EQ(polyData->GetCellData()->GetScalars(), nullptr) << "active scalars would recolour the mapper";
    EXPECT_EQ(polyData->GetFieldData()->GetArray(modelMatrixArrayName), nullptr) << "identity is not stored";
}

TEST(PolyDataConversion, NullAndEmptyInputGiveEmptyMesh) {
    EXPECT_EQ(meshFromPolyData(nullptr).faceCount(), 0u);
    vtkNew<vtkPolyData> empty;
    EXPECT_EQ(meshFromPolyData(empty).faceCount(), 0u);
}

TEST(PolyDataConversion, NegativePointIdThrows) {
    vtkSmartPointer<vtkPolyData> polyData = squarePyramid();
    vtkIdType bad[] = {0, 1, -5};
    polyData->GetPolys()->InsertNextCell(3, bad);
    EXPECT_THROW(meshFromPolyData(polyData), std::runtime_error);
}

// A face property cluster_id is read so that a partition made elsewhere reaches the file builder,
// in ASCII and in binary of either byte order.
TEST(PlyFile, FaceClusterIdsComeThrough) {
    testing::ScratchDirectory scratch;
    const std::string header = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 2\nproperty list uchar int vertex_indices\nproperty int cluster_id\nend_header\n";
    const Mesh ascii = readMesh(scratch.writeFile(
        "ascii.ply", "ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 7\n3 0 2 3 -2\n"));
    ASSERT_EQ(ascii.faceArrays.count("cluster_id"), 1u);
    EXPECT_EQ(ascii.faceArrays.at("cluster_id"), (std::vector<double>{7, -2}));

    for (bool bigEndian : {false, true}) {
        std::string body;
        for (float coordinate : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f})
            testing::appendBinaryFloat(body, coordinate, bigEndian);
        for (const std::array<uint32_t, 4>& face : {std::array<uint32_t, 4>{0, 1, 2, 3}, std::array<uint32_t, 4>{0, 2, 3, 40000}}) {
            body.push_back(char(3));
            for (uint32_t value : face) testing::appendBinaryInteger(body, value, 4, bigEndian);
        }
        const std::string format = bigEndian ? "binary_big_endian" : "binary_little_endian";
        const Mesh binary = readMesh(scratch.writeFile(format + ".ply", "ply\nformat " + format + " 1.0\n" + header + body));
        ASSERT_EQ(binary.faceArrays.count("cluster_id"), 1u) << format;
        EXPECT_EQ(binary.faceArrays.at("cluster_id"), (std::vector<double>{3, 40000})) << format;
    }
}

// STL triangles as corner coordinates, written in ASCII or binary STL.
using StlTriangle = std::array<glm::vec3, 3>;

std::string asciiStl(const std::vector<StlTriangle>& triangles) {
    std::string text = "solid test\n";
    for (const StlTriangle& triangle : triangles) {
        text += "facet normal 0 0 0\nouter loop\n";
        for (const glm::vec3& corner : triangle)
            text += "vertex " + std::to_string(corner.x) + " " + std::to_string(corner.y) + " " + std::to_string(corner.z) + "\n";
        text += "endloop\nendfacet\n";
    }
    return text + "endsolid test\n";
}

std::string binaryStl(const std::vector<StlTriangle>& triangles) {
    std::string bytes(80, '\0');
    testing::appendBinaryInteger(bytes, uint32_t(triangles.size()), 4, false);
    for (const StlTriangle& triangle : triangles) {
        for (int k = 0; k < 3; ++k) testing::appendBinaryFloat(bytes, 0.0f, false);  // normal
        for (const glm::vec3& corner : triangle)
            for (int k = 0; k < 3; ++k) testing::appendBinaryFloat(bytes, corner[k], false);
        bytes += std::string(2, '\0');  // attribute byte count
    }
    return bytes;
}

// vtkSTLReader's point merging dropped triangles with repeated corners, so they never reached the
// mesh report; they must stay faces, counted as degenerate with the collinear one VTK always kept.
TEST(StlFile, DegenerateTrianglesAreKeptAndCounted) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1), middle(0.5f, 0, 0);
    const std::vector<StlTriangle> triangles = {{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d},
                                                {a, a, b}, {c, c, c}, {a, middle, b}, {-a, a, d}};
    testing::ScratchDirectory scratch;
    for (const std::string& path : {scratch.writeFile("ascii.stl", asciiStl(triangles)),
                                    scratch.writeFile("binary.stl", binaryStl(triangles))}) {
        SCOPED_TRACE(path);
        const Mesh mesh = readMesh(path);
        EXPECT_EQ(mesh.faceCount(), 8u);
        EXPECT_EQ(mesh.positions.size(), 5u) << "equal corners (and -0, +0) are one point";
        const FaceGeometry faces = computeFaceGeometry(mesh);
        EXPECT_EQ(faces.degenerateCount, 4u);
        EXPECT_EQ(checkMesh(mesh, faces).degenerateFaces, 4u);
        EXPECT_EQ(std::vector<uint32_t>(mesh.faceBegin(4), mesh.faceBegin(5)), (std::vector<uint32_t>{0, 0, 2}));
    }
}

}  // namespace
}  // namespace conescope

namespace conescope {
namespace {

// A square of two triangles whose shared edge the file stores twice (as exporters do at texture
// seams): read, the triangles are neighbours, and the note says what was merged.
TEST(VertexMerging, SplitSeamsAreJoinedWithANoteInEveryIndexedFormat) {
    testing::ScratchDirectory scratch;
    const std::string off = "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 3 4 5\n";
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 4 5 6\n";
    for (const std::string& path : {scratch.writeFile("seam.off", off), scratch.writeFile("seam.obj", obj)}) {
        const MeshFile file = readMeshFile(path);
        EXPECT_EQ(file.mesh.positions.size(), 4u) << path;
        EXPECT_EQ(checkMesh(file.mesh, computeFaceGeometry(file.mesh)).components, 1u) << path;
        ASSERT_EQ(file.notes.size(), 1u) << path;
        EXPECT_NE(file.notes[0].find("merged 2 vertices"), std::string::npos) << file.notes[0];
    }
    // Nothing to merge: the file's vertices as they are, and no note.
    const MeshFile square = readMeshFile(scratch.writeFile("square.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"));
    EXPECT_EQ(square.mesh.positions.size(), 4u);
    EXPECT_TRUE(square.notes.empty());
    // -0 and +0 are one position; a whole file of one point stays one vertex (and degenerate faces).
    const MeshFile zeros = readMeshFile(scratch.writeFile("zeros.off", "OFF\n4 2 0\n0 0 0\n-0 0 -0\n0 0 0\n0 -0 0\n3 0 1 2\n3 1 2 3\n"));
    EXPECT_EQ(zeros.mesh.positions.size(), 1u);
    EXPECT_EQ(computeFaceGeometry(zeros.mesh).degenerateCount, 2u);
}

// fandisk moved by 1e6 in float64: float32 steps of 0.0625 there merge 5,877 of its 6,475 positions,
// and the numbers describe another mesh. Every reader of positions wider than float says so, with
// the counts and why; the same mesh near the origin, or read from float32, says nothing.
std::string shiftedText(const Mesh& mesh, const std::string& format, double shift) {
    std::string text;
    char line[128];
    const auto point = [&](const glm::vec3& p, const char* pattern) {
        std::snprintf(line, sizeof line, pattern, double(p.x) + shift, double(p.y) + shift, double(p.z) + shift);
        text += line;
    };
    if (format == ".off") {
        text = "OFF\n" + std::to_string(mesh.positions.size()) + " " + std::to_string(mesh.faceCount()) + " 0\n";
        for (const glm::vec3& p : mesh.positions) point(p, "%.17g %.17g %.17g\n");
    } else if (format == ".obj") {
        for (const glm::vec3& p : mesh.positions) point(p, "v %.17g %.17g %.17g\n");
    } else {  // legacy VTK, ASCII, double points
        text = "# vtk DataFile Version 3.0\nshifted\nASCII\nDATASET POLYDATA\nPOINTS " + std::to_string(mesh.positions.size()) + " double\n";
        for (const glm::vec3& p : mesh.positions) point(p, "%.17g %.17g %.17g\n");
        text += "POLYGONS " + std::to_string(mesh.faceCount()) + " " + std::to_string(mesh.faceCount() * 4) + "\n";
    }
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* c = mesh.faceBegin(f);
        if (format == ".obj") text += "f " + std::to_string(c[0] + 1) + " " + std::to_string(c[1] + 1) + " " + std::to_string(c[2] + 1) + "\n";
        else text += "3 " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + "\n";
    }
    return text;
}

std::string binaryPlyOfDoubles(const Mesh& mesh, double shift) {
    std::string bytes = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(mesh.positions.size()) +
                        "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(mesh.faceCount()) +
                        "\nproperty list uchar int vertex_indices\nend_header\n";
    const auto append = [&](const void* data, size_t size) { bytes.append(static_cast<const char*>(data), size); };
    for (const glm::vec3& p : mesh.positions)
        for (int k = 0; k < 3; ++k) {
            const double value = double(p[k]) + shift;
            append(&value, 8);
        }
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint8_t three = 3;
        append(&three, 1);
        for (size_t k = 0; k < 3; ++k) {
            const int32_t index = int32_t(mesh.faceBegin(f)[k]);
            append(&index, 4);
        }
    }
    return bytes;
}

TEST(VertexMerging, PositionsThatRoundingToFloatMergesAreAWarning) {
    testing::ScratchDirectory scratch;
    const Mesh fandisk = readMesh((testing::datasetsDir() / "fandisk.off").string());
    ASSERT_EQ(fandisk.positions.size(), 6475u);
    const std::string expected = "Warning: 6475 vertices read, 598 kept: float32, which ConeScope computes in, merged 5877 positions "
                                 "the file holds apart (at coordinates up to 1e+06 float32 steps by 0.0625), so faces collapse";
    for (const char* format : {".off", ".obj", ".vtk"}) {
        SCOPED_TRACE(format);
        const MeshFile far = readMeshFile(scratch.writeFile(std::string("far") + format, shiftedText(fandisk, format, 1e6)));
        EXPECT_EQ(far.mesh.positions.size(), 598u);
        ASSERT_EQ(far.notes.size(), 1u);
        EXPECT_EQ(far.notes[0].rfind(expected, 0), 0u) << far.notes[0];
        EXPECT_NE(far.notes[0].find("move the mesh near the origin"), std::string::npos);
        const MeshFile near = readMeshFile(scratch.writeFile(std::string("near") + format, shiftedText(fandisk, format, 0.0)));
        EXPECT_EQ(near.mesh.positions.size(), 6475u);
        EXPECT_TRUE(near.notes.empty()) << near.notes.front();
    }
    const MeshFile ply = readMeshFile(scratch.writeFile("far.ply", binaryPlyOfDoubles(fandisk, 1e6)));
    ASSERT_EQ(ply.notes.size(), 1u);
    EXPECT_EQ(ply.notes[0].rfind(expected, 0), 0u) << ply.notes[0];
    // Arrays given in float64 (the Python module's), and the same rounded to float32 first: nothing
    // then tells the merged positions apart.
    Mesh arrays = fandisk;
    std::vector<glm::dvec3> exact;
    for (glm::vec3& p : arrays.positions) {
        exact.push_back(glm::dvec3(p) + 1e6);
        p = glm::vec3(exact.back());
    }
    const MeshFile given = meshFromArrays(arrays, "arrays", exact);
    ASSERT_EQ(given.notes.size(), 1u);
    EXPECT_EQ(given.notes[0].rfind(expected, 0), 0u) << given.notes[0];
    EXPECT_EQ(meshFromArrays(arrays, "arrays").notes.front().find("Warning"), std::string::npos);
}

// A seam stored twice is merged with its note; a position rounding merged beside it is counted apart.
TEST(VertexMerging, SeamsAndRoundingAreCountedApart) {
    testing::ScratchDirectory scratch;
    const MeshFile file = readMeshFile(scratch.writeFile(
        "both.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\nv 1.00000001 1 0\nf 1 2 3\nf 4 5 6\nf 2 7 6\n"));
    EXPECT_EQ(file.mesh.positions.size(), 4u);
    ASSERT_EQ(file.notes.size(), 2u);
    EXPECT_NE(file.notes[0].find("merged 2 vertices into others at the same position"), std::string::npos) << file.notes[0];
    EXPECT_EQ(file.notes[1].rfind("Warning: 7 vertices read, 4 kept", 0), 0u) << file.notes[1];
    EXPECT_NE(file.notes[1].find("merged 1 position the file holds apart"), std::string::npos) << file.notes[1];
}

}  // namespace
}  // namespace conescope
