// The XML of .vtp files, read through expat: what XML allows (comments, CDATA, processing
// instructions, single quotes, references, a byte order mark) must read as the XML says, and what
// VTK would read differently from the XML — it reads array data from the file's bytes after the
// start tag — or cannot read must be a MeshReadError naming the file and the line.
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using testing::ScratchDirectory;

std::string cubeVtp() {
    std::ifstream input(testing::formatSamplesDir() / "cube.vtp", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(input), std::istreambuf_iterator<char>());
}

// `text` with the first `from` replaced by `to`; the test fails when there is none.
std::string edited(std::string text, const std::string& from, const std::string& to) {
    size_t position = text.find(from);
    EXPECT_NE(position, std::string::npos) << from;
    return position == std::string::npos ? text : text.replace(position, from.size(), to);
}

std::string cubeVtpWith(const std::string& from, const std::string& to) { return edited(cubeVtp(), from, to); }

const std::string offsetsArray = "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4 8 12 16 20 24</DataArray>";

// The cube of tests/data/formats/cube.vtp, exactly: its points, first face and cluster ids.
void expectCube(const std::string& path) {
    SCOPED_TRACE(path);
    Mesh mesh = readMesh(path);
    ASSERT_EQ(mesh.positions.size(), 8u);
    ASSERT_EQ(mesh.faceCount(), 6u);
    EXPECT_EQ(std::vector<uint32_t>(mesh.faceVertices.begin(), mesh.faceVertices.begin() + 4), (std::vector<uint32_t>{0, 2, 3, 1}));
    EXPECT_EQ(mesh.faceArrays.at("cluster_id"), (std::vector<double>{0, 0, 1, 1, 2, 2}));
}

TEST(VtpXml, CommentsInstructionsAndCdataBetweenElementsAreSkipped) {
    ScratchDirectory scratch;
    // The hand-written scanner took the tag inside this CDATA section (after its '>') for a piece
    // and refused the file for its count.
    expectCube(scratch.writeFile("cdata.vtp", cubeVtpWith("<PolyData>", "<PolyData><![CDATA[ x > 1 <Piece NumberOfPoints=\"99999999999\"> ]]>")));
    expectCube(scratch.writeFile("comment.vtp", cubeVtpWith("<PolyData>", "<PolyData>\n<!-- <Piece NumberOfPoints=\"99999999999\"> -->")));
    expectCube(scratch.writeFile("instruction.vtp", cubeVtpWith("<PolyData>", "<PolyData><?note a > b?>")));
}

// Only a real <PointData> element spares the piece the one prepareVtpForVtk adds: the tag in this
// CDATA section counted for the hand-written scanner, and VTK crashed on the bad cell value.
TEST(VtpXml, PointDataInCdataDoesNotCount) {
    ScratchDirectory scratch;
    std::string text = cubeVtpWith("<CellData>", "<![CDATA[ > <PointData> ]]><CellData>");
    EXPECT_READ_ERROR(scratch.writeFile("cdata.vtp", edited(text, ">0 0 1 1 2 2<", ">0 0 x 1 2 2<")),
                      "Cannot read cell data array \"cluster_id\"");
}

TEST(VtpXml, AttributesInSingleQuotesOrWithSpacesAroundTheEqualsSign) {
    ScratchDirectory scratch;
    std::string singleQuoted = cubeVtp();
    for (char& c : singleQuoted)
        if (c == '"') c = '\'';
    expectCube(scratch.writeFile("single.vtp", singleQuoted));
    expectCube(scratch.writeFile("spaces.vtp", cubeVtpWith("NumberOfPoints=\"8\"", "NumberOfPoints = \"8\"")));
}

