// readPly: one walk over a PLY file that checks every element and keeps positions and faces.
#include "io/PlyFormat.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/PositionMerging.h"
#include "io/TextEncoding.h"
#include "io/TextScanning.h"

namespace conescope {

namespace {

using text::isNumber;
using text::LineCursor;
using text::parseInteger;
using text::splitWords;

// A header line longer than this is taken for binary data, not for a PLY header.
constexpr size_t longestHeaderLine = 4000;

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
    std::vector<std::string> linesReadAsComments;  // "line 3: 'Created by ...'"
};

// What the mesh is made of: the vertex element's x, y, z and the face element's index list.
struct MeshProperties {
    const PlyElement* vertices = nullptr;
    const PlyProperty* coordinates[3] = {nullptr, nullptr, nullptr};
    const PlyElement* faces = nullptr;
    const PlyProperty* faceIndices = nullptr;
};

class PlyParser {
public:
    // `convertedFrom` names the encoding the text was converted from, if it was (TextEncoding.h).
    PlyParser(const std::string& path, std::string_view text, const std::string& convertedFrom, const ProgressCallback& progress,
              std::vector<uint64_t>* exactKeys)
        : path_(path), bytes_(text), convertedFrom_(convertedFrom), progress_(progress, text.size()), exactKeys_(exactKeys) {}

    Mesh parse(std::vector<std::string>& notes) {
        header_ = parseHeader();
        // Converting turned the binary data into other bytes; an ascii body came through as text.
        if (!convertedFrom_.empty() && header_.format != PlyFormat::Ascii)
            fail("binary PLY in a " + convertedFrom_ + " text file: its data was re-encoded as text and is lost");
        findMeshProperties();
        if (header_.format == PlyFormat::Ascii)
            readAsciiBody();
        else
            readBinaryBody();
        // After the walk: a count in the header that is too small shifts the lines, and the message
        // about the data left over names the cause, not the face it made short.
        if (!shortFace_.empty()) fail(shortFace_.lineNumber, shortFace_.what);
        if (!clusterIds_.empty()) mesh_.faceArrays["cluster_id"] = std::move(clusterIds_);
        const std::vector<std::string>& comments = header_.linesReadAsComments;
        if (comments.size() == 1) notes.push_back("read a header line without a PLY keyword as a comment (" + comments[0] + ")");
        if (comments.size() > 1)
            notes.push_back("read " + std::to_string(comments.size()) + " header lines without a PLY keyword as comments (" +
                            comments[0] + " is the first)");
        return std::move(mesh_);
    }

private:
    // "path:line: what", or "path: what" for line 0 (binary data has no lines).
    [[noreturn]] void fail(size_t lineNumber, const std::string& what) const {
        throw MeshReadError(path_ + (lineNumber ? ":" + std::to_string(lineNumber) : std::string()) + ": " + what);
    }
    [[noreturn]] void fail(const std::string& what) const { fail(0, what); }

    // Turk's ply.c (and VTK's copy) split words at spaces and tabs only and stop a line at a NUL
    // byte, so a form feed or NUL would make other readers see other words ("y\f" is not "y").
    void checkCharacters(std::string_view line, size_t lineNumber) const {
        for (char c : line)
            if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\r')
                fail(lineNumber, "unexpected control character " + quotedForMessage(std::string(1, c)));
    }

