// parseObj: one pass over the lines of an OBJ file, building the Mesh as it goes. Not Debian's
// tinyobjloader (2.0.0rc10): on our malformed-file inputs it returns a mesh without an error for
// "v 0.5 x 0.5" (read as 0.5 0 0.5), "v nan 0 0" (0 0 0), "v 0 0 1e39" (inf), "v 1 2" (z = 0),
// "f 1 2.5 3" and "f 1 2 3abc" (atoi: 2 and 3), "f 1 2 9" (index 8 kept, only a warning) and
// "f -3 -2 -4" with 3 vertices (index -1), and drops "f 1 2" with a warning.
#include "io/ObjFormat.h"

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/PositionMerging.h"
#include "io/TextEncoding.h"
#include "io/TextScanning.h"

namespace conescope {

namespace {

using text::LineCursor;

// The elements a corner indexes, in the order of its slash-separated parts.
enum ObjElement { Position, TextureCoordinate, Normal };
const char* const elementNames[] = {"vertex", "texture coordinate", "normal"};

// Statements that are accepted and carry nothing this mesh needs: attributes for texturing,
// shading and display, grouping, and materials (an empty usemtl included).
bool isStatementWithoutGeometry(std::string_view keyword) {
    static const std::string_view keywords[] = {"vp", "s", "usemtl", "mtllib", "mg", "bevel", "c_interp",
                                                "d_interp", "lod", "shadow_obj", "trace_obj", "maplib", "usemap"};
    for (std::string_view known : keywords)
        if (keyword == known) return true;
    return false;
}

// "1 line", "24 points".
std::string counted(size_t count, const std::string& singular) {
    return std::to_string(count) + " " + singular + (count == 1 ? "" : "s");
}

// The largest positive index of one element kind a corner used beyond the elements defined before
// it: positive indices may refer forward, so whether it exists is known only at the end of the file.
struct ForwardReference {
    int64_t index = 0;
    size_t lineNumber = 0;
    std::string corner;
};

class ObjParser {
public:
    ObjParser(std::string_view text, const std::string& sourceName, const ProgressCallback& progress, std::vector<uint64_t>* exactKeys)
        : text_(text), sourceName_(sourceName), progress_(progress, text.size()), exactKeys_(exactKeys) {}