// The hand-written scanner read "&#56;" as the count itself and refused files VTK reads; worse, it
// missed an offsets array named "offset&#115;", whose forged last offset VTK then allocated from.
TEST(VtpXml, ReferencesInAttributeValuesAreDecoded) {
    ScratchDirectory scratch;
    expectCube(scratch.writeFile("count.vtp", cubeVtpWith("NumberOfPoints=\"8\"", "NumberOfPoints=\"&#56;\"")));
    expectCube(scratch.writeFile("type.vtp", cubeVtpWith("type=\"Int32\"", "type=\"Int&#51;2\"")));
    std::string declared = edited(cubeVtp(), "<?xml version=\"1.0\"?>\n", "<?xml version=\"1.0\"?>\n<!DOCTYPE VTKFile [<!ENTITY n \"8\">]>\n");
    expectCube(scratch.writeFile("entity.vtp", edited(declared, "NumberOfPoints=\"8\"", "NumberOfPoints=\"&n;\"")));
    std::string forged = cubeVtpWith(offsetsArray, "<DataArray type=\"Int64\" Name=\"offset&#115;\" format=\"ascii\">4 8 12 16 20 4294967295</DataArray>");
    EXPECT_READ_ERROR(scratch.writeFile("forged.vtp", forged), ":12: Polys of piece 0: the last offset is 4294967295");
}

// Byte positions count the byte order mark: the <PointData/> added to the piece (which keeps VTK
// from crashing on the bad cell value) must land after the piece's tag.
TEST(VtpXml, ByteOrderMarkLatin1AndCrlfLineEnds) {
    ScratchDirectory scratch;
    expectCube(scratch.writeFile("bom.vtp", "\xef\xbb\xbf" + cubeVtp()));
    EXPECT_READ_ERROR(scratch.writeFile("bom-bad-value.vtp", "\xef\xbb\xbf" + cubeVtpWith(">0 0 1 1 2 2<", ">0 0 x 1 2 2<")),
                      "Cannot read cell data array \"cluster_id\"");
    std::string latin1 = edited(cubeVtp(), "<?xml version=\"1.0\"?>", "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>");
    expectCube(scratch.writeFile("latin1.vtp", edited(latin1, "Name=\"cluster_id\"", "Name=\"cluster_id\" note=\"caf\xe9\"")));
    std::string crlf;
    for (char c : cubeVtp()) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    expectCube(scratch.writeFile("crlf.vtp", crlf));
}

TEST(VtpXml, MalformedXmlNamesTheLine) {
    ScratchDirectory scratch;
    std::string text = cubeVtp();
    EXPECT_READ_ERROR(scratch.writeFile("half.vtp", text.substr(0, text.size() / 2)),
                      "half.vtp:9: malformed XML: unclosed token (column 7); the file ends before the XML does (cut short?)");
    EXPECT_READ_ERROR(scratch.writeFile("tag.vtp", cubeVtpWith("</Piece>", "</Pieces>")), "tag.vtp:16: malformed XML: mismatched tag");
    EXPECT_READ_ERROR(scratch.writeFile("twice.vtp", cubeVtpWith("NumberOfPolys=\"6\"", "NumberOfPolys=\"6\" NumberOfPolys=\"5\"")),
                      "twice.vtp:4: malformed XML: duplicate attribute");
    EXPECT_READ_ERROR(scratch.writeFile("less.vtp", cubeVtpWith("Name=\"cluster_id\"", "Name=\"cluster<id\"")),
                      "less.vtp:6: malformed XML: not well-formed (invalid token)");
    EXPECT_READ_ERROR(scratch.writeFile("junk.vtp", text + "junk\n"), "junk.vtp:19: malformed XML: junk after document element");
}

// VTK reads inline data from the bytes after the start tag up to the first character that is not
// data, not through the XML: values after a comment were dropped without a word.
TEST(VtpXml, MarkupInsideArrayDataIsRefused) {
    ScratchDirectory scratch;
    const char* refused = "DataArray 'cluster_id' in CellData of piece 0: its data holds markup or a reference";
    EXPECT_READ_ERROR(scratch.writeFile("comment.vtp", cubeVtpWith(">0 0 1 1 2 2<", ">0 0 1 1 2 2 <!-- more --> 5 5<")),
                      std::string("comment.vtp:6: ") + refused);
    EXPECT_READ_ERROR(scratch.writeFile("cdata.vtp", cubeVtpWith(">0 0 1 1 2 2<", "><![CDATA[0 0 1 1 2 2]]><")), refused);
    EXPECT_READ_ERROR(scratch.writeFile("reference.vtp", cubeVtpWith(">0 0 1 1 2 2<", ">0 0 &#49; 1 2 2<")), refused);
}

