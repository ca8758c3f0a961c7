// VTK's own formats, .vtp (XML) and legacy .vtk, when bad: every case must end in MeshReadError
// naming the file, never in a crash, a huge allocation, a silently empty mesh or VTK chatter on
// stderr. The other formats are in MalformedFileTests.cpp.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"

namespace conescope {
namespace {

using testing::expectErrorWhenReplaced;
using testing::fileBytes;
using testing::formatSamplesDir;
using testing::replaceFirst;
using testing::ScratchDirectory;

// ---------------------------------------------------------------- VTP

TEST(MalformedVtp, OtherXml) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("other.vtp", "<?xml version=\"1.0\"?>\n<html><body/></html>\n"),
                      "not a VTK XML PolyData");
}

TEST(MalformedVtp, ImageDataInsteadOfPolyData) {
    ScratchDirectory scratch;
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\">\n"
                       "<ImageData WholeExtent=\"0 1 0 1 0 1\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n"
                       "<Piece Extent=\"0 1 0 1 0 1\"></Piece></ImageData></VTKFile>\n";
    EXPECT_READ_ERROR(scratch.writeFile("image.vtp", text), "not a VTK XML PolyData");
}

TEST(MalformedVtp, DataShorterThanDeclared) {
    expectErrorWhenReplaced("cube.vtp", "NumberOfPoints=\"8\"", "NumberOfPoints=\"80\"", ": ");
}

TEST(MalformedVtp, ConnectivityOutOfRange) {
    expectErrorWhenReplaced("cube.vtp", "0 2 3 1", "0 2 3 99", "uses vertex 99");
}

// VTK sizes the connectivity by the last offset before reading it: a forged offset was a 32 GB
// allocation (found by fuzz_mesh_readers).
TEST(MalformedVtp, ForgedOffsetIsRejectedBeforeVtkAllocates) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    ASSERT_NE(text.find(">4 8 12 16 20 24<"), std::string::npos);
    replaceFirst(text, ">4 8 12 16 20 24<", ">4 8 12 16 20\n4294967295<");
    EXPECT_READ_ERROR(scratch.writeFile("offset.vtp", text), "the last offset is 4294967295 but the connectivity array holds 24 values");
    // VTK reads a number's leading digits and allocates for them, whatever follows them (a 3.4 GB
    // allocation, found by fuzz_mesh_readers); a number past 2^64 it reads as the largest.
    std::string junk = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(junk, ">4 8 12 16 20 24<", ">4 8 12 16 20 429496729St5ctypeIcE5<");
    EXPECT_READ_ERROR(scratch.writeFile("junk.vtp", junk), "the last offset is 429496729 but the connectivity array holds 24 values");
    std::string huge = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(huge, ">4 8 12 16 20 24<", ">4 8 12 16 20 +99999999999999999999999<");
    EXPECT_READ_ERROR(scratch.writeFile("huge.vtp", huge), "the last offset is 18446744073709551615 but the connectivity array holds 24 values");
}

// VTK reads as many values as the piece counts give and ignores the rest: each of these read as a
// smaller or wrong mesh without a word. tests/io/VtpEncodingTests.cpp has the binary encodings.
TEST(MalformedVtp, MoreAsciiValuesThanTheCountsGive) {
    expectErrorWhenReplaced("cube.vtp", "NumberOfPolys=\"6\"", "NumberOfPolys=\"5\"",
                            ": DataArray 'cluster_id' in CellData of piece 0 holds 6 values but the piece's 5 cells gives 5 "
                            "(is a count or NumberOfComponents too small?)");
    expectErrorWhenReplaced("cube.vtp", "NumberOfPoints=\"8\"", "NumberOfPoints=\"7\"",
                            ": DataArray in Points of piece 0 holds 24 values but NumberOfPoints=7 times 3 components gives 21");
    expectErrorWhenReplaced("cube.vtp", ">4 8 12 16 20 24<", ">0 4 8 12 16 20 24<",
                            ": DataArray 'offsets' in Polys of piece 0 holds 7 values but NumberOfPolys=6 gives 6");
    expectErrorWhenReplaced("cube.vtp", "1 3 7 5<", "1 3 7 5 0 1 2 3<",
                            ": Polys of piece 0: the last offset is 24 but the connectivity array holds 28 values");
}

