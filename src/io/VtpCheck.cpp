// prepareVtpForVtk: checks a .vtp file before VTK 9.1's vtkXMLPolyDataReader reads it, because
// that reader crashes on some damaged files and drops or allocates from others without a word (the
// cases, found by mutating valid files, are listed in docs/dev/architecture.md, "Readers"). The XML is
// read by expat (VtpXml.cpp) and the arrays decoded in VtpEncoding.cpp; this file checks every
// array, in every encoding, against the counts of its piece, and adds an empty <PointData/> where
// its absence would crash VTK's error message.
#include "io/HeaderChecks.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/TextScanning.h"
#include "io/VtpEncoding.h"
#include "io/VtpXml.h"

namespace conescope {

namespace {

// zlib's best ratio is about 1:1032; a count beyond 1100 values per byte of file is forged.
constexpr uint64_t mostValuesPerCompressedByte = 1100;

// The file as the checks see it: its bytes, its XML, and how its binary data are laid out.
struct VtpFile {
    const std::string& path;
    std::string_view bytes;
    VtpXml xml;
    BinaryLayout layout;
    uint64_t countLimit = 0;                    // no count in the file can be larger
    std::optional<std::string_view> appended;  // the data after <AppendedData ...>'s '_'
    bool appendedBase64 = false;
};

[[noreturn]] void fail(const VtpFile& file, const VtpElement& element, const std::string& what) {
    throw MeshReadError(file.path + ":" + std::to_string(element.line) + ": " + what);
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && isVtkSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isVtkSpace(text.back())) text.remove_suffix(1);
    return text;
}

// The elements of a Piece whose arrays the piece counts size.
bool isSection(std::string_view name) {
    for (const char* section : {"PointData", "CellData", "Points", "Verts", "Lines", "Strips", "Polys", "FieldData"})
        if (name == section) return true;
    return false;
}

bool isCellSection(std::string_view name) { return name == "Verts" || name == "Lines" || name == "Strips" || name == "Polys"; }

const VtpElement* parentOf(const VtpFile& file, const VtpElement& element) {
    return element.parent == noElement ? nullptr : &file.xml.elements[element.parent];
}

// A count attribute: absent is 0; not a number, negative or beyond what the file can hold is refused.
uint64_t count(const VtpFile& file, const VtpElement& element, std::string_view key) {
    std::optional<std::string_view> value = element.attribute(key);
    if (!value) return 0;
    std::optional<int64_t> number = text::parseInteger(*value);
    if (!number || *number < 0)
        fail(file, element, element.name + " has a bad " + std::string(key) + " " + quotedForMessage(std::string(*value)));
    if (static_cast<uint64_t>(*number) > file.countLimit)
        fail(file, element, element.name + " declares " + std::string(key) + "=" + std::to_string(*number) +
                                ", more than the file can hold (forged count or truncated file)");
    return static_cast<uint64_t>(*number);
}

void checkPiece(const VtpFile& file, const VtpElement& piece) {
    uint64_t points = count(file, piece, "NumberOfPoints");
    if (points > file.countLimit / 3)
        fail(file, piece, "Piece declares NumberOfPoints=" + std::to_string(points) + ", more than the file can hold");
    for (const char* cells : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"}) count(file, piece, cells);
}

void checkArrayAttributes(const VtpFile& file, const VtpElement& array) {
    std::optional<std::string_view> type = array.attribute("type");
    if (!type) fail(file, array, "DataArray without a type attribute");
    if (!isVtkXmlType(*type)) fail(file, array, "DataArray has unknown type " + quotedForMessage(std::string(*type)));
    if (array.attribute("NumberOfComponents")) {
        uint64_t components = count(file, array, "NumberOfComponents");
        if (components < 1 || components > 4096)
            fail(file, array, "DataArray has NumberOfComponents=" + std::to_string(components) + " (expected 1 to 4096)");
    }
    count(file, array, "NumberOfTuples");
    count(file, array, "offset");
}

// Where an array sits: the section holding it and that section's piece (either may be missing).
struct ArrayPlace {
    const VtpElement* section = nullptr;
    const VtpElement* piece = nullptr;
    size_t pieceIndex = 0;
    std::string_view sectionName() const { return section ? std::string_view(section->name) : std::string_view(); }
};

// The two arrays of a cell section VTK reads (the first of each name), as far as known.
struct CellSection {
    ArrayPlace place;
    uint64_t cells = 0;
    bool sawOffsets = false, sawConnectivity = false;
    std::optional<uint64_t> lastOffset;  // value number `cells`, when it could be decoded
    std::optional<uint64_t> connectivityValues;
};

std::string arrayLabel(const VtpElement& array, const ArrayPlace& place) {
    std::string label = "DataArray";
    if (std::optional<std::string_view> name = array.attribute("Name")) label += " '" + std::string(*name) + "'";
    if (place.section) label += " in " + place.section->name;
    if (place.piece) label += " of piece " + std::to_string(place.pieceIndex);
    return label;
}

// An inline array's text exactly as VTK reads it: the bytes after the start tag up to the first
// '<' or '&', which must be all of the element's content, since VTK does not read it as XML.
std::string_view inlineText(const VtpFile& file, const VtpElement& array, const std::string& label) {
    std::string_view vtkReads = textVtkReadsAfterTag(file.bytes, array);
    if (array.selfClosed) {
        if (!trimmed(vtkReads).empty()) fail(file, array, label + " is self-closed, but text follows it that VTK would read as its data");
        return {};
    }
    if (vtkReads.size() != contentBytes(file.bytes, array).size())
        fail(file, array, label + ": its data holds markup or a reference ('<' or '&': a comment, CDATA, an entity); VTK reads "
                                  "an array's data as the bytes stand, so it must be plain text");
    return trimmed(vtkReads);
}

// VTK reads every array with an offset attribute from the appended data, whatever its format says
// (a damaged format="appended" made it read ASCII-checked data as compressed blocks, and divide by
// a block size of 0); a file saying otherwise is refused.
void requireAppendedFormatWithOffset(const VtpFile& file, const VtpElement& array, const std::string& label) {
    std::optional<std::string_view> format = array.attribute("format");
    if (!array.attribute("offset") || format == std::optional<std::string_view>("appended")) return;
    fail(file, array, label + " has an offset attribute but format " + (format ? quotedForMessage(std::string(*format)) : "(none)") +
                          ": VTK reads an array with an offset from the appended data, so its format must be 'appended'");
}

// The values an array holds in its encoding. VTK sizes a connectivity array before it reads it
// in any format, so an array it cannot read is refused here rather than passed on.
StoredValues storedValues(const VtpFile& file, const VtpElement& array, const std::string& label, std::string_view type,
                          std::optional<uint64_t> wanted) {
    requireAppendedFormatWithOffset(file, array, label);
    std::string_view format = array.attribute("format").value_or("ascii");
    std::string where = file.path + ":" + std::to_string(array.line) + ": " + label;
    if (format == "ascii") return asciiValues(inlineText(file, array, label), wanted);
    if (format == "binary")
        return binaryValues(file.layout, EncodedBytes(inlineText(file, array, label), true), where + ": inline binary data", type, wanted);
    if (format != "appended") fail(file, array, label + " has unknown format " + quotedForMessage(std::string(format)));
    if (!file.appended) fail(file, array, label + " is appended, but the file has no <AppendedData> with a '_' before its data");
    if (!array.attribute("offset")) fail(file, array, label + ": appended data is corrupt: no offset attribute");
    uint64_t offset = count(file, array, "offset");  // in bytes of the raw data, or characters of the base64 text
    if (offset > file.appended->size()) fail(file, array, label + ": appended data is corrupt: offset beyond the data");
    return binaryValues(file.layout, EncodedBytes(file.appended->substr(offset), file.appendedBase64), where + ": appended data", type,
                        wanted);
}

// How many values an array must hold by the counts of its piece: exactly `exact`, or at least
// `minimum` (connectivity: a point per cell at least); `source` names the count for messages.
struct ExpectedValues {
    std::optional<uint64_t> exact;
    uint64_t minimum = 0;
    std::string source;
};

ExpectedValues expectedValues(const VtpFile& file, const VtpElement& array, const ArrayPlace& place) {
    uint64_t components = array.attribute("NumberOfComponents") ? count(file, array, "NumberOfComponents") : 1;
    std::string times = components > 1 ? " times " + std::to_string(components) + " components" : "";
    auto exactly = [&](uint64_t number, const std::string& source) { return ExpectedValues{number * components, 0, source + times}; };
    auto counted = [&](const VtpElement& element, const std::string& key) {
        uint64_t number = count(file, element, key);
        return exactly(number, key + "=" + std::to_string(number));
    };
    std::string_view section = place.sectionName();
    if (section == "FieldData") return array.attribute("NumberOfTuples") ? counted(array, "NumberOfTuples") : ExpectedValues{};
    if (!place.piece) return {};
    const VtpElement& piece = *place.piece;
    if (section == "Points" || section == "PointData") return counted(piece, "NumberOfPoints");
    if (section == "CellData") {
        uint64_t cells = count(file, piece, "NumberOfVerts") + count(file, piece, "NumberOfLines") + count(file, piece, "NumberOfStrips") +
                         count(file, piece, "NumberOfPolys");
        return exactly(cells, "the piece's " + std::to_string(cells) + " cells");
    }
    if (!isCellSection(section)) return {};
    std::string key = "NumberOf" + std::string(section);
    // Offsets hold one value per cell: VTK 9.1 puts the leading 0 in front itself.
    if (array.attribute("Name") == std::optional<std::string_view>("offsets")) return counted(piece, key);
    uint64_t cells = count(file, piece, key);
    return ExpectedValues{std::nullopt, cells, key + "=" + std::to_string(cells)};
}

// VTK reads as many values as the counts give and ignores the rest, so more is data dropped
// without a word. Binary headers state their size, which must then match exactly; short ASCII
// arrays VTK reports itself.
void checkValueCount(const VtpFile& file, const VtpElement& array, const std::string& label, const StoredValues& stored,
                     const ExpectedValues& expected) {
    std::string holds = label + " holds " + std::to_string(stored.values) + " values";
    if (expected.exact && stored.values > *expected.exact)
        fail(file, array,
             holds + " but " + expected.source + " gives " + std::to_string(*expected.exact) + " (is a count or NumberOfComponents too small?)");
    if (!stored.exact) return;
    if (expected.exact && stored.values < *expected.exact)
        fail(file, array, holds + " but " + expected.source + " gives " + std::to_string(*expected.exact) + " (truncated array or wrong count)");
    if (stored.values < expected.minimum) fail(file, array, holds + ", fewer than the cells of " + expected.source + " need");
}

void checkArrayValues(const VtpFile& file, const VtpElement& array, const ArrayPlace& place, CellSection* cells) {
    std::string_view type = array.attribute("type").value_or("");
    if (typeSize(type) == 0) return;  // String and Bit arrays: VTK checks them
    std::string label = arrayLabel(array, place);
    std::string_view name = array.attribute("Name").value_or("");
    bool isOffsets = cells && name == "offsets" && !cells->sawOffsets;
    bool isConnectivity = cells && name == "connectivity" && !cells->sawConnectivity;
    // VTK converts other types to integers and allocates from the result.
    if ((isOffsets || isConnectivity) && !isIntegerType(type))
        fail(file, array, label + " has type " + std::string(type) + ", but cell arrays need an integer type");
    std::optional<uint64_t> wanted;
    if (isOffsets && cells->cells > 0) wanted = cells->cells - 1;
    StoredValues stored = storedValues(file, array, label, type, wanted);
    checkValueCount(file, array, label, stored, expectedValues(file, array, place));
    if (isOffsets) {
        cells->sawOffsets = true;
        cells->lastOffset = stored.wantedValue;
    }
    if (isConnectivity) {
        cells->sawConnectivity = true;
        cells->connectivityValues = stored.values;
    }
}

// VTK sizes a cell section's connectivity by its last offset before reading it and reads no more
// than that: a forged offset (4294967295 in a 1 kB file) is a 32 GB allocation, a small one drops
// connectivity. VTK refuses offsets that fall from one cell to the next, so a last offset equal to
// the connectivity length bounds them all.
void checkOffsetsEndAtConnectivity(const VtpFile& file, const CellSection& cells) {
    if (!cells.lastOffset || !cells.connectivityValues || *cells.lastOffset == *cells.connectivityValues) return;
    fail(file, *cells.place.section,
         cells.place.section->name + " of piece " + std::to_string(cells.place.pieceIndex) + ": the last offset is " +
             std::to_string(*cells.lastOffset) + " but the connectivity array holds " + std::to_string(*cells.connectivityValues) +
             " values (forged offset, or a cell count that does not fit the offsets)");
}

// The section an array stands in and that section's piece, as VTK looks them up: each the parent
// of the one before. `pieceIndex` numbers the pieces met so far.
ArrayPlace arrayPlace(const VtpFile& file, const VtpElement& array, const std::vector<size_t>& pieceIndex) {
    const VtpElement* section = parentOf(file, array);
    if (!section || !isSection(section->name)) return {};
    const VtpElement* piece = parentOf(file, *section);
    if (!piece || piece->name != "Piece") return ArrayPlace{section, nullptr, 0};
    return ArrayPlace{section, piece, pieceIndex[section->parent]};
}

// Walks the elements in document order: each piece's counts, each array's attributes and the
// values it holds against the counts of its piece, and each cell section's last offset against
// its connectivity once the walk has left the section.
void checkPiecesAndArrays(const VtpFile& file) {
    const std::vector<VtpElement>& elements = file.xml.elements;
    std::vector<size_t> pieceIndex(elements.size(), 0);
    size_t pieces = 0;
    std::optional<CellSection> cells;
    auto finishCells = [&] {
        if (cells) checkOffsetsEndAtConnectivity(file, *cells);
        cells.reset();
    };
    for (size_t e = 0; e < elements.size(); ++e) {
        const VtpElement& element = elements[e];
        if (cells && element.tagBegin >= cells->place.section->contentEnd) finishCells();
        const VtpElement* parent = parentOf(file, element);
        if (element.name == "Piece") {
            checkPiece(file, element);
            pieceIndex[e] = pieces++;
        } else if (isCellSection(element.name) && parent && parent->name == "Piece") {
            finishCells();
            cells = CellSection();
            cells->place = ArrayPlace{&element, parent, pieceIndex[element.parent]};
            cells->cells = count(file, *parent, "NumberOf" + element.name);
        } else if (element.name == "DataArray") {
            checkArrayAttributes(file, element);
            checkArrayValues(file, element, arrayPlace(file, element, pieceIndex), cells && cells->place.section == parent ? &*cells : nullptr);
        }
    }
    finishCells();
}

// Inserts "<PointData/>" after the start tag of every piece with content that has no PointData.
std::string withPointDataInEveryPiece(std::string bytes, const VtpXml& xml) {
    std::vector<bool> hasPointData(xml.elements.size(), false);
    for (const VtpElement& element : xml.elements)
        if (element.name == "PointData" && element.parent != noElement) hasPointData[element.parent] = true;
    std::string patched;
    size_t copied = 0;
    for (size_t e = 0; e < xml.elements.size(); ++e) {
        const VtpElement& piece = xml.elements[e];
        if (piece.name != "Piece" || piece.selfClosed || hasPointData[e]) continue;
        patched.append(bytes, copied, piece.tagEnd - copied);
        patched += "<PointData/>";
        copied = piece.tagEnd;
    }
    if (copied == 0) return bytes;
    patched.append(bytes, copied, std::string::npos);
    return patched;
}

// The layout of binary data and the count limit, from the root element.
void readRootAttributes(VtpFile& file) {
    if (file.xml.elements.empty()) return;
    const VtpElement& root = file.xml.elements.front();
    std::optional<std::string_view> headerType = root.attribute("header_type");
    if (headerType && *headerType != "UInt64" && *headerType != "UInt32")
        fail(file, root, "unknown header_type " + quotedForMessage(std::string(*headerType)));
    file.layout = binaryLayout(headerType, root.attribute("byte_order"), root.attribute("compressor"));
    // Each value takes at least one byte of file, or 1/1100 of one when compressed: larger counts
    // are forged and would make VTK allocate them.
    file.countLimit = static_cast<uint64_t>(file.bytes.size()) * (file.layout.compressed ? mostValuesPerCompressedByte : 1) + 16;
}

void findAppendedData(VtpFile& file) {
    if (file.xml.appendedData == noElement) return;
    const VtpElement& appendedData = file.xml.elements[file.xml.appendedData];
    file.appended = appendedDataBytes(file.bytes, appendedData);
    // vtkXMLDataParser switches to raw bytes for encoding="raw" only; anything else is base64.
    file.appendedBase64 = appendedData.attribute("encoding") != std::optional<std::string_view>("raw");
}

}  // namespace

std::string prepareVtpForVtk(const std::string& path) {
    std::string bytes = readFileBytes(path);
    VtpFile file{path, bytes, readVtpXml(path, bytes), {}, 0, std::nullopt, false};
    readRootAttributes(file);
    findAppendedData(file);
    checkPiecesAndArrays(file);
    return withPointDataInEveryPiece(std::move(bytes), file.xml);
}

}  // namespace conescope
