// prepareVtpForVtk: checks the XML header of a .vtp file and works around crashes of VTK 9.1's
// vtkXMLPolyDataReader before it reads the file.
//
// Crashes found by mutating valid files:
//  - a cell-data array that fails to read (too short, a non-number) when the piece has no
//    <PointData> element: the error message dereferences the missing element. Adding an empty
//    <PointData/> turns the crash into VTK's ordinary "Cannot read cell data array" error.
//  - a <DataArray> with an unknown type in <FieldData>, and piece counts near 2^31 (NumberOfPolys):
//    rejected here.
//
// Data VTK would drop or allocate from without a word, checked for arrays in every encoding (ASCII,
// inline base64, raw or base64 appended, compressed or not):
//  - more values than the piece counts give (VTK reads only what the counts say), and for binary
//    arrays any other number than they give;
//  - binary headers and block tables that run past the data in the file;
//  - a cell section's last offset, which VTK sizes the connectivity by, against the values the
//    connectivity array holds.
#include "io/HeaderChecks.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkSmartPointer.h>
#include <vtkZLibDataCompressor.h>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/TextScanning.h"

namespace conescope {

namespace {

struct XmlStartTag {
    std::string_view name;
    std::string_view attributes;  // text between the name and '>' (or "/>")
    size_t begin = 0;             // index of '<'
    size_t end = 0;               // index just after '>'
    bool selfClosing = false;
};

bool isXmlSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Start tags in document order, skipping comments, processing instructions and end tags. A tag cut
// off by the end of the text ends the list (the XML parser reports the damage).
std::vector<XmlStartTag> startTags(std::string_view xml) {
    std::vector<XmlStartTag> tags;
    size_t position = 0;
    while ((position = xml.find('<', position)) != std::string_view::npos) {
        if (xml.substr(position, 4) == "<!--") {
            size_t close = xml.find("-->", position + 4);
            if (close == std::string_view::npos) break;
            position = close + 3;
            continue;
        }
        size_t close = xml.find('>', position);
        if (close == std::string_view::npos) break;
        char first = position + 1 < xml.size() ? xml[position + 1] : '\0';
        if (first == '/' || first == '?' || first == '!') {
            position = close + 1;
            continue;
        }
        XmlStartTag tag;
        tag.begin = position;
        tag.end = close + 1;
        size_t nameEnd = position + 1;
        while (nameEnd < close && !isXmlSpace(xml[nameEnd]) && xml[nameEnd] != '/') ++nameEnd;
        tag.name = xml.substr(position + 1, nameEnd - position - 1);
        tag.selfClosing = xml[close - 1] == '/';
        tag.attributes = xml.substr(nameEnd, close - nameEnd - (tag.selfClosing ? 1 : 0));
        tags.push_back(tag);
        position = close + 1;
    }
    return tags;
}

// Value of attribute `key` (name="value" or name='value'), if present.
std::optional<std::string_view> attributeValue(std::string_view attributes, std::string_view key) {
    size_t position = 0;
    while (position < attributes.size()) {
        while (position < attributes.size() && isXmlSpace(attributes[position])) ++position;
        size_t nameStart = position;
        while (position < attributes.size() && attributes[position] != '=' && !isXmlSpace(attributes[position])) ++position;
        std::string_view name = attributes.substr(nameStart, position - nameStart);
        while (position < attributes.size() && isXmlSpace(attributes[position])) ++position;
        if (position >= attributes.size() || attributes[position] != '=') return std::nullopt;
        ++position;
        while (position < attributes.size() && isXmlSpace(attributes[position])) ++position;
        if (position >= attributes.size() || (attributes[position] != '"' && attributes[position] != '\'')) return std::nullopt;
        char quote = attributes[position++];
        size_t valueEnd = attributes.find(quote, position);
        if (valueEnd == std::string_view::npos) return std::nullopt;
        if (name == key) return attributes.substr(position, valueEnd - position);
        position = valueEnd + 1;
    }
    return std::nullopt;
}

bool isVtkXmlType(std::string_view type) {
    for (const char* known : {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64", "Float32",
                              "Float64", "String", "Bit"})
        if (type == known) return true;
    return false;
}

// Bytes per value of an array type; 0 for String and Bit, which have no fixed size.
uint64_t typeSize(std::string_view type) {
    if (type == "Int8" || type == "UInt8") return 1;
    if (type == "Int16" || type == "UInt16") return 2;
    if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
    if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
    return 0;
}

bool isIntegerType(std::string_view type) { return type.find("Int") != std::string_view::npos; }

// The elements of a Piece whose arrays the piece counts size.
bool isSection(std::string_view name) {
    for (const char* section : {"PointData", "CellData", "Points", "Verts", "Lines", "Strips", "Polys", "FieldData"})
        if (name == section) return true;
    return false;
}

bool isCellSection(std::string_view name) { return name == "Verts" || name == "Lines" || name == "Strips" || name == "Polys"; }

// Unsigned integer of `size` bytes at position (the caller checked the bytes are there).
uint64_t unsignedAt(std::string_view bytes, size_t position, size_t size, bool bigEndian) {
    uint64_t value = 0;
    for (size_t k = 0; k < size; ++k) {
        size_t byteIndex = bigEndian ? k : size - 1 - k;
        value = (value << 8) | static_cast<unsigned char>(bytes[position + byteIndex]);
    }
    return value;
}

// Value of a base64 character as vtkBase64Utilities decodes it ('=' pads count as 0), or -1.
int base64Digit(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return c == '=' ? 0 : -1;
}

// One array's binary data from where its header starts: raw bytes (appended, encoding="raw") or
// base64 text (format="binary", or appended with encoding="base64"), read as VTK reads them.
class EncodedBytes {
public:
    EncodedBytes(std::string_view text, bool base64) : text_(text), base64_(base64) {}

