// checkPlyFile: a full structural walk of a PLY file before vtkPLYReader sees it.
#include "io/HeaderChecks.h"

#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/TextScanning.h"

namespace conescope {

namespace {

using text::isNumber;
using text::LineCursor;
using text::parseInteger;
using text::splitWords;

// vtkPLY reads ASCII lines into a fixed 4096-byte buffer; longer lines would be split silently.
constexpr size_t longestPlyLine = 4000;

struct PlyType {
    size_t size = 0;
    bool isInteger = false;
    bool isSigned = false;
};

std::optional<PlyType> plyType(std::string_view name) {
    if (name == "char" || name == "int8") return PlyType{1, true, true};
    if (name == "uchar" || name == "uint8") return PlyType{1, true, false};
    if (name == "short" || name == "int16") return PlyType{2, true, true};
    if (name == "ushort" || name == "uint16") return PlyType{2, true, false};
    if (name == "int" || name == "int32") return PlyType{4, true, true};
    if (name == "uint" || name == "uint32") return PlyType{4, true, false};
    if (name == "float" || name == "float32") return PlyType{4, false, true};
    if (name == "double" || name == "float64") return PlyType{8, false, true};
    return std::nullopt;
}

struct PlyProperty {
    std::string name;
    bool isList = false;
    PlyType countType;
    PlyType valueType;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    size_t bodyOffset = 0;   // first byte after "end_header\n"
    size_t lineCount = 0;    // lines in the header, so body line numbers continue from it
};

class PlyChecker {
public:
    PlyChecker(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

    // The face element's cluster_id values, gathered by check().
    std::vector<double> clusterIds;

    void check() {
        PlyHeader header = parseHeader();
        checkPropertiesVtkReads(header);
        for (const PlyElement& element : header.elements)
            if (element.name == "vertex") vertexCount_ = element.count;
        if (header.format == PlyFormat::Ascii)
            checkAsciiBody(header);
        else
            checkBinaryBody(header);
    }

private:
    [[noreturn]] void fail(size_t lineNumber, const std::string& what) const {
        throw MeshReadError(path_ + ":" + std::to_string(lineNumber) + ": " + what);
    }
    [[noreturn]] void fail(const std::string& what) const { throw MeshReadError(path_ + ": " + what); }

    // vtkPLY splits words at spaces and tabs only and stops a line at a NUL byte, so a form feed
    // or NUL would make it see other words than this check does ("y\f" is not "y").
    void checkCharacters(std::string_view line, size_t lineNumber) const {
        for (char c : line)
            if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\r')
                fail(lineNumber, "unexpected control character " + quotedForMessage(std::string(1, c)));
    }

    PlyHeader parseHeader() {
        PlyHeader header;
        LineCursor lines(bytes_, 0, 0);
        bool sawFormat = false;
        while (true) {
            if (lines.atEnd()) fail(lines.lineNumber(), "PLY header has no end_header line (truncated or not PLY)");
            std::string_view line = lines.next();
            if (line.size() > longestPlyLine) fail(lines.lineNumber(), "PLY header line is too long (not PLY?)");
            checkCharacters(line, lines.lineNumber());
            std::vector<std::string_view> words = splitWords(line);
            std::string_view keyword = words.empty() ? std::string_view() : words[0];
            if (lines.lineNumber() == 1) {
                if (keyword != "ply" || words.size() != 1)
                    fail(1, "not a PLY file: first line is " + quotedForMessage(std::string(line)));
            } else if (keyword == "format") {
                std::string_view format = words.size() > 1 ? words[1] : std::string_view();
                if (format == "ascii") header.format = PlyFormat::Ascii;
                else if (format == "binary_little_endian") header.format = PlyFormat::BinaryLittleEndian;
                else if (format == "binary_big_endian") header.format = PlyFormat::BinaryBigEndian;
                else fail(lines.lineNumber(), "unknown PLY format " + quotedForMessage(std::string(format)));
                sawFormat = true;
            } else if (keyword == "element") {
                header.elements.push_back(parseElement(words, lines.lineNumber()));
            } else if (keyword == "property") {
                if (header.elements.empty()) fail(lines.lineNumber(), "PLY property before any element");
                header.elements.back().properties.push_back(parseProperty(words, lines.lineNumber()));
            } else if (keyword == "end_header") {
                // vtkPLY reads lines up to '\n'; without it, it runs off the end and frees twice.
                if (!lines.lastLineHadNewline()) fail(lines.lineNumber(), "file ends right after end_header (no data)");
                break;
            } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
                fail(lines.lineNumber(), "unexpected PLY header line " + quotedForMessage(std::string(line)));
            }
        }
        if (!sawFormat) fail(lines.lineNumber(), "PLY header has no format line");
        for (const PlyElement& element : header.elements)
            if (element.count > 0 && element.properties.empty())
                fail(lines.lineNumber(), "PLY element '" + element.name + "' has no properties");
        header.bodyOffset = lines.position();
        header.lineCount = lines.lineNumber();
        return header;
    }

