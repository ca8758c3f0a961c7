// .vtp arrays in each binary encoding VTK reads (inline base64, raw or base64 appended data, each
// zlib-compressed or not): a count smaller than the data, a forged size or a forged offset must be a
// MeshReadError before VTK drops data or allocates from it. The files are built here byte by byte,
// so each damage is exact; a good file in every encoding must still read.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkZLibDataCompressor.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using testing::ScratchDirectory;

std::string littleEndian(uint64_t value, size_t bytes) {
    std::string text;
    for (size_t k = 0; k < bytes; ++k) text += static_cast<char>(value >> (8 * k));
    return text;
}

std::string base64(const std::string& bytes) {
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        size_t present = std::min<size_t>(3, bytes.size() - i);
        uint32_t group = 0;
        for (size_t k = 0; k < 3; ++k) group = (group << 8) | (k < present ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (size_t k = 0; k < 4; ++k) text += k <= present ? alphabet[(group >> (18 - 6 * k)) & 63] : '=';
    }
    return text;
}

std::string zlibCompressed(const std::string& bytes) {
    vtkNew<vtkZLibDataCompressor> compressor;
    std::string compressed(compressor->GetMaximumCompressionSpace(bytes.size()), '\0');
    compressed.resize(compressor->Compress(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                                           reinterpret_cast<unsigned char*>(compressed.data()), compressed.size()));
    return compressed;
}

enum class Storage { Inline, AppendedRaw, AppendedBase64 };

struct Encoding {
    const char* name;
    Storage storage;
    bool compressed;
};

void PrintTo(const Encoding& encoding, std::ostream* out) { *out << encoding.name; }

// The unit cube of tests/data/formats as three arrays, with the counts and headers a test may forge.
struct Cube {
    uint64_t points = 8, polys = 6;
    std::vector<int64_t> connectivity = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
    std::vector<int64_t> offsets = {4, 8, 12, 16, 20, 24};
    std::optional<uint32_t> offsetsByteCount;  // replaces the uncompressed header of the offsets array
    std::optional<uint32_t> offsetsBlockCount;  // replaces the block count of the compressed offsets array
    std::optional<uint32_t> offsetsBlockBytes;  // replaces its compressed block size
};

std::string int64Values(const std::vector<int64_t>& values) {
    std::string bytes;
    for (int64_t value : values) bytes += littleEndian(static_cast<uint64_t>(value), 8);
    return bytes;
}

std::string pointValues() {
    std::string bytes;
    for (int i = 0; i < 8; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            float coordinate = ((i >> axis) & 1) ? 0.5f : -0.5f;
            uint32_t bits = 0;
            std::memcpy(&bits, &coordinate, 4);
            bytes += littleEndian(bits, 4);
        }
    return bytes;
}

// One array's binary data as vtkXMLWriter stores it: a UInt32 byte count and the values, or a
// one-block table (1, size, size, compressed size) and the zlib block. In base64 the table and the
// block are separate streams, as VTK writes them.
std::string storedArray(const std::string& values, const Encoding& encoding, std::optional<uint32_t> byteCount = {},
                        std::optional<uint32_t> blockCount = {}, std::optional<uint32_t> blockBytes = {}) {
    bool base64Text = encoding.storage != Storage::AppendedRaw;
    if (!encoding.compressed) {
        std::string bytes = littleEndian(byteCount.value_or(static_cast<uint32_t>(values.size())), 4) + values;
        return base64Text ? base64(bytes) : bytes;
    }
    std::string block = zlibCompressed(values);
    std::string table = littleEndian(blockCount.value_or(1), 4) + littleEndian(values.size(), 4) + littleEndian(values.size(), 4) +
                        littleEndian(blockBytes.value_or(static_cast<uint32_t>(block.size())), 4);
    return base64Text ? base64(table) + base64(block) : table + block;
}