    // The most bytes the text can hold: a size read from the file is checked against this before
    // anything is allocated from it.
    uint64_t capacity() const { return base64_ ? text_.size() / 4 * 3 : text_.size(); }

    // The first `count` bytes, or nothing when the data end first. Base64 is decoded like
    // vtkBase64InputStream: four characters at a time, a character outside the alphabet or a
    // group with a '=' pad ending the stream.
    std::optional<std::string> read(uint64_t count) const {
        if (count > capacity()) return std::nullopt;
        if (!base64_) return std::string(text_.substr(0, count));
        std::string bytes;
        for (size_t group = 0; bytes.size() < count; group += 4) {
            std::string_view characters = text_.substr(group, 4);
            uint32_t bits = 0;
            for (char c : characters) {
                if (base64Digit(c) < 0) return std::nullopt;
                bits = (bits << 6) | static_cast<uint32_t>(base64Digit(c));
            }
            size_t decoded = characters[2] == '=' ? 1 : characters[3] == '=' ? 2 : 3;
            for (size_t k = 0; k < decoded && bytes.size() < count; ++k) bytes += static_cast<char>(bits >> (16 - 8 * k));
            if (decoded < 3 && bytes.size() < count) return std::nullopt;
        }
        return bytes;
    }

    // The data after the first `count` bytes (at most capacity()), as a stream of its own: VTK
    // reads a compressed array's blocks as a new base64 stream starting after its header's text.
    EncodedBytes after(uint64_t count) const {
        size_t used = static_cast<size_t>(base64_ ? (count + 2) / 3 * 4 : count);
        return EncodedBytes(text_.substr(std::min(used, text_.size())), base64_);
    }

private:
    std::string_view text_;
    bool base64_;
};

// How many whitespace-separated words an ASCII array's text holds, and the word at index `wanted`.
struct AsciiWords {
    uint64_t count = 0;
    std::string_view wanted;
};

AsciiWords asciiWords(std::string_view content, std::optional<uint64_t> wanted) {
    AsciiWords words;
    text::LineCursor lines(content, 0, 0);
    while (!lines.atEnd())
        for (std::string_view word : text::splitWords(lines.next())) {
            if (wanted && words.count == *wanted) words.wanted = word;
            ++words.count;
        }
    return words;
}

// The decompressor vtkXMLReader uses for a compressor attribute, or null for one it does not know
// (it then refuses the file itself).
vtkSmartPointer<vtkDataCompressor> compressorNamed(std::string_view name) {
    if (name == "vtkZLibDataCompressor") return vtkSmartPointer<vtkZLibDataCompressor>::New();
    if (name == "vtkLZ4DataCompressor") return vtkSmartPointer<vtkLZ4DataCompressor>::New();
    if (name == "vtkLZMADataCompressor") return vtkSmartPointer<vtkLZMADataCompressor>::New();
    return nullptr;
}

// zlib's best ratio is about 1:1032; a count beyond 1100 values per byte of file is forged.
constexpr uint64_t mostValuesPerCompressedByte = 1100;

class VtpChecker {
public:
    VtpChecker(const std::string& path, std::string bytes) : path_(path), bytes_(std::move(bytes)) {}