    static const PlyProperty* findProperty(const PlyElement& element, const std::string& name) {
        for (const PlyProperty& property : element.properties)
            if (property.name == name) return &property;
        return nullptr;
    }

    // vtkPLYReader assumes vertex x, y, z and a face index list exist, and that the optional
    // properties it knows (normals, colours, texture coordinates) have the usual shape; a missing
    // coordinate or a list where it expects a scalar makes it crash, so both are errors here.
    void checkPropertiesVtkReads(const PlyHeader& header) const {
        const PlyElement* vertices = nullptr;
        const PlyElement* faces = nullptr;
        for (const PlyElement& element : header.elements) {
            if (element.name == "vertex") vertices = &element;
            if (element.name == "face") faces = &element;
        }
        if (!vertices) fail("PLY file has no vertex element");
        for (const char* coordinate : {"x", "y", "z"})
            if (!findProperty(*vertices, coordinate)) fail("PLY vertex element lacks property '" + std::string(coordinate) + "'");
        if (!faces || faces->count == 0) fail("PLY file has no face element (no faces)");
        const PlyProperty* indices = findProperty(*faces, "vertex_indices");
        if (!indices) indices = findProperty(*faces, "vertex_index");
        if (!indices || !indices->isList) fail("PLY face element lacks the list property 'vertex_indices'");
        static const char* const vertexScalars[] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha",
                                                    "u", "v", "s", "t", "texture_u", "texture_v"};
        for (const char* name : vertexScalars)
            if (const PlyProperty* property = findProperty(*vertices, name); property && property->isList)
                fail("PLY vertex property '" + std::string(name) + "' is a list, expected a single value");
        for (const char* name : {"red", "green", "blue", "intensity"})
            if (const PlyProperty* property = findProperty(*faces, name); property && property->isList)
                fail("PLY face property '" + std::string(name) + "' is a list, expected a single value");
        if (const PlyProperty* texture = findProperty(*faces, "texcoord"); texture && !texture->isList)
            fail("PLY face property 'texcoord' must be a list");
    }

    PlyElement parseElement(const std::vector<std::string_view>& words, size_t lineNumber) {
        if (words.size() != 3) fail(lineNumber, "PLY element line needs a name and a count");
        std::optional<int64_t> count = parseInteger(words[2]);
        if (!count || *count < 0)
            fail(lineNumber, "bad PLY element count " + quotedForMessage(std::string(words[2])));
        PlyElement element;
        element.name = std::string(words[1]);
        element.count = static_cast<uint64_t>(*count);
        return element;
    }

    PlyProperty parseProperty(const std::vector<std::string_view>& words, size_t lineNumber) {
        PlyProperty property;
        if (words.size() == 5 && words[1] == "list") {
            std::optional<PlyType> countType = plyType(words[2]), valueType = plyType(words[3]);
            if (!countType || !valueType)
                fail(lineNumber, "unknown PLY list type " + quotedForMessage(std::string(words[2]) + " " + std::string(words[3])));
            if (!countType->isInteger) fail(lineNumber, "PLY list count type must be an integer type");
            property.isList = true;
            property.countType = *countType;
            property.valueType = *valueType;
            property.name = std::string(words[4]);
            return property;
        }
        if (words.size() != 3) fail(lineNumber, "PLY property line needs a type and a name");
        std::optional<PlyType> type = plyType(words[1]);
        if (!type) fail(lineNumber, "unknown PLY property type " + quotedForMessage(std::string(words[1])));
        property.valueType = *type;
        property.name = std::string(words[2]);
        return property;
    }

    // vtkPLYReader takes the faces' corner indices from this list.
    static bool isFaceIndexList(const PlyElement& element, const PlyProperty& property) {
        return element.name == "face" && property.isList &&
               (property.name == "vertex_indices" || property.name == "vertex_index");
    }