std::string cubeVtp(const Encoding& encoding, const Cube& cube) {
    struct Array {
        std::string attributes, stored;
    };
    const Array arrays[] = {
        {"type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"", storedArray(pointValues(), encoding)},
        {"type=\"Int64\" Name=\"connectivity\"", storedArray(int64Values(cube.connectivity), encoding)},
        {"type=\"Int64\" Name=\"offsets\"", storedArray(int64Values(cube.offsets), encoding, cube.offsetsByteCount,
                                                        cube.offsetsBlockCount, cube.offsetsBlockBytes)},
    };
    std::string appended, elements[3];
    for (size_t a = 0; a < 3; ++a) {
        if (encoding.storage == Storage::Inline) {
            elements[a] = "<DataArray " + arrays[a].attributes + " format=\"binary\">\n  " + arrays[a].stored + "\n</DataArray>\n";
        } else {
            elements[a] = "<DataArray " + arrays[a].attributes + " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>\n";
            appended += arrays[a].stored;
        }
    }
    std::string text = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                                   "header_type=\"UInt32\"") +
                       (encoding.compressed ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<PolyData>\n<Piece NumberOfPoints=\"" +
                       std::to_string(cube.points) + "\" NumberOfPolys=\"" + std::to_string(cube.polys) + "\">\n<Points>\n" + elements[0] +
                       "</Points>\n<Polys>\n" + elements[1] + elements[2] + "</Polys>\n</Piece>\n</PolyData>\n";
    if (encoding.storage != Storage::Inline)
        text += std::string("<AppendedData encoding=\"") + (encoding.storage == Storage::AppendedRaw ? "raw" : "base64") + "\">\n_" +
                appended + "\n</AppendedData>\n";
    return text + "</VTKFile>\n";
}

class VtpEncoding : public ::testing::TestWithParam<Encoding> {
protected:
    std::string write(const Cube& cube) { return scratch_.writeFile(std::string(GetParam().name) + ".vtp", cubeVtp(GetParam(), cube)); }

private:
    ScratchDirectory scratch_;
};

TEST_P(VtpEncoding, GoodCubeReads) {
    Mesh mesh = readMesh(write(Cube()));
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.faceCount(), 6u);
}

// VTK sizes the connectivity by the last offset before reading it: 4294967295 was a 32 GB allocation.
TEST_P(VtpEncoding, ForgedLastOffset) {
    Cube cube;
    cube.offsets.back() = 4294967295;
    EXPECT_READ_ERROR(write(cube), "Polys of piece 0: the last offset is 4294967295 but the connectivity array holds 24 values");
}

// Each of these read as a smaller or wrong mesh without a word: VTK reads only what the counts give.
TEST_P(VtpEncoding, MoreValuesThanTheCountsGive) {
    Cube fewerPolys;
    fewerPolys.polys = 5;
    EXPECT_READ_ERROR(write(fewerPolys),
                      "DataArray 'offsets' in Polys of piece 0 holds 6 values but NumberOfPolys=5 gives 5 (is a count or NumberOfComponents too small?)");
    Cube fewerPoints;
    fewerPoints.points = 7;
    EXPECT_READ_ERROR(write(fewerPoints),
                      "DataArray 'Points' in Points of piece 0 holds 24 values but NumberOfPoints=7 times 3 components gives 21");
    // Offsets with the leading 0 (one more than the cells): VTK 9.1 took the 0 as the end of the
    // first cell and dropped the last.
    Cube leadingZero;
    leadingZero.offsets.insert(leadingZero.offsets.begin(), 0);
    EXPECT_READ_ERROR(write(leadingZero), "DataArray 'offsets' in Polys of piece 0 holds 7 values but NumberOfPolys=6 gives 6");
}

TEST_P(VtpEncoding, OffsetsEndBeforeTheConnectivity) {
    Cube cube;
    cube.polys = 5;
    cube.offsets.pop_back();
    EXPECT_READ_ERROR(write(cube), "Polys of piece 0: the last offset is 20 but the connectivity array holds 24 values");
}

INSTANTIATE_TEST_SUITE_P(Encodings, VtpEncoding,
                         ::testing::Values(Encoding{"inline", Storage::Inline, false}, Encoding{"inline_zlib", Storage::Inline, true},
                                           Encoding{"appended_raw", Storage::AppendedRaw, false},
                                           Encoding{"appended_raw_zlib", Storage::AppendedRaw, true},
                                           Encoding{"appended_base64", Storage::AppendedBase64, false},
                                           Encoding{"appended_base64_zlib", Storage::AppendedBase64, true}),
                         [](const ::testing::TestParamInfo<Encoding>& info) { return std::string(info.param.name); });