    std::string checkAndPatch() {
        // Raw appended data after <AppendedData> is binary; only the XML before it is scanned.
        size_t xmlEnd = bytes_.find("<AppendedData");
        std::vector<XmlStartTag> tags = startTags(std::string_view(bytes_).substr(0, xmlEnd));
        for (const XmlStartTag& tag : tags)
            if (tag.name == "VTKFile") readBinaryLayout(tag);
        // Each value takes at least one byte of file, or 1/1100 of one when compressed: larger
        // counts are forged and would make VTK allocate them.
        countLimit_ = static_cast<uint64_t>(bytes_.size()) * (layout_.compressed ? mostValuesPerCompressedByte : 1) + 16;
        findAppendedData(xmlEnd);
        checkPieces(tags);
        return withPointDataInEveryPiece(tags);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw MeshReadError(path_ + ": " + what); }

    uint64_t count(const XmlStartTag& tag, std::string_view key) const {
        std::optional<std::string_view> value = attributeValue(tag.attributes, key);
        if (!value) return 0;
        std::optional<int64_t> number = text::parseInteger(*value);
        if (!number || *number < 0)
            fail(std::string(tag.name) + " has a bad " + std::string(key) + " " + quotedForMessage(std::string(*value)));
        if (static_cast<uint64_t>(*number) > countLimit_)
            fail(std::string(tag.name) + " declares " + std::string(key) + "=" + std::to_string(*number) +
                 ", more than the file can hold (forged count or truncated file)");
        return static_cast<uint64_t>(*number);
    }