    Mesh parse(std::vector<std::string>& notes) {
        LineCursor lines(text_, 0, 0);
        while (!lines.atEnd()) {
            progress_.at(lines.position());
            std::string_view line = lines.next();
            text::splitWords(line.substr(0, line.find('#')), words_);
            if (!words_.empty()) readStatement(lines.lineNumber());
        }
        for (ObjElement kind : {Position, TextureCoordinate, Normal}) checkForwardReference(kind);
        addNotes(notes);
        if (mesh_.faceCount() == 0) {
            std::string skipped = skippedElements();
            if (shortFaces_) skipped += (skipped.empty() ? "" : " and ") + counted(shortFaces_, "face") + " of fewer than 3 corners";
            const size_t vertices = mesh_.positions.size();
            throw MeshReadError(sourceName_ + ": no faces (" + std::to_string(vertices) + (vertices == 1 ? " vertex" : " vertices") +
                                (skipped.empty() ? "" : "; " + skipped + " skipped, " + whichAreNotFaces()) + ")");
        }
        // Groups are kept only when the file has some: a cluster per group for the file builder.
        if (groupStatements_ > 0) mesh_.faceArrays["group_id"] = std::move(groupOfFace_);
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(size_t lineNumber, const std::string& what) const {
        throw MeshReadError(sourceName_ + ":" + std::to_string(lineNumber) + ": " + what);
    }

    void readStatement(size_t lineNumber) {
        const std::string_view keyword = words_[0];
        if (keyword == "v") {
            readPosition(lineNumber);
        } else if (keyword == "f") {
            readFace(lineNumber);
        } else if (keyword == "vt") {
            ++defined_[TextureCoordinate];
        } else if (keyword == "vn") {
            ++defined_[Normal];
        } else if (keyword == "g" || keyword == "o") {
            readGroup(keyword);
        } else if (keyword == "l" || keyword == "p") {
            skipLineOrPoints(keyword, lineNumber);
        } else if (!isStatementWithoutGeometry(keyword)) {
            if (unknownStatements_++ == 0) firstUnknown_ = "line " + std::to_string(lineNumber) + ": " + quotedForMessage(std::string(keyword));
        }
    }

    // "v x y z [w | r g b]": a missing or unreadable coordinate is an error, never a 0.
    void readPosition(size_t lineNumber) {
        const auto vertex = [&] { return "vertex " + std::to_string(defined_[Position] + 1); };
        if (words_.size() < 4) fail(lineNumber, vertex() + " has fewer than 3 coordinates");
        if (defined_[Position] == std::numeric_limits<uint32_t>::max())
            fail(lineNumber, "more vertices than 32-bit indices can address");
        glm::dvec3 position;
        for (int k = 0; k < 3; ++k) {
            if (!text::parseFiniteFloat(words_[k + 1]))
                fail(lineNumber, vertex() + " has a coordinate that is not a finite number: " +
                                     quotedForMessage(std::string(words_[k + 1])));
            position[k] = *text::parseNumber(words_[k + 1]);
        }
        addExactPosition(exactKeys_, position);
        mesh_.positions.emplace_back(position);
        ++defined_[Position];
    }

    // A face of one or two corners (exporters write edges so) draws nothing: skipped with a note,
    // as lines are, its corners still checked. One without corners is a damaged line.
    void readFace(size_t lineNumber) {
        const size_t corners = words_.size() - 1;
        if (corners == 0) fail(lineNumber, "face has 0 corners; a face needs at least 3");
        if (corners < 3) {
            for (size_t k = 1; k < words_.size(); ++k) readCorner(words_[k], lineNumber);
            if (shortFaces_++ == 0) firstShortFace_ = lineNumber;
            return;
        }
        for (size_t k = 1; k < words_.size(); ++k) mesh_.faceVertices.push_back(uint32_t(readCorner(words_[k], lineNumber)));
        if (mesh_.faceVertices.size() > std::numeric_limits<uint32_t>::max())
            fail(lineNumber, "more face corners than 32-bit offsets can address");
        mesh_.faceStarts.push_back(uint32_t(mesh_.faceVertices.size()));
        groupOfFace_.push_back(double(group_));
    }

    // The group a face is in is the pair (object name, group names) of the o and g statements
    // before it; the same pair again is the same group. Numbered in order of first use.
    void readGroup(std::string_view keyword) {
        std::string names;
        for (size_t k = 1; k < words_.size(); ++k) names += std::string(words_[k]) + (k + 1 < words_.size() ? " " : "");
        (keyword == "o" ? objectName_ : groupNames_) = names;
        ++groupStatements_;
        const auto [entry, added] = groups_.try_emplace(objectName_ + '\n' + groupNames_, uint32_t(groups_.size()));
        group_ = entry->second;
    }

    // Lines and points are checked like faces (bad indices mean a damaged file) but not kept.
    void skipLineOrPoints(std::string_view keyword, size_t lineNumber) {
        for (size_t k = 1; k < words_.size(); ++k) readCorner(words_[k], lineNumber);
        if (keyword == "l")
            ++lineElements_;
        else
            pointElements_ += words_.size() - 1;
    }

    // A corner is v, v/vt, v//vn or v/vt/vn. Returns the 0-based position index, which may still
    // refer forward (checkForwardReference settles it at the end). Trailing slashes name nothing:
    // slicers write `104/` and `1//` for the vertex alone, and assimp reads them so.
    int64_t readCorner(std::string_view corner, size_t lineNumber) {
        std::array<std::string_view, 3> parts;
        size_t count = 0, start = 0;
        while (true) {
            const size_t slash = corner.find('/', start);
            if (count == parts.size()) fail(lineNumber, "malformed face corner " + quotedForMessage(std::string(corner)));
            parts[count++] = corner.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        while (count > 1 && parts[count - 1].empty()) --count;
        const bool wellFormed = !parts[0].empty() && (count != 2 || !parts[1].empty()) && (count != 3 || !parts[2].empty());
        if (!wellFormed) fail(lineNumber, "malformed face corner " + quotedForMessage(std::string(corner)));
        const int64_t position = resolveIndex(parts[0], Position, corner, lineNumber);
        if (count > 1 && !parts[1].empty()) resolveIndex(parts[1], TextureCoordinate, corner, lineNumber);
        if (count > 2) resolveIndex(parts[2], Normal, corner, lineNumber);
        return position;
    }

    // OBJ indices start at 1; negative ones count back from the elements defined so far.
    int64_t resolveIndex(std::string_view text, ObjElement kind, std::string_view corner, size_t lineNumber) {
        std::optional<int64_t> index = text::parseInteger(text);
        if (!index || *index == 0) fail(lineNumber, "malformed face corner " + quotedForMessage(std::string(corner)));
        const int64_t defined = defined_[kind];
        if (*index < -defined)
            fail(lineNumber, "face corner " + quotedForMessage(std::string(corner)) + " refers to " + elementNames[kind] + " " +
                                 std::to_string(*index) + " but only " + std::to_string(defined) + " are defined before it");
        if (*index < 0) return defined + *index;
        ForwardReference& forward = forward_[kind];
        if (*index > defined && *index > forward.index) forward = {*index, lineNumber, std::string(corner)};
        return *index - 1;
    }

    void checkForwardReference(ObjElement kind) const {
        const ForwardReference& forward = forward_[kind];
        if (forward.index > defined_[kind])
            fail(forward.lineNumber, "face corner " + quotedForMessage(forward.corner) + " uses " + elementNames[kind] + " " +
                                         std::to_string(forward.index) + " but the file has only " + std::to_string(defined_[kind]));
    }

    // "6 lines and 24 points", or "" when there were none.
    std::string skippedElements() const {
        std::string lines = lineElements_ ? counted(lineElements_, "line") : "";
        std::string points = pointElements_ ? counted(pointElements_, "point") : "";
        return lines + (!lines.empty() && !points.empty() ? " and " : "") + points;
    }

    // "which is not a face" for one line or point, "which are not faces" for more.
    std::string whichAreNotFaces() const {
        return lineElements_ + pointElements_ + shortFaces_ == 1 ? "which is not a face" : "which are not faces";
    }

    void addNotes(std::vector<std::string>& notes) const {
        if (std::string skipped = skippedElements(); !skipped.empty())
            notes.push_back("skipped " + skipped + (lineElements_ + pointElements_ == 1 ? ": it is not a face" : ": they are not faces"));
        if (shortFaces_)
            notes.push_back("skipped " + counted(shortFaces_, "face") + " of fewer than 3 corners (" +
                            (shortFaces_ == 1 ? "line " : "the first on line ") + std::to_string(firstShortFace_) +
                            "): a face needs at least 3");
        if (unknownStatements_)
            notes.push_back("ignored " + counted(unknownStatements_, "statement") + " with a keyword this reader does not know (" +
                            firstUnknown_ + (unknownStatements_ > 1 ? " is the first" : "") + ")");
    }

    std::string_view text_;
    const std::string& sourceName_;
    ReadProgress progress_;
    std::vector<uint64_t>* exactKeys_;
    Mesh mesh_;
    std::vector<std::string_view> words_;
    std::array<int64_t, 3> defined_{};  // v, vt and vn statements read so far
    std::array<ForwardReference, 3> forward_;
    size_t lineElements_ = 0, pointElements_ = 0, unknownStatements_ = 0;
    size_t shortFaces_ = 0, firstShortFace_ = 0;  // faces of 1 or 2 corners, skipped
    std::string firstUnknown_;
    std::string objectName_, groupNames_;
    std::map<std::string, uint32_t> groups_{{"\n", 0}};  // faces before any o or g: the default group
    uint32_t group_ = 0;
    size_t groupStatements_ = 0;
    std::vector<double> groupOfFace_;
};

}  // namespace

Mesh parseObj(std::string_view text, const std::string& sourceName, std::vector<std::string>& notes,
              const ProgressCallback& progress, std::vector<uint64_t>* exactKeys) {
    return ObjParser(text, sourceName, progress, exactKeys).parse(notes);
}

Mesh readObj(const std::string& path, std::vector<std::string>& notes, const ProgressCallback& progress, std::vector<uint64_t>* exactKeys) {
    Utf8Text text = utf8WithoutByteOrderMark(readFileBytes(path), path);
    if (!text.convertedFrom.empty()) notes.push_back(conversionNote(text));
    return parseObj(text.text, path, notes, progress, exactKeys);
}

}  // namespace conescope