    PlyHeader parseHeader() {
        PlyHeader header;
        LineCursor lines(bytes_, 0, 0);
        bool sawFormat = false;
        // The last line without a PLY keyword, until an element line follows it.
        size_t unknownLineNumber = 0;
        std::string_view unknownLine;
        while (true) {
            if (lines.atEnd()) fail(lines.lineNumber(), "PLY header has no end_header line (truncated or not PLY)");
            std::string_view line = lines.next();
            if (line.size() > longestHeaderLine) fail(lines.lineNumber(), "PLY header line is too long (not PLY?)");
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
                unknownLineNumber = 0;
            } else if (keyword == "property") {
                if (header.elements.empty()) fail(lines.lineNumber(), "PLY property before any element");
                // assimp ends an element's property list at such a line and drops the properties after it.
                if (unknownLineNumber)
                    fail(unknownLineNumber, "unexpected PLY header line " + quotedForMessage(std::string(unknownLine)) +
                                                " among the properties of element '" + header.elements.back().name + "'");
                header.elements.back().properties.push_back(parseProperty(words, lines.lineNumber()));
            } else if (keyword == "end_header") {
                // The data starts after end_header's line end; a file ending right here has none.
                if (!lines.lastLineHadNewline()) fail(lines.lineNumber(), "file ends right after end_header (no data)");
                break;
            } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
                // A line without a keyword is a comment where assimp 5.2.5 skips it (see PlyFormat.h).
                if (!sawFormat)
                    fail(lines.lineNumber(), "unexpected PLY header line " + quotedForMessage(std::string(line)) + " before the format line");
                unknownLineNumber = lines.lineNumber();
                unknownLine = line;
                header.linesReadAsComments.push_back("line " + std::to_string(unknownLineNumber) + ": " +
                                                     quotedForMessage(std::string(line)));
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

    // The mesh needs one vertex element with scalar x, y, z and one face element with an integer
    // index list; a second element of either name would leave it unclear which one is meant.
    void findMeshProperties() {
        for (const PlyElement& element : header_.elements) {
            if (element.name != "vertex" && element.name != "face") continue;
            const PlyElement*& found = element.name == "vertex" ? parts_.vertices : parts_.faces;
            if (found) fail("PLY header declares element '" + element.name + "' twice");
            found = &element;
        }
        if (!parts_.vertices) fail("PLY file has no vertex element");
        if (parts_.vertices->count > std::numeric_limits<uint32_t>::max())
            fail("PLY vertex count " + std::to_string(parts_.vertices->count) + " exceeds what 32-bit indices can address");
        const char* const names[] = {"x", "y", "z"};
        for (int k = 0; k < 3; ++k) {
            parts_.coordinates[k] = findProperty(*parts_.vertices, names[k]);
            if (!parts_.coordinates[k]) fail("PLY vertex element lacks property '" + std::string(names[k]) + "'");
            if (parts_.coordinates[k]->isList) fail("PLY vertex property '" + std::string(names[k]) + "' is a list, expected a single value");
        }
        if (!parts_.faces || parts_.faces->count == 0) fail("PLY file has no face element (no faces)");
        parts_.faceIndices = findProperty(*parts_.faces, "vertex_indices");
        if (!parts_.faceIndices) parts_.faceIndices = findProperty(*parts_.faces, "vertex_index");
        if (!parts_.faceIndices || !parts_.faceIndices->isList)
            fail("PLY face element lacks the list property 'vertex_indices'");
        if (!parts_.faceIndices->valueType.isInteger) fail("PLY face indices must have an integer type");
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

    void checkIndex(int64_t index, uint64_t face, size_t lineNumber) const {
        const uint64_t vertexCount = parts_.vertices->count;
        if (index >= 0 && static_cast<uint64_t>(index) < vertexCount) return;
        fail(lineNumber, "face " + std::to_string(face) + " uses vertex " + std::to_string(index) + " but there are only " +
                             std::to_string(vertexCount) + " vertices");
    }

    // A coordinate the mesh can keep as a float: nan, inf and numbers beyond float range are errors.
    double coordinate(double value, const std::string& shown, uint64_t vertex, size_t lineNumber) const {
        if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max()))
            fail(lineNumber, "PLY vertex " + std::to_string(vertex) + " has a coordinate that is not a finite float: " + shown);
        return value;
    }

    // Called after each element instance: a vertex's position or a face's corners join the mesh.
    void finishElement(const PlyElement& element, uint64_t index, const glm::dvec3& position, size_t lineNumber) {
        if (&element == parts_.vertices) {
            mesh_.positions.emplace_back(position);
            addExactPosition(exactKeys_, position);
        }
        if (&element != parts_.faces) return;
        const size_t corners = mesh_.faceVertices.size() - mesh_.faceStarts.back();
        if (corners < 3 && shortFace_.empty())
            shortFace_ = {lineNumber, "PLY face " + std::to_string(index) + " has " + std::to_string(corners) + " vertices (needs at least 3)"};
        if (mesh_.faceVertices.size() > std::numeric_limits<uint32_t>::max())
            fail(lineNumber, "more face corners than 32-bit offsets can address");
        mesh_.faceStarts.push_back(uint32_t(mesh_.faceVertices.size()));
    }