    void checkIndex(int64_t index, const PlyElement& element, uint64_t elementIndex, size_t lineNumber) const {
        if (index >= 0 && static_cast<uint64_t>(index) < vertexCount_) return;
        std::string what = element.name + " " + std::to_string(elementIndex) + " uses vertex " + std::to_string(index) +
                           " but there are only " + std::to_string(vertexCount_) + " vertices";
        if (lineNumber) fail(lineNumber, what);
        fail(what);
    }

    void checkAsciiBody(const PlyHeader& header) {
        LineCursor lines(bytes_, header.bodyOffset, header.lineCount);
        for (const PlyElement& element : header.elements) {
            for (uint64_t i = 0; i < element.count; ++i) {
                std::string elementName = "PLY " + element.name + " " + std::to_string(i);
                if (lines.atEnd())
                    fail(lines.lineNumber(), "file ends early: expected " + elementName + " of " +
                                                 std::to_string(element.count) + " (truncated file or wrong count)");
                std::string_view line = lines.next();
                if (!lines.lastLineHadNewline())
                    fail(lines.lineNumber(), elementName + " is not ended by a newline (truncated file?)");
                if (line.size() > longestPlyLine) fail(lines.lineNumber(), elementName + ": line is too long for VTK's PLY reader");
                checkCharacters(line, lines.lineNumber());
                checkAsciiElement(element, i, splitWords(line), lines.lineNumber());
            }
        }
        checkNothingAfterLastElement(header, lines);
    }

    // "8 vertex, 5 face": the counts a message about data beyond them quotes.
    static std::string declaredCounts(const PlyHeader& header) {
        std::string counts;
        for (const PlyElement& element : header.elements)
            counts += (counts.empty() ? "" : ", ") + std::to_string(element.count) + " " + element.name;
        return counts;
    }

    // vtkPLY stops reading after the counts the header declares, so a count that is too small would
    // drop the elements after it without a word. Blank lines at the end are harmless.
    void checkNothingAfterLastElement(const PlyHeader& header, LineCursor& lines) const {
        while (!lines.atEnd()) {
            if (splitWords(lines.next()).empty()) continue;
            fail(lines.lineNumber(), "data after the last element the header declares (" + declaredCounts(header) +
                                         "): is a count in the header too small?");
        }
    }

    // The binary counterpart: vtkPLY stops after the declared elements here too. Only space, tab,
    // CR and LF may follow them, as some exporters end even a binary file with a newline. Any other
    // byte counts as lost data, however few: a face with an empty list is a single count byte, and
    // a remainder too short for any element still means the counts and the data disagree. Bytes
    // that are all whitespace could in principle be an element too, but its values would be absurd
    // (a list of 10 or 32 indices, each 0x0a0a0a0a or 0x20202020, or coordinates near 1e-19), so
    // padding is the reading taken.
    void checkNothingAfterLastBinaryElement(const PlyHeader& header, size_t declaredEnd) const {
        if (bytes_.find_first_not_of(" \t\r\n", declaredEnd) == std::string_view::npos) return;
        const size_t extra = bytes_.size() - declaredEnd;
        fail("data after the last element the header declares (" + declaredCounts(header) + "): " + std::to_string(extra) +
             (extra == 1 ? " byte" : " bytes") + " from offset " + std::to_string(declaredEnd) +
             " to the end of the " + std::to_string(bytes_.size()) + "-byte file; is a count in the header too small?");
    }

    static bool isClusterId(const PlyElement& element, const PlyProperty& property) {
        return element.name == "face" && !property.isList && property.name == "cluster_id";
    }