    void checkPiece(const XmlStartTag& piece) const {
        uint64_t points = count(piece, "NumberOfPoints");
        if (points > countLimit_ / 3) fail("Piece declares NumberOfPoints=" + std::to_string(points) + ", more than the file can hold");
        for (const char* cells : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"}) count(piece, cells);
    }

    void checkDataArray(const XmlStartTag& array) const {
        std::optional<std::string_view> type = attributeValue(array.attributes, "type");
        if (!type) fail("DataArray without a type attribute");
        if (!isVtkXmlType(*type)) fail("DataArray has unknown type " + quotedForMessage(std::string(*type)));
        if (attributeValue(array.attributes, "NumberOfComponents")) {
            uint64_t components = count(array, "NumberOfComponents");
            if (components < 1 || components > 4096)
                fail("DataArray has NumberOfComponents=" + std::to_string(components) + " (expected 1 to 4096)");
        }
        count(array, "NumberOfTuples");
        count(array, "offset");
    }

    // Binary data of every array (inline or appended) starts with a header of UInt32 or UInt64
    // words in the file's byte order: its byte count, or (compressed) its block count, block size,
    // last block size and compressed block sizes.
    struct BinaryLayout {
        size_t wordSize = 4;
        bool bigEndian = false;
        bool compressed = false;
        vtkSmartPointer<vtkDataCompressor> decompressor;
    };

    void readBinaryLayout(const XmlStartTag& file) {
        std::optional<std::string_view> headerType = attributeValue(file.attributes, "header_type");
        if (headerType && *headerType != "UInt64" && *headerType != "UInt32")
            fail("unknown header_type " + quotedForMessage(std::string(*headerType)));
        layout_.wordSize = headerType && *headerType == "UInt64" ? 8 : 4;
        layout_.bigEndian = attributeValue(file.attributes, "byte_order") == std::optional<std::string_view>("BigEndian");
        std::optional<std::string_view> compressor = attributeValue(file.attributes, "compressor");
        layout_.compressed = compressor.has_value();
        if (compressor) layout_.decompressor = compressorNamed(*compressor);
    }

    // The appended data start right after the '_' that follows <AppendedData ...> and run to
    // </AppendedData>, as raw bytes or as base64 text.
    void findAppendedData(size_t appendedTag) {
        if (appendedTag == std::string::npos) return;
        std::vector<XmlStartTag> tags = startTags(std::string_view(bytes_).substr(appendedTag, 200));
        if (tags.empty() || tags[0].name != "AppendedData") return;
        size_t marker = bytes_.find('_', appendedTag + tags[0].end);
        if (marker == std::string::npos) return;  // VTK reports the missing marker
        size_t begin = marker + 1;
        size_t endTag = bytes_.rfind("</AppendedData>");
        size_t end = endTag != std::string::npos && endTag > begin ? endTag : bytes_.size();
        appendedText_ = std::string_view(bytes_).substr(begin, end - begin);
        appendedBase64_ = attributeValue(tags[0].attributes, "encoding") == std::optional<std::string_view>("base64");
    }

    // Where an array sits: its piece (null for FieldData outside one) and the section holding it.
    struct ArrayPlace {
        const XmlStartTag* piece = nullptr;
        size_t pieceIndex = 0;
        std::string_view section;
    };

    // The two arrays of a cell section VTK reads (the first of each name), as far as known.
    struct CellSection {
        ArrayPlace place;
        uint64_t cells = 0;
        bool sawOffsets = false, sawConnectivity = false;
        std::optional<uint64_t> lastOffset;          // value number `cells`, when it could be decoded
        std::optional<uint64_t> connectivityValues;
    };

    // Walks the arrays in document order: their attributes, the values each holds against the
    // counts of its piece, and each cell section's last offset against its connectivity.
    void checkPieces(const std::vector<XmlStartTag>& tags) const {
        ArrayPlace place;
        size_t pieces = 0;
        std::optional<CellSection> cells;
        auto finishCells = [&] {
            if (cells) checkOffsetsEndAtConnectivity(*cells);
            cells.reset();
        };
        for (const XmlStartTag& tag : tags) {
            if (tag.name == "Piece") {
                finishCells();
                checkPiece(tag);
                place = ArrayPlace{&tag, pieces++, {}};
            } else if (isSection(tag.name)) {
                finishCells();
                place.section = tag.name;
                if (place.piece && isCellSection(tag.name)) {
                    cells = CellSection();
                    cells->place = place;
                    cells->cells = count(*place.piece, "NumberOf" + std::string(tag.name));
                }
            } else if (tag.name == "DataArray") {
                checkDataArray(tag);
                checkArrayValues(tag, place, cells ? &*cells : nullptr);
            }
        }
        finishCells();
    }

    static std::string arrayLabel(const XmlStartTag& array, const ArrayPlace& place) {
        std::string label = "DataArray";
        if (std::optional<std::string_view> name = attributeValue(array.attributes, "Name")) label += " '" + std::string(*name) + "'";
        if (!place.section.empty()) label += " in " + std::string(place.section);
        if (place.piece) label += " of piece " + std::to_string(place.pieceIndex);
        return label;
    }

    // What the values of an array hold, as far as its encoding tells.
    struct StoredValues {
        uint64_t values = 0;
        bool exact = false;                  // binary: the header gives the number exactly
        std::optional<uint64_t> wantedValue; // the value asked for, when decodable and not negative
    };

    void checkArrayValues(const XmlStartTag& array, const ArrayPlace& place, CellSection* cells) const {
        std::string_view type = attributeValue(array.attributes, "type").value_or("");
        uint64_t valueSize = typeSize(type);
        if (valueSize == 0) return;  // String and Bit arrays: VTK checks them
        std::string label = arrayLabel(array, place);
        std::string_view name = attributeValue(array.attributes, "Name").value_or("");
        bool isOffsets = cells && name == "offsets" && !cells->sawOffsets;
        bool isConnectivity = cells && name == "connectivity" && !cells->sawConnectivity;
        // VTK converts other types to integers and allocates from the result.
        if ((isOffsets || isConnectivity) && !isIntegerType(type))
            fail(label + " has type " + std::string(type) + ", but cell arrays need an integer type");
        std::optional<uint64_t> wanted;
        if (isOffsets && cells->cells > 0) wanted = cells->cells - 1;
        StoredValues stored = storedValues(array, label, type, wanted);
        checkValueCount(label, stored, expectedValues(array, place));
        if (isOffsets) {
            cells->sawOffsets = true;
            cells->lastOffset = stored.wantedValue;
        }
        if (isConnectivity) {
            cells->sawConnectivity = true;
            cells->connectivityValues = stored.values;
        }
    }

    // The values an array holds in its encoding. VTK sizes a connectivity array before it reads
    // it in any format, so an array it cannot read is refused here rather than passed on.
    StoredValues storedValues(const XmlStartTag& array, const std::string& label, std::string_view type,
                              std::optional<uint64_t> wanted) const {
        std::string_view format = attributeValue(array.attributes, "format").value_or("ascii");
        if (format == "ascii") {
            AsciiWords words = asciiWords(inlineText(array), wanted);
            return StoredValues{words.count, false, text::parseInteger<uint64_t>(words.wanted)};
        }
        if (format == "binary") return binaryValues(EncodedBytes(inlineText(array), true), label + ": inline binary data", type, wanted);
        if (format != "appended") fail(label + " has unknown format " + quotedForMessage(std::string(format)));
        if (!appendedText_) fail(label + " is appended, but the file has no <AppendedData> with a '_' before its data");
        if (!attributeValue(array.attributes, "offset")) fail(label + ": appended data is corrupt: no offset attribute");
        uint64_t offset = count(array, "offset");  // in bytes of the raw data, or characters of the base64 text
        if (offset > appendedText_->size()) fail(label + ": appended data is corrupt: offset beyond the data");
        return binaryValues(EncodedBytes(appendedText_->substr(offset), appendedBase64_), label + ": appended data", type, wanted);
    }

    // The text inside an array's element, from its first non-space character to the next tag.
    std::string_view inlineText(const XmlStartTag& array) const {
        if (array.selfClosing) return {};
        std::string_view rest = std::string_view(bytes_).substr(array.end);
        rest = rest.substr(0, rest.find('<'));
        while (!rest.empty() && isXmlSpace(rest.front())) rest.remove_prefix(1);
        while (!rest.empty() && isXmlSpace(rest.back())) rest.remove_suffix(1);
        return rest;
    }

    uint64_t headerWord(const std::string& header, size_t word) const {
        return unsignedAt(header, word * layout_.wordSize, layout_.wordSize, layout_.bigEndian);
    }

    // An integer value of the array's type that is not negative (VTK rejects negative offsets itself).
    std::optional<uint64_t> nonNegativeValue(const std::string& bytes, size_t position, std::string_view type) const {
        uint64_t size = typeSize(type);
        uint64_t raw = unsignedAt(bytes, position, size, layout_.bigEndian);
        bool isSigned = type.rfind("Int", 0) == 0;
        if (isSigned && (raw >> (8 * size - 1)) & 1) return std::nullopt;
        return raw;
    }

    StoredValues binaryValues(const EncodedBytes& data, const std::string& where, std::string_view type,
                              std::optional<uint64_t> wanted) const {
        if (layout_.compressed) return compressedValues(data, where, type, wanted);
        const size_t word = layout_.wordSize;
        uint64_t valueSize = typeSize(type);
        std::optional<std::string> header = data.read(word);
        if (!header) fail(where + " is corrupt: its header runs past the end of the data");
        uint64_t byteCount = headerWord(*header, 0);
        if (byteCount > data.capacity() - word)
            fail(where + " is corrupt: byte count " + std::to_string(byteCount) + " runs past the end of the data");
        checkWholeValues(where, byteCount, type);
        StoredValues stored{byteCount / valueSize, true, std::nullopt};
        if (wanted && *wanted < stored.values)
            if (std::optional<std::string> bytes = data.read(word + (*wanted + 1) * valueSize))
                stored.wantedValue = nonNegativeValue(*bytes, word + *wanted * valueSize, type);
        return stored;
    }

    void checkWholeValues(const std::string& where, uint64_t bytes, std::string_view type) const {
        if (bytes % typeSize(type) != 0)
            fail(where + " is corrupt: " + std::to_string(bytes) + " bytes are not a whole number of " + std::string(type) + " values");
    }

    // A compressed array's block table, checked against the data that is there.
    struct CompressedBlocks {
        EncodedBytes data;                 // the compressed blocks, one after the other
        uint64_t blockSize = 0, lastBlockSize = 0;
        std::vector<uint64_t> starts;      // where each block starts in `data`, and where the last ends
        uint64_t blockCount() const { return starts.size() - 1; }
        uint64_t plainBytes(uint64_t block) const { return block + 1 < blockCount() || lastBlockSize == 0 ? blockSize : lastBlockSize; }
    };

    // VTK allocates the block size table from the block count and each block from its sizes, so
    // all must fit the data in the file before VTK sees them.
    CompressedBlocks compressedBlocks(const EncodedBytes& data, const std::string& where) const {
        auto corrupt = [&](const std::string& what) { fail(where + " is corrupt: " + what); };
        const size_t word = layout_.wordSize;
        std::optional<std::string> table = data.read(3 * word);
        if (!table) corrupt("block table runs past the end of the data");
        uint64_t blockCount = headerWord(*table, 0);
        if (blockCount > (data.capacity() - 3 * word) / word) corrupt("block table runs past the end of the data");
        CompressedBlocks blocks{data.after((3 + blockCount) * word), headerWord(*table, 1), headerWord(*table, 2), {0}};
        if (blockCount > 0 && (blocks.blockSize == 0 || blocks.lastBlockSize > blocks.blockSize)) corrupt("inconsistent block sizes");
        if (blockCount == 0 && blocks.lastBlockSize != 0) corrupt("inconsistent block sizes");
        if (blockCount > 1 && blocks.blockSize > std::numeric_limits<uint64_t>::max() / blockCount) corrupt("inconsistent block sizes");
        std::optional<std::string> header = data.read((3 + blockCount) * word);
        if (!header) corrupt("block table runs past the end of the data");
        for (uint64_t block = 0; block < blockCount; ++block) {
            uint64_t size = headerWord(*header, 3 + block);
            if (size > blocks.data.capacity() - blocks.starts.back()) corrupt("compressed blocks run past the end of the data");
            blocks.starts.push_back(blocks.starts.back() + size);
        }
        return blocks;
    }

    StoredValues compressedValues(const EncodedBytes& data, const std::string& where, std::string_view type,
                                  std::optional<uint64_t> wanted) const {
        CompressedBlocks blocks = compressedBlocks(data, where);
        uint64_t plainBytes = blocks.blockCount() == 0 ? 0 : (blocks.blockCount() - 1) * blocks.blockSize + blocks.plainBytes(blocks.blockCount() - 1);
        checkWholeValues(where, plainBytes, type);
        uint64_t valueSize = typeSize(type);
        StoredValues stored{plainBytes / valueSize, true, std::nullopt};
        if (wanted && *wanted < stored.values)
            if (std::optional<std::string> bytes = decompressedRange(blocks, *wanted * valueSize, valueSize))
                stored.wantedValue = nonNegativeValue(*bytes, 0, type);
        return stored;
    }

    // Bytes [begin, begin + count) of a compressed array, decompressing only the blocks holding
    // them; nothing when a block does not decompress (VTK then reports the damage).
    std::optional<std::string> decompressedRange(const CompressedBlocks& blocks, uint64_t begin, uint64_t count) const {
        if (!layout_.decompressor) return std::nullopt;
        std::string range;
        for (uint64_t block = begin / blocks.blockSize; range.size() < count; ++block) {
            std::optional<std::string> compressed = blocks.data.read(blocks.starts[block + 1]);
            if (!compressed) return std::nullopt;
            std::string plain(blocks.plainBytes(block), '\0');
            const auto* source = reinterpret_cast<const unsigned char*>(compressed->data()) + blocks.starts[block];
            size_t sourceSize = blocks.starts[block + 1] - blocks.starts[block];
            if (layout_.decompressor->Uncompress(source, sourceSize, reinterpret_cast<unsigned char*>(plain.data()), plain.size()) != plain.size())
                return std::nullopt;
            uint64_t from = range.empty() ? begin - block * blocks.blockSize : 0;
            range += plain.substr(from, count - range.size());
        }
        return range;
    }

    // How many values an array must hold by the counts of its piece: exactly `exact`, or at least
    // `minimum` (connectivity: a point per cell at least); `source` names the count for messages.
    struct ExpectedValues {
        std::optional<uint64_t> exact;
        uint64_t minimum = 0;
        std::string source;
    };

    ExpectedValues expectedValues(const XmlStartTag& array, const ArrayPlace& place) const {
        uint64_t components = attributeValue(array.attributes, "NumberOfComponents") ? count(array, "NumberOfComponents") : 1;
        std::string times = components > 1 ? " times " + std::to_string(components) + " components" : "";
        auto exactly = [&](uint64_t number, const std::string& source) {
            return ExpectedValues{number * components, 0, source + times};
        };
        auto counted = [&](const XmlStartTag& tag, const std::string& key) {
            uint64_t number = count(tag, key);
            return exactly(number, key + "=" + std::to_string(number));
        };
        if (place.section == "FieldData")
            return attributeValue(array.attributes, "NumberOfTuples") ? counted(array, "NumberOfTuples") : ExpectedValues{};
        if (!place.piece) return {};
        const XmlStartTag& piece = *place.piece;
        if (place.section == "Points" || place.section == "PointData") return counted(piece, "NumberOfPoints");
        if (place.section == "CellData") {
            uint64_t cells = count(piece, "NumberOfVerts") + count(piece, "NumberOfLines") + count(piece, "NumberOfStrips") +
                             count(piece, "NumberOfPolys");
            return exactly(cells, "the piece's " + std::to_string(cells) + " cells");
        }
        if (!isCellSection(place.section)) return {};
        std::string key = "NumberOf" + std::string(place.section);
        // Offsets hold one value per cell: VTK 9.1 puts the leading 0 in front itself.
        if (attributeValue(array.attributes, "Name") == std::optional<std::string_view>("offsets")) return counted(piece, key);
        uint64_t cells = count(piece, key);
        return ExpectedValues{std::nullopt, cells, key + "=" + std::to_string(cells)};
    }

    // VTK reads as many values as the counts give and ignores the rest, so more is data dropped
    // without a word. Binary headers state their size, which must then match exactly; short ASCII
    // arrays VTK reports itself.
    void checkValueCount(const std::string& label, const StoredValues& stored, const ExpectedValues& expected) const {
        std::string holds = label + " holds " + std::to_string(stored.values) + " values";
        if (expected.exact && stored.values > *expected.exact)
            fail(holds + " but " + expected.source + " gives " + std::to_string(*expected.exact) + " (is a count or NumberOfComponents too small?)");
        if (!stored.exact) return;
        if (expected.exact && stored.values < *expected.exact)
            fail(holds + " but " + expected.source + " gives " + std::to_string(*expected.exact) + " (truncated array or wrong count)");
        if (stored.values < expected.minimum) fail(holds + ", fewer than the cells of " + expected.source + " need");
    }

    // VTK sizes a cell section's connectivity by its last offset before reading it and reads no
    // more than that: a forged offset (4294967295 in a 1 kB file) is a 32 GB allocation, a small
    // one drops connectivity. VTK refuses offsets that fall from one cell to the next, so a last
    // offset equal to the connectivity length bounds them all.
    void checkOffsetsEndAtConnectivity(const CellSection& cells) const {
        if (!cells.lastOffset || !cells.connectivityValues || *cells.lastOffset == *cells.connectivityValues) return;
        fail(std::string(cells.place.section) + " of piece " + std::to_string(cells.place.pieceIndex) + ": the last offset is " +
             std::to_string(*cells.lastOffset) + " but the connectivity array holds " + std::to_string(*cells.connectivityValues) +
             " values (forged offset, or a cell count that does not fit the offsets)");
    }

    // Inserts "<PointData/>" after the start tag of every non-empty piece that has no PointData.
    std::string withPointDataInEveryPiece(const std::vector<XmlStartTag>& tags) {
        std::string patched;
        size_t copied = 0;
        for (size_t t = 0; t < tags.size(); ++t) {
            if (tags[t].name != "Piece" || tags[t].selfClosing) continue;
            bool hasPointData = false;
            for (size_t inner = t + 1; inner < tags.size() && tags[inner].name != "Piece"; ++inner)
                hasPointData = hasPointData || tags[inner].name == "PointData";
            if (hasPointData) continue;
            patched.append(bytes_, copied, tags[t].end - copied);
            patched += "<PointData/>";
            copied = tags[t].end;
        }
        if (copied == 0) return std::move(bytes_);
        patched.append(bytes_, copied, std::string::npos);
        return patched;
    }

    const std::string& path_;
    std::string bytes_;
    uint64_t countLimit_ = 0;
    BinaryLayout layout_;
    std::optional<std::string_view> appendedText_;  // the data after <AppendedData ...>'s '_'
    bool appendedBase64_ = false;
};

}  // namespace

std::string prepareVtpForVtk(const std::string& path) { return VtpChecker(path, readFileBytes(path)).checkAndPatch(); }

}  // namespace conescope