// VTK reads the text after a self-closed array as its data: the hand-written scanner saw no data
// there, so a forged last offset reached VTK, which asked for 32 GB.
TEST(VtpXml, TextAfterASelfClosedArrayIsRefused) {
    ScratchDirectory scratch;
    std::string text = cubeVtpWith(offsetsArray, "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\"/>4 8 12 16 20 4294967295");
    EXPECT_READ_ERROR(scratch.writeFile("after.vtp", text),
                      "after.vtp:14: DataArray 'offsets' in Polys of piece 0 is self-closed, but text follows it that VTK would read as its data");
}

// VTK finds where an array's data start by the first '>' after its '<': this file read as a
// different cube (faces from the attribute) without a word.
TEST(VtpXml, GreaterThanInADataArrayAttributeIsRefused) {
    ScratchDirectory scratch;
    std::string text = cubeVtpWith(
        "format=\"ascii\">0 2 3 1 4 5 7 6 0 1 5 4 2 6 7 3 0 4 6 2 1 3 7 5</DataArray>",
        "format=\"ascii\" note=\"> 0 1 2 3 4 5 6 7 0 1 2 3 4 5 6 7 0 1 2 3 4 5 6 7\"></DataArray>");
    EXPECT_READ_ERROR(scratch.writeFile("attribute.vtp", text),
                      "attribute.vtp:13: an attribute value of this <DataArray> holds '>', which VTK takes for the end of the tag");
}

// VTK ends the XML at the first "<AppendedData" in the bytes and closes the document itself.
TEST(VtpXml, AppendedDataWhereVtkCannotReadItIsRefused) {
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile("comment.vtp", cubeVtpWith("<PolyData>", "<PolyData>\n<!-- <AppendedData encoding=\"raw\"> -->")),
                      "comment.vtp:4: \"<AppendedData\" outside an <AppendedData> tag");
    EXPECT_READ_ERROR(scratch.writeFile("inside.vtp", cubeVtpWith("</PolyData>", "<AppendedData encoding=\"raw\">_</AppendedData></PolyData>")),
                      "inside.vtp:17: <AppendedData> stands inside <PolyData>; VTK reads it only as a child of the root <VTKFile>");
}

TEST(VtpXml, ElementsWrittenByAnEntityAreRefused) {
    ScratchDirectory scratch;
    std::string cellData = "<CellData><DataArray type='Int32' Name='cluster_id' format='ascii'>0 0 1 1 2 2</DataArray></CellData>";
    std::string text = cubeVtpWith("<?xml version=\"1.0\"?>\n", "<?xml version=\"1.0\"?>\n<!DOCTYPE VTKFile [<!ENTITY cells \"" + cellData + "\">]>\n");
    text = edited(text, "<Points>", "&cells;<Points>");
    EXPECT_READ_ERROR(scratch.writeFile("entity.vtp", text), "entity.vtp:10: element <CellData> is written by an entity reference");
}

// expat reads UTF-16, VTK does not: the hand-written scanner found no tags in it and VTK crashed.
TEST(VtpXml, Utf16IsRefused) {
    ScratchDirectory scratch;
    std::string utf16 = "\xff\xfe";
    for (char c : cubeVtpWith("version=\"1.0\"?>", "version=\"1.0\" encoding=\"UTF-16\"?>")) utf16 += std::string{c, '\0'};
    EXPECT_READ_ERROR(scratch.writeFile("utf16.vtp", utf16), "utf16.vtp: UTF-16 text");
}

}  // namespace
}  // namespace conescope