    void checkAsciiElement(const PlyElement& element, uint64_t elementIndex, const std::vector<std::string_view>& words,
                           size_t lineNumber) {
        std::string elementName = "PLY " + element.name + " " + std::to_string(elementIndex);
        size_t word = 0;
        for (const PlyProperty& property : element.properties) {
            if (word >= words.size()) fail(lineNumber, elementName + " has too few values");
            if (!property.isList) {
                if (!isNumber(words[word]))
                    fail(lineNumber, elementName + ": expected a number, found " + quotedForMessage(std::string(words[word])));
                if (isClusterId(element, property)) clusterIds.push_back(*text::parseNumber(words[word]));
                ++word;
                continue;
            }
            std::optional<int64_t> count = parseInteger(words[word++]);
            if (!count || *count < 0)
                fail(lineNumber, elementName + ": bad list length " + quotedForMessage(std::string(words[word - 1])));
            if (static_cast<uint64_t>(*count) > words.size() - word)
                fail(lineNumber, elementName + " lists " + std::to_string(words.size() - word) + " of its " +
                                     std::to_string(*count) + " values");
            for (int64_t k = 0; k < *count; ++k, ++word) {
                if (isFaceIndexList(element, property)) {
                    std::optional<int64_t> index = parseInteger(words[word]);
                    if (!index)
                        fail(lineNumber, elementName + ": expected a vertex index, found " +
                                             quotedForMessage(std::string(words[word])));
                    checkIndex(*index, element, elementIndex, lineNumber);
                } else if (!isNumber(words[word])) {
                    fail(lineNumber, elementName + ": expected a number, found " + quotedForMessage(std::string(words[word])));
                }
            }
        }
    }

    // Reads one integer of the given type at position (the caller checked the bytes are there).
    int64_t binaryInteger(size_t position, const PlyType& type, bool bigEndian) const {
        uint64_t raw = 0;
        for (size_t k = 0; k < type.size; ++k) {
            size_t byteIndex = bigEndian ? k : type.size - 1 - k;
            raw = (raw << 8) | static_cast<unsigned char>(bytes_[position + byteIndex]);
        }
        if (type.isSigned && type.size < 8 && (raw >> (8 * type.size - 1)) & 1) raw |= ~uint64_t(0) << (8 * type.size);
        return static_cast<int64_t>(raw);
    }

    // Reads one number of any PLY type at position (the caller checked the bytes are there).
    double binaryNumber(size_t position, const PlyType& type, bool bigEndian) const {
        if (type.isInteger) return double(binaryInteger(position, type, bigEndian));
        const uint64_t raw = uint64_t(binaryInteger(position, PlyType{type.size, true, false}, bigEndian));
        if (type.size == 4) {
            const uint32_t bits = uint32_t(raw);
            float value = 0.0f;
            std::memcpy(&value, &bits, 4);
            return value;
        }
        double value = 0.0;
        std::memcpy(&value, &raw, 8);
        return value;
    }

    void checkBinaryBody(const PlyHeader& header) {
        bool bigEndian = header.format == PlyFormat::BinaryBigEndian;
        size_t position = header.bodyOffset;
        auto require = [&](uint64_t bytes, const PlyElement& element, uint64_t i) {
            if (bytes > bytes_.size() - position)
                fail("PLY " + element.name + " " + std::to_string(i) + " of " + std::to_string(element.count) +
                     " is cut off at byte " + std::to_string(bytes_.size()) + " (truncated file or wrong count)");
        };
        for (const PlyElement& element : header.elements) {
            for (uint64_t i = 0; i < element.count; ++i) {
                for (const PlyProperty& property : element.properties) {
                    if (!property.isList) {
                        require(property.valueType.size, element, i);
                        if (isClusterId(element, property)) clusterIds.push_back(binaryNumber(position, property.valueType, bigEndian));
                        position += property.valueType.size;
                        continue;
                    }
                    require(property.countType.size, element, i);
                    int64_t count = binaryInteger(position, property.countType, bigEndian);
                    position += property.countType.size;
                    if (count < 0)
                        fail("PLY " + element.name + " " + std::to_string(i) + " has negative list length " + std::to_string(count));
                    require(static_cast<uint64_t>(count) * property.valueType.size, element, i);
                    if (isFaceIndexList(element, property)) {
                        if (!property.valueType.isInteger) fail("PLY face indices must have an integer type");
                        for (int64_t k = 0; k < count; ++k)
                            checkIndex(binaryInteger(position + k * property.valueType.size, property.valueType, bigEndian),
                                       element, i, 0);
                    }
                    position += static_cast<size_t>(count) * property.valueType.size;
                }
            }
        }
        checkNothingAfterLastBinaryElement(header, position);
    }

    const std::string& path_;
    std::string_view bytes_;
    uint64_t vertexCount_ = 0;
};

}  // namespace

std::vector<double> checkPlyFile(const std::string& path) {
    std::string bytes = readFileBytes(path);
    PlyChecker checker(path, bytes);
    checker.check();
    return std::move(checker.clusterIds);
}

}  // namespace conescope