    // "PLY face 5", for messages only (built when one is needed).
    static std::string elementName(const PlyElement& element, uint64_t index) {
        return "PLY " + element.name + " " + std::to_string(index);
    }

    void readAsciiBody() {
        LineCursor lines(bytes_, header_.bodyOffset, header_.lineCount);
        std::vector<std::string_view> words;
        for (const PlyElement& element : header_.elements) {
            for (uint64_t i = 0; i < element.count; ++i) {
                progress_.at(lines.position());
                if (lines.atEnd())
                    fail(lines.lineNumber(), "file ends early: expected " + elementName(element, i) + " of " +
                                                 std::to_string(element.count) + " (truncated file or wrong count)");
                std::string_view line = lines.next();
                // Its last number could have been cut short.
                if (!lines.lastLineHadNewline())
                    fail(lines.lineNumber(), elementName(element, i) + " is not ended by a newline (truncated file?)");
                checkCharacters(line, lines.lineNumber());
                text::splitWords(line, words);
                readAsciiElement(element, i, words, lines.lineNumber());
            }
        }
        checkNothingAfterLastElement(lines);
    }

    // "8 vertex, 5 face": the counts a message about data beyond them quotes.
    std::string declaredCounts() const {
        std::string counts;
        for (const PlyElement& element : header_.elements)
            counts += (counts.empty() ? "" : ", ") + std::to_string(element.count) + " " + element.name;
        return counts;
    }

    // Readers stop after the counts the header declares, so a count that is too small would drop
    // the elements after it without a word. Blank lines at the end are harmless.
    void checkNothingAfterLastElement(LineCursor& lines) const {
        while (!lines.atEnd()) {
            if (splitWords(lines.next()).empty()) continue;
            fail(lines.lineNumber(), "data after the last element the header declares (" + declaredCounts() +
                                         "): is a count in the header too small?");
        }
    }

    // The binary counterpart: readers stop after the declared elements here too. Only space, tab,
    // CR and LF may follow them, as some exporters end even a binary file with a newline. Any other
    // byte counts as lost data, however few: a face with an empty list is a single count byte, and
    // a remainder too short for any element still means the counts and the data disagree. Bytes
    // that are all whitespace could in principle be an element too, but its values would be absurd
    // (a list of 10 or 32 indices, each 0x0a0a0a0a or 0x20202020, or coordinates near 1e-19), so
    // padding is the reading taken.
    void checkNothingAfterLastBinaryElement(size_t declaredEnd) const {
        if (bytes_.find_first_not_of(" \t\r\n", declaredEnd) == std::string_view::npos) return;
        const size_t extra = bytes_.size() - declaredEnd;
        fail("data after the last element the header declares (" + declaredCounts() + "): " + std::to_string(extra) +
             (extra == 1 ? " byte" : " bytes") + " from offset " + std::to_string(declaredEnd) +
             " to the end of the " + std::to_string(bytes_.size()) + "-byte file; is a count in the header too small?");
    }

    static bool isClusterId(const PlyElement& element, const PlyProperty& property) {
        return element.name == "face" && !property.isList && property.name == "cluster_id";
    }

    // A value of an integer type must be an integer: "0.5" for an int would be read as 0 elsewhere.
    void checkAsciiValue(std::string_view word, const PlyType& type, const PlyElement& element, uint64_t elementIndex,
                         size_t lineNumber) const {
        if (type.isInteger ? parseInteger(word).has_value() : isNumber(word)) return;
        fail(lineNumber, elementName(element, elementIndex) + ": expected " + (type.isInteger ? "an integer" : "a number") + ", found " +
                             quotedForMessage(std::string(word)));
    }