TEST(MalformedVtp, NoPolygons) {
    ScratchDirectory scratch;
    std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\">\n<PolyData>\n"
                       "<Piece NumberOfPoints=\"1\" NumberOfPolys=\"0\"><Points>"
                       "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray>"
                       "</Points></Piece></PolyData></VTKFile>\n";
    EXPECT_READ_ERROR(scratch.writeFile("points.vtp", text), "no faces");
}

// A bad cell-data array in a piece without <PointData> crashed VTK 9.1 (its error message
// dereferences the missing element); prepareVtpForVtk adds an empty one.
TEST(MalformedVtp, BadCellDataValueWithoutPointData) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    ASSERT_EQ(text.find("<PointData"), std::string::npos);
    replaceFirst(text, ">0 0 1 1 2 2<", ">0 0 x 1 2 2<");
    EXPECT_READ_ERROR(scratch.writeFile("value.vtp", text), "Cannot read cell data array \"cluster_id\"");
    text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, ">0 0 1 1 2 2<", ">0 0 1 1 2<");
    EXPECT_READ_ERROR(scratch.writeFile("short.vtp", text), "Cannot read cell data array \"cluster_id\"");
}

TEST(MalformedVtp, UnknownArrayType) {
    expectErrorWhenReplaced("cube.vtp", "type=\"Int32\"", "type=\"Int99\"", "DataArray has unknown type 'Int99'");
}

TEST(MalformedVtp, ForgedPieceCounts) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, "NumberOfPolys=\"6\"", "NumberOfPolys=\"2000000000\"");
    EXPECT_READ_ERROR(scratch.writeFile("polys.vtp", text), "NumberOfPolys=2000000000, more than the file can hold");
    text = fileBytes(formatSamplesDir() / "cube.vtp");
    replaceFirst(text, "NumberOfPoints=\"8\"", "NumberOfPoints=\"4000000000\"");
    EXPECT_READ_ERROR(scratch.writeFile("points.vtp", text), "NumberOfPoints=4000000000, more than the file can hold");
}

TEST(MalformedVtp, BadComponentCounts) {
    ScratchDirectory scratch;
    for (const char* components : {"0", "-3", "2000000000"}) {
        std::string text = fileBytes(formatSamplesDir() / "cube.vtp");
        replaceFirst(text, "Name=\"face_normal\" NumberOfComponents=\"3\"", std::string("Name=\"face_normal\" NumberOfComponents=\"") + components + "\"");
        EXPECT_READ_ERROR(scratch.writeFile(std::string("components") + components + ".vtp", text), "NumberOfComponents");
    }
}

