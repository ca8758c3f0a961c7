#include "io/OffFormat.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/PositionMerging.h"

namespace conescope {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// One meaningful line: its text with any '#' comment removed, and its 1-based number.
struct OffLine {
    std::string_view content;
    size_t number = 0;
};

// Walks the text line by line, skipping blank and comment-only lines. OFF writers put one vertex
// or one face per line, so line-wise parsing lets us ignore per-element extras (colours, normals)
// and name the exact line of a problem.
class OffLineReader {
public:
    explicit OffLineReader(std::string_view text) : text_(text) {
        // A UTF-8 byte order mark from Windows editors is not part of the keyword.
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") position_ = 3;
    }

    std::optional<OffLine> next() {
        while (position_ < text_.size()) {
            size_t end = text_.find('\n', position_);
            if (end == std::string_view::npos) end = text_.size();
            std::string_view content = text_.substr(position_, end - position_);
            size_t number = ++linesConsumed_;
            position_ = end + 1;
            size_t comment = content.find('#');
            if (comment != std::string_view::npos) content = content.substr(0, comment);
            for (char c : content)
                if (!isBlank(c)) return OffLine{content, number};
        }
        return std::nullopt;
    }

    // Bytes not yet consumed: an upper bound on what the remaining elements can occupy.
    size_t remainingBytes() const { return position_ < text_.size() ? text_.size() - position_ : 0; }
    // Where an unexpected end of file is reported: the last line of the text.
    size_t lastLineNumber() const { return linesConsumed_; }

private:
    std::string_view text_;
    size_t position_ = 0;
    size_t linesConsumed_ = 0;
};

// Whitespace-separated tokens of one line.
class TokenReader {
public:
    explicit TokenReader(std::string_view line) : rest_(line) {}

    // Next token, or an empty view when the line has no more.
    std::string_view next() {
        size_t start = 0;
        while (start < rest_.size() && isBlank(rest_[start])) ++start;
        size_t end = start;
        while (end < rest_.size() && !isBlank(rest_[end])) ++end;
        std::string_view token = rest_.substr(start, end - start);
        rest_ = rest_.substr(end);
        return token;
    }

private:
    std::string_view rest_;
};

std::string asText(std::string_view token) { return quotedForMessage(std::string(token)); }

// Locale-independent (std::from_chars): a GUI that called setlocale() must not turn "0.5" into 0.
// The whole token must be the number; a leading '+' is allowed.
template <typename Number>
std::optional<Number> parseWhole(std::string_view token) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    Number value = 0;
    auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || token.empty()) return std::nullopt;
    return value;
}

std::optional<double> parseReal(std::string_view token) { return parseWhole<double>(token); }
std::optional<int64_t> parseInteger(std::string_view token) { return parseWhole<int64_t>(token); }

// What the header keyword ([ST][C][N][4][n]OFF) says about the vertex lines.
struct OffKeyword {
    bool homogeneous = false;     // "4": x y z w, divided through by w
    bool dimensionFollows = false;  // "n": the next number is the dimension
};

std::optional<OffKeyword> parseKeyword(std::string_view token) {
    OffKeyword keyword;
    if (token.substr(0, 2) == "ST") token.remove_prefix(2);
    if (token.substr(0, 1) == "C") token.remove_prefix(1);
    if (token.substr(0, 1) == "N") token.remove_prefix(1);
    if (token.substr(0, 1) == "4") {
        keyword.homogeneous = true;
        token.remove_prefix(1);
    }
    if (token.substr(0, 1) == "n") {
        keyword.dimensionFollows = true;
        token.remove_prefix(1);
    }
    if (token != "OFF") return std::nullopt;
    return keyword;
}

struct OffCounts {
    uint64_t vertices = 0;
    uint64_t faces = 0;
};

class OffParser {
public:
    OffParser(std::string_view text, const std::string& sourceName, std::vector<uint64_t>* exactKeys)
        : lines_(text), sourceName_(sourceName), exactKeys_(exactKeys) {}

    Mesh parse() {
        OffCounts counts = parseHeader();
        Mesh mesh;
        // Safe: checkCountsFitText bounded both counts by the text length.
        mesh.positions.reserve(counts.vertices);
        mesh.faceStarts.reserve(counts.faces + 1);
        mesh.faceVertices.reserve(counts.faces * 3);
        for (uint64_t v = 0; v < counts.vertices; ++v) mesh.positions.push_back(parseVertex(v, counts.vertices));
        for (uint64_t f = 0; f < counts.faces; ++f) parseFace(f, counts, mesh);
        // Edge lines may follow the faces and are ignored, but another face means the header's face
        // count is too small: stopping there would drop faces without a word.
        while (std::optional<OffLine> extra = lines_.next())
            if (looksLikeFace(extra->content))
                fail(extra->number, "a face after the " + std::to_string(counts.faces) +
                                        " faces the header declares (is the face count in the header too small?)");
        return mesh;
    }

private:
    // "n i1 .. in" with n >= 3: the shape of a face line (an edge line has n = 2).
    static bool looksLikeFace(std::string_view content) {
        TokenReader tokens(content);
        std::optional<int64_t> size = parseInteger(tokens.next());
        if (!size || *size < 3) return false;
        for (int64_t k = 0; k < *size; ++k)
            if (!parseInteger(tokens.next())) return false;
        return true;
    }

