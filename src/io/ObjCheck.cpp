// checkObjFile: checks the face lines of a Wavefront OBJ before vtkOBJReader sees them. VTK 9.1
// crashes on a face corner like "1/" (a slash with nothing after it) and does not check that
// texture-coordinate and normal indices exist.
#include "io/HeaderChecks.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/TextScanning.h"

namespace conescope {

namespace {

using text::LineCursor;
using text::isFiniteFloat;
using text::splitWords;

// vtkOBJReader reads lines into a fixed buffer; longer ones would be cut.
constexpr size_t longestObjLine = 8000;

struct ObjCounts {
    int64_t positions = 0;
    int64_t textureCoordinates = 0;
    int64_t normals = 0;
};

std::optional<int64_t> parseIndex(std::string_view text) {
    std::optional<int64_t> value = text::parseInteger(text);
    if (!value || *value == 0) return std::nullopt;  // OBJ indices start at 1; negatives count back
    return value;
}

class ObjChecker {
public:
    ObjChecker(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

    void check() {
        ObjCounts seen;
        LineCursor lines(bytes_, 0, 0);
        while (!lines.atEnd()) {
            std::string_view line = lines.next();
            if (line.size() > longestObjLine) fail(lines.lineNumber(), "line is too long for VTK's OBJ reader");
            std::vector<std::string_view> words = splitWords(line);
            if (words.empty()) continue;
            if (words[0] == "v") {
                ++seen.positions;
                checkPosition(words, seen.positions, lines.lineNumber());
            }
            if (words[0] == "vt") ++seen.textureCoordinates;
            if (words[0] == "vn") ++seen.normals;
            if (words[0] == "f" || words[0] == "l" || words[0] == "p")
                for (size_t k = 1; k < words.size(); ++k) checkCorner(words[k], seen, lines.lineNumber());
        }
    }

private:
    [[noreturn]] void fail(size_t lineNumber, const std::string& what) const {
        throw MeshReadError(path_ + ":" + std::to_string(lineNumber) + ": " + what);
    }

    // "v x y z [w | r g b]": VTK's reader would read a missing or unreadable coordinate as 0.
    void checkPosition(const std::vector<std::string_view>& words, size_t number, size_t lineNumber) const {
        if (words.size() < 4) fail(lineNumber, "vertex " + std::to_string(number) + " has fewer than 3 coordinates");
        for (size_t k = 1; k < 4; ++k)
            if (!isFiniteFloat(words[k]))
                fail(lineNumber, "vertex " + std::to_string(number) + " has a coordinate that is not a finite number: " +
                                     quotedForMessage(std::string(words[k])));
    }

    // A corner is v, v/vt, v//vn or v/vt/vn. Relative (negative) indices count back from the
    // elements defined so far; positive ones may refer forward, to the file's total.
    void checkCorner(std::string_view corner, const ObjCounts& seen, size_t lineNumber) const {
        std::vector<std::string_view> parts;
        size_t start = 0;
        while (true) {
            size_t slash = corner.find('/', start);
            parts.push_back(corner.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start));
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        bool wellFormed = parts.size() <= 3 && !parts[0].empty() && (parts.size() < 2 || !parts[1].empty() || parts.size() == 3) &&
                          (parts.size() < 3 || !parts[2].empty());
        if (!wellFormed) fail(lineNumber, "malformed face corner " + quotedForMessage(std::string(corner)));
        checkIndex(parts[0], seen.positions, "vertex", corner, lineNumber);
        if (parts.size() > 1 && !parts[1].empty())
            checkIndex(parts[1], seen.textureCoordinates, "texture coordinate", corner, lineNumber);
        if (parts.size() > 2) checkIndex(parts[2], seen.normals, "normal", corner, lineNumber);
    }

    void checkIndex(std::string_view text, int64_t definedSoFar, const char* what, std::string_view corner,
                    size_t lineNumber) const {
        std::optional<int64_t> index = parseIndex(text);
        if (!index) fail(lineNumber, "malformed face corner " + quotedForMessage(std::string(corner)));
        if (*index < 0 && -*index > definedSoFar)
            fail(lineNumber, std::string("face corner ") + quotedForMessage(std::string(corner)) + " refers to " + what + " " +
                                 std::to_string(*index) + " but only " + std::to_string(definedSoFar) + " are defined before it");
        if (*index > 0 && *index > totals().at(what))
            fail(lineNumber, std::string("face corner ") + quotedForMessage(std::string(corner)) + " uses " + what + " " +
                                 std::to_string(*index) + " but the file has only " + std::to_string(totals().at(what)));
    }

    // Totals over the whole file, for forward references; counted once on first use.
    const std::map<std::string, int64_t>& totals() const {
        if (!totals_.empty()) return totals_;
        totals_ = {{"vertex", 0}, {"texture coordinate", 0}, {"normal", 0}};
        LineCursor lines(bytes_, 0, 0);
        while (!lines.atEnd()) {
            std::vector<std::string_view> words = splitWords(lines.next());
            if (words.empty()) continue;
            if (words[0] == "v") ++totals_["vertex"];
            if (words[0] == "vt") ++totals_["texture coordinate"];
            if (words[0] == "vn") ++totals_["normal"];
        }
        return totals_;
    }

    const std::string& path_;
    std::string_view bytes_;
    mutable std::map<std::string, int64_t> totals_;
};

}  // namespace

void checkObjFile(const std::string& path) {
    std::string bytes = readFileBytes(path);
    ObjChecker(path, bytes).check();
}

}  // namespace conescope