    void readAsciiElement(const PlyElement& element, uint64_t elementIndex, const std::vector<std::string_view>& words,
                          size_t lineNumber) {
        glm::dvec3 position(0.0);
        size_t word = 0;
        for (const PlyProperty& property : element.properties) {
            if (word >= words.size()) fail(lineNumber, elementName(element, elementIndex) + " has too few values");
            if (!property.isList) {
                checkAsciiValue(words[word], property.valueType, element, elementIndex, lineNumber);
                for (int k = 0; k < 3; ++k)
                    if (&property == parts_.coordinates[k])
                        position[k] = coordinate(*text::parseNumber(words[word]), quotedForMessage(std::string(words[word])),
                                                 elementIndex, lineNumber);
                if (isClusterId(element, property)) clusterIds_.push_back(*text::parseNumber(words[word]));
                ++word;
                continue;
            }
            std::optional<int64_t> count = parseInteger(words[word++]);
            if (!count || *count < 0)
                fail(lineNumber, elementName(element, elementIndex) + ": bad list length " + quotedForMessage(std::string(words[word - 1])));
            if (static_cast<uint64_t>(*count) > words.size() - word)
                fail(lineNumber, elementName(element, elementIndex) + " lists " + std::to_string(words.size() - word) + " of its " +
                                     std::to_string(*count) + " values");
            for (int64_t k = 0; k < *count; ++k, ++word) {
                if (&property != parts_.faceIndices) {
                    checkAsciiValue(words[word], property.valueType, element, elementIndex, lineNumber);
                    continue;
                }
                std::optional<int64_t> index = parseInteger(words[word]);
                if (!index)
                    fail(lineNumber, elementName(element, elementIndex) + ": expected a vertex index, found " + quotedForMessage(std::string(words[word])));
                checkIndex(*index, elementIndex, lineNumber);
                mesh_.faceVertices.push_back(uint32_t(*index));
            }
        }
        finishElement(element, elementIndex, position, lineNumber);
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

    void readBinaryBody() {
        const bool bigEndian = header_.format == PlyFormat::BinaryBigEndian;
        size_t position = header_.bodyOffset;
        auto require = [&](uint64_t bytes, const PlyElement& element, uint64_t i) {
            if (bytes > bytes_.size() - position)
                fail("PLY " + element.name + " " + std::to_string(i) + " of " + std::to_string(element.count) +
                     " is cut off at byte " + std::to_string(bytes_.size()) + " (truncated file or wrong count)");
        };
        for (const PlyElement& element : header_.elements) {
            for (uint64_t i = 0; i < element.count; ++i) {
                progress_.at(position);
                glm::dvec3 vertex(0.0);
                for (const PlyProperty& property : element.properties) {
                    if (!property.isList) {
                        require(property.valueType.size, element, i);
                        for (int k = 0; k < 3; ++k) {
                            if (&property != parts_.coordinates[k]) continue;
                            const double value = binaryNumber(position, property.valueType, bigEndian);
                            vertex[k] = coordinate(value, std::to_string(value), i, 0);
                        }
                        if (isClusterId(element, property)) clusterIds_.push_back(binaryNumber(position, property.valueType, bigEndian));
                        position += property.valueType.size;
                        continue;
                    }
                    require(property.countType.size, element, i);
                    int64_t count = binaryInteger(position, property.countType, bigEndian);
                    position += property.countType.size;
                    if (count < 0)
                        fail("PLY " + element.name + " " + std::to_string(i) + " has negative list length " + std::to_string(count));
                    require(static_cast<uint64_t>(count) * property.valueType.size, element, i);
                    for (int64_t k = 0; &property == parts_.faceIndices && k < count; ++k) {
                        const int64_t index = binaryInteger(position + k * property.valueType.size, property.valueType, bigEndian);
                        checkIndex(index, i, 0);
                        mesh_.faceVertices.push_back(uint32_t(index));
                    }
                    position += static_cast<size_t>(count) * property.valueType.size;
                }
                finishElement(element, i, vertex, 0);
            }
        }
        checkNothingAfterLastBinaryElement(position);
    }

    const std::string& path_;
    std::string_view bytes_;
    const std::string& convertedFrom_;
    ReadProgress progress_;
    PlyHeader header_;
    MeshProperties parts_;
    Mesh mesh_;
    std::vector<double> clusterIds_;
    std::vector<uint64_t>* exactKeys_;
    struct Problem {
        size_t lineNumber = 0;
        std::string what;
        bool empty() const { return what.empty(); }
    } shortFace_;  // the first face of fewer than 3 vertices
};

}  // namespace

Mesh readPly(const std::string& path, std::vector<std::string>& notes, const ProgressCallback& progress, std::vector<uint64_t>* exactKeys) {
    Utf8Text text = utf8WithoutByteOrderMark(readFileBytes(path), path);
    if (!text.convertedFrom.empty()) notes.push_back(conversionNote(text));
    return PlyParser(path, text.text, text.convertedFrom, progress, exactKeys).parse(notes);
}

}  // namespace conescope