    [[noreturn]] void fail(size_t lineNumber, const std::string& what) const {
        throw MeshReadError(sourceName_ + ":" + std::to_string(lineNumber) + ": " + what);
    }

    OffLine requireLine(const std::string& expected) {
        std::optional<OffLine> line = lines_.next();
        if (!line) {
            // Several vertices on one line read as one vertex with extras, and the file then
            // seems short: say so rather than only "truncated".
            std::string why = " (truncated file?)";
            if (crowdedLine_ > 0)
                why = " (line " + std::to_string(crowdedLine_) + " holds " + std::to_string(crowdedCount_) +
                      " numbers: are several vertices on one line? OFF puts one vertex per line)";
            fail(lines_.lastLineNumber(), "file ends early: expected " + expected + why);
        }
        return *line;
    }

    // Remembers the first vertex line holding at least two vertices' worth of numbers.
    void noteCrowdedLine(const OffLine& line, TokenReader rest, size_t coordinateCount) {
        if (crowdedLine_ > 0) return;
        size_t numbers = coordinateCount;
        for (std::string_view token = rest.next(); !token.empty(); token = rest.next()) {
            if (!parseReal(token)) return;
            ++numbers;
        }
        if (numbers >= 2 * coordinateCount) crowdedLine_ = line.number, crowdedCount_ = numbers;
    }

    OffCounts parseHeader() {
        std::optional<OffLine> first = lines_.next();
        if (!first) fail(lines_.lastLineNumber(), "no content (only blank lines or comments)");
        TokenReader tokens(first->content);
        std::string_view firstToken = tokens.next();
        std::optional<OffKeyword> keyword = parseKeyword(firstToken);
        if (!keyword) {
            // The keyword is optional in Geomview's OFF; a headerless file starts with its counts.
            if (parseInteger(firstToken)) return parseCounts(*first, TokenReader(first->content));
            fail(first->number, "not an OFF file: expected the keyword 'OFF', found " + asText(firstToken));
        }
        keyword_ = *keyword;
        OffLine line = *first;
        std::string_view token = tokens.next();
        if (token == "BINARY") fail(line.number, "binary OFF is not supported; convert it to text OFF");
        if (token.empty()) {
            line = requireLine(keyword_.dimensionFollows ? "the dimension" : "the counts line");
            tokens = TokenReader(line.content);
            token = tokens.next();
        }
        if (keyword_.dimensionFollows) {
            std::optional<int64_t> dimension = parseInteger(token);
            if (dimension != 3) fail(line.number, "only 3-dimensional nOFF is supported, found dimension " + asText(token));
            token = tokens.next();
            if (token.empty()) {
                line = requireLine("the counts line");
                tokens = TokenReader(line.content);
                token = tokens.next();
            }
        }
        // Re-read the counts from the token just taken plus the rest of its line.
        return parseCounts(line, tokens, token);
    }

    OffCounts parseCounts(const OffLine& line, TokenReader tokens, std::string_view firstToken = {}) {
        std::string_view vertexToken = firstToken.empty() ? tokens.next() : firstToken;
        std::string_view faceToken = tokens.next();
        OffCounts counts;
        counts.vertices = parseCount(line, vertexToken, "vertex count");
        counts.faces = parseCount(line, faceToken, "face count");
        // The edge count, if present, is unused by OFF readers and not checked.
        if (counts.vertices == 0) fail(line.number, "header declares 0 vertices (no faces can exist)");
        if (counts.faces == 0) fail(line.number, "header declares 0 faces (no faces)");
        if (counts.vertices > std::numeric_limits<uint32_t>::max())
            fail(line.number, "vertex count " + std::to_string(counts.vertices) + " exceeds the 32-bit index limit");
        checkCountsFitText(line, counts);
        return counts;
    }

    uint64_t parseCount(const OffLine& line, std::string_view token, const std::string& what) {
        if (token.empty()) fail(line.number, "missing " + what + " (expected 'vertices faces edges')");
        std::optional<int64_t> value = parseInteger(token);
        if (!value) {
            // Counts beyond int64 are still a count, just a forged one; say so rather than "not a number".
            bool allDigits = token.find_first_not_of("0123456789") == std::string_view::npos;
            if (allDigits) fail(line.number, what + " " + asText(token) + " is far larger than the file");
            fail(line.number, "expected a " + what + ", found " + asText(token));
        }
        if (*value < 0) fail(line.number, "negative " + what + " " + std::to_string(*value));
        return static_cast<uint64_t>(*value);
    }