TEST(MalformedVtp, CorruptAppendedBlockTable) {
    // Deleting one byte inside the appended data shifts every later block table.
    Mesh prism = readMesh((testing::datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    std::string path = scratch.file("prism.vtp");
    writePolyData(prism, path, {{"cluster_id", std::vector<double>(prism.faceCount(), 1.0)}});
    std::string bytes = fileBytes(path);
    size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1;
    size_t end = bytes.rfind("</AppendedData>");
    size_t detected = 0, cuts = 0;
    for (size_t remove = data + 1; remove < end; remove += 7, ++cuts) {
        std::string damaged = bytes;
        damaged.erase(remove, 1);
        std::string damagedPath = scratch.writeFile("damaged" + std::to_string(remove) + ".vtp", damaged);
        try {
            readMesh(damagedPath);
        } catch (const MeshReadError&) {
            ++detected;
        }
    }
    EXPECT_GT(detected, cuts / 2);
}

// ---------------------------------------------------------------- legacy VTK

TEST(MalformedLegacyVtk, UnstructuredGridIsNotPolyData) {
    EXPECT_READ_ERROR((formatSamplesDir() / "tetrahedron-grid.vtk").string(), "not a legacy VTK file with POLYDATA");
}

TEST(MalformedLegacyVtk, ForgedPointCount) {
    expectErrorWhenReplaced("cube.vtk", "POINTS 8", "POINTS 900000000", ": ");
}

TEST(MalformedLegacyVtk, PolygonIndexOutOfRange) {
    expectErrorWhenReplaced("cube.vtk", "4 0 2 3 1", "4 0 2 3 77", "uses vertex 77");
}

// Each of these crashed VTK 9.1's legacy reader, or (truncated attribute data) read as zeros.
TEST(MalformedLegacyVtk, CutInsideThePolygons) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    text.resize(text.find("4 2 6 7 3"));
    EXPECT_READ_ERROR(scratch.writeFile("cut.vtk", text), "POLYGONS: file ends after 15 of 30 values");
}

TEST(MalformedLegacyVtk, TruncatedCellDataIsAnErrorNotZeros) {
    ScratchDirectory scratch;
    std::string text = fileBytes(formatSamplesDir() / "cube.vtk");
    text.resize(text.size() - 4);  // drops the last two cluster ids
    EXPECT_READ_ERROR(scratch.writeFile("cut.vtk", text), "SCALARS: file ends after 4 of 6 values");
}

// VTK 4.x builds the polygons from the size alone; a count that disagrees is an inconsistent header.
TEST(MalformedLegacyVtk, PolygonCountDisagreesWithTheCells) {
    expectErrorWhenReplaced("cube.vtk", "POLYGONS 6 30", "POLYGONS 5 30", "POLYGONS: header declares 5 cells but its 30 values hold 6");
    expectErrorWhenReplaced("cube.vtk", "POLYGONS 6 30", "POLYGONS 7 30", "POLYGONS: header declares 7 cells but its 30 values hold 6");
}

// VTK reads the values a header declares and takes the next word as a keyword: it stopped at the
// sixth polygon's "4", and a too-small POINTS or CELL_DATA count is the same case.
TEST(MalformedLegacyVtk, CountSmallerThanTheValues) {
    expectErrorWhenReplaced("cube.vtk", "POLYGONS 6 30", "POLYGONS 5 25",
                            ":20: POLYGONS: value '4' after the 25 values its header declares (is a count in the header too small?)");
    expectErrorWhenReplaced("cube.vtk", "POINTS 8", "POINTS 7", ":13: POINTS: value '0.5' after the 21 values its header declares");
    expectErrorWhenReplaced("cube.vtk", "CELL_DATA 6", "CELL_DATA 5", ":29: SCALARS: value '2' after the 5 values its header declares");
}

TEST(MalformedLegacyVtk, KeywordWithTrailingGarbage) {
    // VTK matches "POLYGONSx" as POLYGONS by prefix and then crashed on what followed.
    expectErrorWhenReplaced("cube.vtk", "POLYGONS", "POLYGONS\x82", "unexpected keyword");
}

TEST(MalformedLegacyVtk, IdBeyondInt) {
    expectErrorWhenReplaced("cube.vtk", "4 1 3 7 5", "4 1 3 711382209708227 5", "expected an integer of type int, found '711382209708227'");
}

TEST(MalformedLegacyVtk, CoordinateBeyondFloat) {
    expectErrorWhenReplaced("cube.vtk", "0.5 0.5 0.5", "0.5 1e999 0.5", "expected a finite float, found '1e999'");
}

TEST(MalformedLegacyVtk, DamagedVersionSwitchesCellLayout) {
    // "5.\xc8" reads as version 0.0 in VTK, so the 5.1 OFFSETS layout must not be assumed.
    Mesh prism = readMesh((testing::datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    std::string path = scratch.file("prism.vtk");
    writePolyData(prism, path);
    std::string bytes = fileBytes(path);
    ASSERT_EQ(bytes.rfind("# vtk DataFile Version 5.1", 0), 0u);
    bytes[25] = '\xc8';
    EXPECT_READ_ERROR(scratch.writeFile("version.vtk", bytes), ": ");
}

TEST(MalformedLegacyVtk, TruncatedBinaryFile) {
    Mesh prism = readMesh((testing::datasetsDir() / "hexagonal-prism.off").string());
    ScratchDirectory scratch;
    std::string path = scratch.file("prism.vtk");
    writePolyData(prism, path, {{"cluster_id", std::vector<double>(prism.faceCount(), 2.0)}});
    std::string bytes = fileBytes(path);
    for (size_t length = 1; length + 1 < bytes.size(); length += 13) {
        std::string cutPath = scratch.writeFile("cut" + std::to_string(length) + ".vtk", bytes.substr(0, length));
        try {
            Mesh mesh = readMesh(cutPath);
            // Only a cut after the polygons and before the cell data can leave a valid file.
            EXPECT_EQ(mesh.faceArrays.count("cluster_id"), 0u) << length;
        } catch (const MeshReadError& error) {
            EXPECT_NE(std::string(error.what()).find(cutPath), std::string::npos);
        }
    }
}

}  // namespace
}  // namespace conescope
