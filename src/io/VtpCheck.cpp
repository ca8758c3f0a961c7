// prepareVtpForVtk: checks the XML header of a .vtp file and works around crashes of VTK 9.1's
// vtkXMLPolyDataReader before it reads the file.
//
// Crashes found by mutating valid files:
//  - a cell-data array that fails to read (too short, a non-number) when the piece has no
//    <PointData> element: the error message dereferences the missing element. Adding an empty
//    <PointData/> turns the crash into VTK's ordinary "Cannot read cell data array" error.
//  - a <DataArray> with an unknown type in <FieldData>, and piece counts near 2^31 (NumberOfPolys):
//    rejected here.
#include "io/HeaderChecks.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

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

class VtpChecker {
public:
    VtpChecker(const std::string& path, std::string bytes) : path_(path), bytes_(std::move(bytes)) {}

    std::string checkAndPatch() {
        // Raw appended data after <AppendedData> is binary; only the XML before it is scanned.
        size_t xmlEnd = bytes_.find("<AppendedData");
        std::string_view xml = std::string_view(bytes_).substr(0, xmlEnd);
        std::vector<XmlStartTag> tags = startTags(xml);
        bool compressed = false;
        for (const XmlStartTag& tag : tags)
            if (tag.name == "VTKFile") compressed = attributeValue(tag.attributes, "compressor").has_value();
        // Each value takes at least one byte of file, or 1/1100 of one when zlib-compressed (its
        // best ratio is about 1:1032): larger counts are forged and would make VTK allocate them.
        countLimit_ = static_cast<uint64_t>(bytes_.size()) * (compressed ? 1100 : 1) + 16;
        for (const XmlStartTag& tag : tags) {
            if (tag.name == "Piece") checkPiece(tag);
            if (tag.name == "DataArray") checkDataArray(tag);
        }
        checkAppendedData(tags, xmlEnd);
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
        checkAsciiOffsets(array);
    }

    // VTK sizes a cell section's connectivity by its last offset before reading it, so a forged
    // offset (4294967295 in a 1 kB file) is a 32 GB allocation. Offsets are connectivity indices:
    // no larger than the number of values the file can hold.
    void checkAsciiOffsets(const XmlStartTag& array) const {
        if (array.selfClosing || attributeValue(array.attributes, "Name") != std::optional<std::string_view>("offsets")) return;
        std::optional<std::string_view> format = attributeValue(array.attributes, "format");
        if (format && *format != "ascii") return;
        std::string_view rest = std::string_view(bytes_).substr(array.end);
        std::string_view content = rest.substr(0, rest.find('<'));
        size_t index = 0;
        text::LineCursor lines(content, 0, 0);
        while (!lines.atEnd())
            for (std::string_view word : text::splitWords(lines.next())) {
                std::optional<int64_t> value = text::parseInteger(word);
                if (!value) continue;  // VTK reports non-numbers itself
                if (*value < 0 || static_cast<uint64_t>(*value) > countLimit_)
                    fail("offsets value " + std::to_string(index) + " is " + std::to_string(*value) +
                         ", more connectivity than the file can hold (forged offset or truncated file)");
                ++index;
            }
    }

    // Raw appended data: each array starts with a header of UInt32 or UInt64 words giving its byte
    // count, or (compressed) its block count, block sizes and compressed block sizes. VTK 9.1 trusts
    // these words and crashes on inconsistent ones, so they must fit the data that is there and,
    // where the piece counts say how many bytes an array holds, agree with that.
    void checkAppendedData(const std::vector<XmlStartTag>& tags, size_t appendedTag) const {
        if (appendedTag == std::string::npos) return;
        const XmlStartTag* file = nullptr;
        for (const XmlStartTag& tag : tags)
            if (tag.name == "VTKFile") file = &tag;
        std::vector<XmlStartTag> appendedTags = startTags(std::string_view(bytes_).substr(appendedTag, 200));
        const XmlStartTag* appended = appendedTags.empty() || appendedTags[0].name != "AppendedData" ? nullptr : &appendedTags[0];
        if (!file || !appended) return;
        std::optional<std::string_view> encoding = attributeValue(appended->attributes, "encoding");
        if (encoding && *encoding != "raw") return;  // base64 is decoded and length-checked by VTK
        size_t marker = bytes_.find('_', appendedTag + appended->end);
        if (marker == std::string::npos) fail("AppendedData has no '_' marker before its data");
        AppendedLayout layout;
        layout.begin = marker + 1;
        size_t endTag = bytes_.rfind("</AppendedData>");
        layout.end = endTag != std::string::npos && endTag > layout.begin ? endTag : bytes_.size();
        std::optional<std::string_view> headerType = attributeValue(file->attributes, "header_type");
        layout.wordSize = headerType && *headerType == "UInt64" ? 8 : 4;
        if (headerType && *headerType != "UInt64" && *headerType != "UInt32")
            fail("unknown header_type " + quotedForMessage(std::string(*headerType)));
        std::optional<std::string_view> byteOrder = attributeValue(file->attributes, "byte_order");
        layout.bigEndian = byteOrder && *byteOrder == "BigEndian";
        layout.compressed = attributeValue(file->attributes, "compressor").has_value();

        const XmlStartTag* piece = nullptr;
        std::string_view section;
        for (const XmlStartTag& tag : tags) {
            if (tag.name == "Piece") {
                piece = &tag;
            } else if (tag.name == "DataArray") {
                if (attributeValue(tag.attributes, "format") != std::optional<std::string_view>("appended")) continue;
                checkAppendedArray(tag, layout, expectedValues(tag, piece, section));
            } else {
                section = tag.name;
            }
        }
    }