    // The shortest possible vertex line is "0 0 0\n" (6 bytes) and face line "3 0 1 2\n" (8 bytes):
    // counts the remaining text cannot hold are forged or the file is truncated. Checking this
    // before reserving keeps a 20-byte file from asking for gigabytes.
    void checkCountsFitText(const OffLine& line, const OffCounts& counts) {
        const uint64_t shortestVertex = 6, shortestFace = 8;
        uint64_t available = lines_.remainingBytes() + 1;  // the last line may lack its newline
        if (counts.vertices > available / shortestVertex)
            fail(line.number, "header declares " + std::to_string(counts.vertices) + " vertices but only " +
                                  std::to_string(lines_.remainingBytes()) + " bytes follow (truncated file or wrong count)");
        available -= counts.vertices * shortestVertex;
        if (counts.faces > available / shortestFace)
            fail(line.number, "header declares " + std::to_string(counts.vertices) + " vertices and " +
                                  std::to_string(counts.faces) + " faces but only " +
                                  std::to_string(lines_.remainingBytes()) + " bytes follow (truncated file or wrong count)");
    }

    glm::vec3 parseVertex(uint64_t index, uint64_t vertexCount) {
        std::string vertexName = "vertex " + std::to_string(index);
        OffLine line = requireLine(vertexName + " of " + std::to_string(vertexCount));
        TokenReader tokens(line.content);
        size_t coordinateCount = keyword_.homogeneous ? 4 : 3;
        double coordinates[4] = {0.0, 0.0, 0.0, 1.0};
        for (size_t k = 0; k < coordinateCount; ++k) {
            std::string_view token = tokens.next();
            if (token.empty())
                fail(line.number, vertexName + " has " + std::to_string(k) + " coordinates, expected " +
                                      std::to_string(coordinateCount));
            std::optional<double> value = parseReal(token);
            if (!value) fail(line.number, vertexName + ": expected a coordinate, found " + asText(token));
            if (!std::isfinite(*value)) fail(line.number, vertexName + " has a non-finite coordinate " + asText(token));
            coordinates[k] = *value;
        }
        noteCrowdedLine(line, tokens, coordinateCount);
        if (coordinates[3] == 0.0) fail(line.number, vertexName + " has homogeneous coordinate w = 0");
        glm::dvec3 position = glm::dvec3(coordinates[0], coordinates[1], coordinates[2]) / coordinates[3];
        addExactPosition(exactKeys_, position);
        glm::vec3 single(position);
        if (!std::isfinite(single.x) || !std::isfinite(single.y) || !std::isfinite(single.z))
            fail(line.number, vertexName + " has a coordinate beyond single-precision range");
        return single;
    }

    void parseFace(uint64_t index, const OffCounts& counts, Mesh& mesh) {
        std::string faceName = "face " + std::to_string(index);
        OffLine line = requireLine(faceName + " of " + std::to_string(counts.faces));
        TokenReader tokens(line.content);
        std::string_view sizeToken = tokens.next();
        std::optional<int64_t> size = parseInteger(sizeToken);
        if (!size) fail(line.number, faceName + ": expected its vertex count, found " + asText(sizeToken));
        if (*size < 3) fail(line.number, faceName + " has " + std::to_string(*size) + " vertices (needs at least 3)");
        // No reserve from the size: indices must be on this line, so the line length bounds memory.
        for (int64_t k = 0; k < *size; ++k) {
            std::string_view token = tokens.next();
            if (token.empty())
                fail(line.number, faceName + " lists " + std::to_string(k) + " of its " + std::to_string(*size) +
                                      " vertex indices");
            std::optional<int64_t> vertex = parseInteger(token);
            if (!vertex) fail(line.number, faceName + ": expected a vertex index, found " + asText(token));
            if (*vertex < 0) fail(line.number, faceName + " has negative vertex index " + std::to_string(*vertex));
            if (static_cast<uint64_t>(*vertex) >= counts.vertices)
                fail(line.number, faceName + " uses vertex " + std::to_string(*vertex) + " but there are only " +
                                      std::to_string(counts.vertices) + " vertices");
            mesh.faceVertices.push_back(static_cast<uint32_t>(*vertex));
        }
        // Anything left on the line is a per-face colour, which the culling does not use.
        if (mesh.faceVertices.size() > std::numeric_limits<uint32_t>::max())
            fail(line.number, "too many face vertices for 32-bit face offsets");
        mesh.faceStarts.push_back(static_cast<uint32_t>(mesh.faceVertices.size()));
    }

    OffLineReader lines_;
    const std::string& sourceName_;
    std::vector<uint64_t>* exactKeys_;
    OffKeyword keyword_;
    size_t crowdedLine_ = 0, crowdedCount_ = 0;
};

}  // namespace

Mesh parseOff(std::string_view text, const std::string& sourceName, std::vector<uint64_t>* exactKeys) {
    return OffParser(text, sourceName, exactKeys).parse();
}

Mesh readOff(const std::string& path, std::vector<uint64_t>* exactKeys) {
    return parseOff(readFileBytes(path), path, exactKeys);
}

}  // namespace conescope