// Sizes in binary headers are checked against the data in the file before VTK allocates from them.
TEST(VtpBinaryHeader, ForgedByteCount) {
    ScratchDirectory scratch;
    Cube cube;
    cube.offsetsByteCount = 4294967295u;
    EXPECT_READ_ERROR(scratch.writeFile("inline.vtp", cubeVtp({"inline", Storage::Inline, false}, cube)),
                      "DataArray 'offsets' in Polys of piece 0: inline binary data is corrupt: byte count 4294967295 runs past the end of the data");
    EXPECT_READ_ERROR(scratch.writeFile("raw.vtp", cubeVtp({"raw", Storage::AppendedRaw, false}, cube)),
                      "DataArray 'offsets' in Polys of piece 0: appended data is corrupt: byte count 4294967295 runs past the end of the data");
    cube.offsetsByteCount = 40;
    EXPECT_READ_ERROR(scratch.writeFile("short.vtp", cubeVtp({"short", Storage::Inline, false}, cube)),
                      "holds 5 values but NumberOfPolys=6 gives 6 (truncated array or wrong count)");
}

TEST(VtpBinaryHeader, ForgedBlockTable) {
    ScratchDirectory scratch;
    for (Encoding encoding : {Encoding{"inline", Storage::Inline, true}, Encoding{"raw", Storage::AppendedRaw, true}}) {
        Cube blocks;
        blocks.offsetsBlockCount = 1000000000;
        EXPECT_READ_ERROR(scratch.writeFile(std::string("blocks_") + encoding.name + ".vtp", cubeVtp(encoding, blocks)),
                          "block table runs past the end of the data");
        Cube size;
        size.offsetsBlockBytes = 4000000000u;
        EXPECT_READ_ERROR(scratch.writeFile(std::string("size_") + encoding.name + ".vtp", cubeVtp(encoding, size)),
                          "compressed blocks run past the end of the data");
    }
}

// vtkXMLDataParser reads appended data as base64 unless encoding="raw", with no encoding too: the
// check read such data as raw bytes, refusing a good file and checking other sizes than VTK reads.
TEST(VtpArrayFormat, AppendedDataWithoutEncodingIsBase64) {
    ScratchDirectory scratch;
    std::string text = cubeVtp({"base64", Storage::AppendedBase64, false}, Cube());
    std::string encoding = "<AppendedData encoding=\"base64\">";
    ASSERT_NE(text.find(encoding), std::string::npos);
    text.replace(text.find(encoding), encoding.size(), "<AppendedData>");
    EXPECT_EQ(readMesh(scratch.writeFile("good.vtp", text)).faceCount(), 6u);
    Cube forged;
    forged.offsetsByteCount = 4294967295u;
    text = cubeVtp({"base64", Storage::AppendedBase64, false}, forged);
    text.replace(text.find(encoding), encoding.size(), "<AppendedData>");
    EXPECT_READ_ERROR(scratch.writeFile("forged.vtp", text), "appended data is corrupt: byte count 4294967295 runs past the end of the data");
}

// VTK reads any array with an offset attribute from the appended data, whatever its format says;
// a damaged format (found by fuzz_mesh_readers) made it read blocks the checks never saw, and crash.
TEST(VtpArrayFormat, OffsetWithoutAppendedFormatIsRefused) {
    ScratchDirectory scratch;
    for (Encoding encoding : {Encoding{"raw", Storage::AppendedRaw, true}, Encoding{"base64", Storage::AppendedBase64, false}}) {
        std::string text = cubeVtp(encoding, Cube());
        std::string appended = "Name=\"offsets\" format=\"appended\"";
        ASSERT_NE(text.find(appended), std::string::npos);
        std::string ascii = text, none = text;
        ascii.replace(ascii.find(appended), appended.size(), "Name=\"offsets\" format=\"ascii\"");
        none.replace(none.find(appended), appended.size(), "Name=\"offsets\" forEat=\"appended\"");
        EXPECT_READ_ERROR(scratch.writeFile(std::string("ascii_") + encoding.name + ".vtp", ascii),
                          ":10: DataArray 'offsets' in Polys of piece 0 has an offset attribute but format 'ascii'");
        EXPECT_READ_ERROR(scratch.writeFile(std::string("none_") + encoding.name + ".vtp", none), "has an offset attribute but format (none)");
    }
}

}  // namespace
}  // namespace conescope