    // How many values an array must hold, from the piece counts: exactly `exact` (or
    // `exactAlternative`: offsets hold one value per cell, or one more in newer files), or at least
    // `minimum` (connectivity: a point per cell at least).
    struct ExpectedValues {
        std::optional<uint64_t> exact;
        std::optional<uint64_t> exactAlternative;
        uint64_t minimum = 0;
    };

    ExpectedValues expectedValues(const XmlStartTag& array, const XmlStartTag* piece, std::string_view section) const {
        ExpectedValues expected;
        uint64_t components = attributeValue(array.attributes, "NumberOfComponents") ? count(array, "NumberOfComponents") : 1;
        if (section == "FieldData") {
            if (attributeValue(array.attributes, "NumberOfTuples")) expected.exact = count(array, "NumberOfTuples") * components;
            return expected;
        }
        if (!piece) return expected;
        uint64_t points = count(*piece, "NumberOfPoints");
        uint64_t cells = count(*piece, "NumberOfVerts") + count(*piece, "NumberOfLines") + count(*piece, "NumberOfStrips") +
                         count(*piece, "NumberOfPolys");
        if (section == "Points" || section == "PointData") expected.exact = points * components;
        if (section == "CellData") expected.exact = cells * components;
        if (section == "Verts" || section == "Lines" || section == "Strips" || section == "Polys") {
            uint64_t cellsOfType = count(*piece, "NumberOf" + std::string(section));
            std::string_view name = attributeValue(array.attributes, "Name").value_or("");
            if (name == "offsets") {
                expected.exact = cellsOfType;
                expected.exactAlternative = cellsOfType + 1;
            } else {
                expected.minimum = cellsOfType;
            }
        }
        return expected;
    }

    struct AppendedLayout {
        size_t begin = 0, end = 0;
        size_t wordSize = 4;
        bool bigEndian = false;
        bool compressed = false;
    };

    uint64_t headerWord(const AppendedLayout& layout, size_t position) const {
        uint64_t value = 0;
        for (size_t k = 0; k < layout.wordSize; ++k) {
            size_t byteIndex = layout.bigEndian ? k : layout.wordSize - 1 - k;
            value = (value << 8) | static_cast<unsigned char>(bytes_[position + byteIndex]);
        }
        return value;
    }

    static uint64_t typeSize(std::string_view type) {
        if (type == "Int8" || type == "UInt8") return 1;
        if (type == "Int16" || type == "UInt16") return 2;
        if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
        if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
        return 0;  // String, Bit: no fixed size per value
    }

    void checkAppendedArray(const XmlStartTag& array, const AppendedLayout& layout, const ExpectedValues& expected) const {
        std::string name(attributeValue(array.attributes, "Name").value_or("(unnamed)"));
        auto corrupt = [&](const std::string& what) { fail("appended data of array '" + name + "' is corrupt: " + what); };
        if (!attributeValue(array.attributes, "offset")) corrupt("no offset attribute");
        uint64_t available = layout.end - layout.begin;
        uint64_t offset = count(array, "offset");
        if (offset > available || available - offset < layout.wordSize) corrupt("offset beyond the data");
        size_t header = layout.begin + static_cast<size_t>(offset);
        uint64_t remaining = available - offset;
        uint64_t valueSize = typeSize(attributeValue(array.attributes, "type").value_or(""));
        auto checkSize = [&](uint64_t bytes) {
            if (valueSize == 0) return;  // String and Bit arrays: VTK checks them
            bool exactMatch = !expected.exact || bytes == *expected.exact * valueSize ||
                              (expected.exactAlternative && bytes == *expected.exactAlternative * valueSize);
            if (!exactMatch || bytes < expected.minimum * valueSize)
                corrupt(std::to_string(bytes) + " bytes do not match the counts of the piece");
        };

        if (!layout.compressed) {
            uint64_t byteCount = headerWord(layout, header);
            if (byteCount > remaining - layout.wordSize) corrupt("byte count runs past the end of the data");
            checkSize(byteCount);
            return;
        }
        uint64_t blockCount = headerWord(layout, header);
        if (blockCount > remaining / layout.wordSize || remaining / layout.wordSize - blockCount < 3)
            corrupt("block table runs past the end of the data");
        uint64_t blockSize = headerWord(layout, header + layout.wordSize);
        uint64_t lastBlockSize = headerWord(layout, header + 2 * layout.wordSize);
        if (blockCount > 0 && (blockSize == 0 || lastBlockSize > blockSize)) corrupt("inconsistent block sizes");
        if (blockCount == 0 && lastBlockSize != 0) corrupt("inconsistent block sizes");
        uint64_t uncompressedBytes = blockCount == 0 ? 0 : (blockCount - 1) * blockSize + (lastBlockSize ? lastBlockSize : blockSize);
        checkSize(uncompressedBytes);
        uint64_t compressedBytes = 0;
        uint64_t dataRoom = remaining - (3 + blockCount) * layout.wordSize;
        for (uint64_t block = 0; block < blockCount; ++block) {
            compressedBytes += headerWord(layout, header + (3 + block) * layout.wordSize);
            if (compressedBytes > dataRoom) corrupt("compressed blocks run past the end of the data");
        }
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
};

}  // namespace

std::string prepareVtpForVtk(const std::string& path) { return VtpChecker(path, readFileBytes(path)).checkAndPatch(); }

}  // namespace conescope
