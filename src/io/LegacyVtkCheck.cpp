// checkLegacyVtkFile: walks the geometry sections of a legacy .vtk POLYDATA file before
// vtkPolyDataReader sees it. VTK 9.1's reader crashes (in vtkDataReader::ReadString) on a file cut
// inside a cell list, and allocates from declared counts; we check every declared value is present
// and every cell list is consistent, streaming through the data without allocating from counts.
#include "io/HeaderChecks.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/FileChecks.h"
#include "io/MeshReader.h"
#include "io/TextScanning.h"

namespace conescope {

namespace {

using text::parseInteger;

std::string lowerCase(std::string_view word) {
    std::string lower(word);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return lower;
}

// Bytes per binary value of a legacy type name; 0 for types we do not walk (strings, bits).
size_t legacyTypeSize(const std::string& type) {
    if (type == "double" || type == "long" || type == "unsigned_long" || type == "vtktypeint64" ||
        type == "vtktypeuint64" || type == "vtkidtype")
        return 8;
    if (type == "float" || type == "int" || type == "unsigned_int" || type == "vtktypeint32" || type == "vtktypeuint32")
        return 4;
    if (type == "short" || type == "unsigned_short") return 2;
    if (type == "char" || type == "signed_char" || type == "unsigned_char") return 1;
    return 0;
}

bool isFloatingType(const std::string& type) { return type == "float" || type == "double"; }

bool fitsFloatingType(std::string_view token, const std::string& type) {
    if (type != "double") return text::isFiniteFloat(token);
    std::optional<double> value = text::parseNumber(token);
    return value && std::isfinite(*value);
}

bool fitsIntegerType(int64_t value, const std::string& type) {
    size_t size = legacyTypeSize(type);
    bool isUnsigned = type.find("unsigned") != std::string::npos || type.find("uint") != std::string::npos;
    if (isUnsigned && value < 0) return false;
    if (size >= 8) return true;
    int64_t limit = int64_t(1) << (8 * size - (isUnsigned ? 0 : 1));
    return value < limit && value >= (isUnsigned ? 0 : -limit);
}

class LegacyVtkChecker {
public:
    LegacyVtkChecker(const std::string& path, std::string_view bytes) : path_(path), bytes_(bytes) {}

    void check() {
        readHeader();
        while (true) {
            std::string keyword = lowerCase(nextToken());
            if (keyword.empty()) return;
            if (keyword == "field")
                walkField();
            else if (keyword == "points")
                walkPoints();
            else if (keyword == "vertices" || keyword == "lines" || keyword == "polygons" || keyword == "triangle_strips")
                walkCells(keyword);
            else if (keyword == "cell_data" || keyword == "point_data")
                walkAttributes(static_cast<uint64_t>(nextCount(keyword + " count")));
            else
                // VTK matches keywords by prefix ("POINTSxyz" counts as POINTS) and then trusts
                // what follows, so anything but the exact keywords is refused here.
                failUnexpectedKeyword(keyword, "");
        }
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw MeshReadError(path_ + ":" + std::to_string(lineOfLastToken_) + ": " + what);
    }

    // VTK reads exactly the values a section's header declares; a number where the next keyword
    // belongs means that count was too small, and the values after it would be lost or misread.
    [[noreturn]] void failUnexpectedKeyword(const std::string& keyword, const std::string& where) const {
        if (text::isNumber(keyword) && !lastSection_.empty())
            fail(lastSection_ + ": value " + quotedForMessage(keyword) + " after the " + std::to_string(lastSectionValues_) +
                 " values its header declares (is a count in the header too small?)");
        fail("unexpected keyword " + quotedForMessage(keyword) + where);
    }

    std::string_view nextLine() {
        size_t end = bytes_.find('\n', position_);
        if (end == std::string_view::npos) end = bytes_.size();
        std::string_view line = bytes_.substr(position_, end - position_);
        position_ = std::min(end + 1, bytes_.size());
        lineOfLastToken_ = ++newlinesPassed_;
        return line;
    }

    // VTK reads keywords and ASCII values with operator>>, so tokens may cross lines.
    std::string_view nextToken() {
        while (position_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[position_]))) {
            if (bytes_[position_] == '\n') ++newlinesPassed_;
            ++position_;
        }
        lineOfLastToken_ = newlinesPassed_ + 1;
        size_t start = position_;
        while (position_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[position_]))) ++position_;
        return bytes_.substr(start, position_ - start);
    }

    int64_t nextCount(const std::string& what) {
        std::string_view token = nextToken();
        std::optional<int64_t> count = parseInteger(token);
        if (!count || *count < 0) fail("bad " + what + " " + quotedForMessage(std::string(token)));
        return *count;
    }

    void readHeader() {
        std::string_view version = nextLine();
        if (version.substr(0, 2) != "# " || version.find("DataFile") == std::string_view::npos)
            fail("not a legacy VTK file (first line is " + quotedForMessage(std::string(version)) + ")");
        usesOffsetsAndConnectivity_ = isVersion51OrLater(version);
        nextLine();  // title
        binary_ = lowerCase(nextToken()) == "binary";
        if (lowerCase(nextToken()) != "dataset" || lowerCase(nextToken()) != "polydata")
            fail("expected DATASET POLYDATA");
    }

    // VTK reads the version like sscanf(line, "# vtk DataFile Version %d.%d") and takes 0.0 when
    // that fails ("Version 5." or "Version1415914182 5.1" are 0.0; "Version5.1" is 5.1). Files
    // from 5.1 on store cells as OFFSETS and CONNECTIVITY arrays, older ones as counted lists.
    static bool isVersion51OrLater(std::string_view firstLine) {
        size_t keyword = firstLine.find("Version");
        if (keyword == std::string_view::npos) return false;
        std::string_view rest = firstLine.substr(keyword + 7);
        std::optional<int> major = scanInteger(rest);
        if (!major || rest.empty() || rest.front() != '.') return false;
        rest.remove_prefix(1);
        std::optional<int> minor = scanInteger(rest);
        if (!minor) return false;
        return *major > 5 || (*major == 5 && *minor >= 1);
    }

    // Like sscanf's %d: skips leading whitespace, reads an optionally signed integer, consumes it.
    static std::optional<int> scanInteger(std::string_view& text) {
        while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
        if (!text.empty() && text.front() == '+') text.remove_prefix(1);
        int value = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc()) return std::nullopt;
        text.remove_prefix(static_cast<size_t>(end - text.data()));
        return value;
    }

    // Binary data starts after the rest of the keyword line.
    void skipToLineEnd() {
        size_t end = bytes_.find('\n', position_);
        position_ = end == std::string_view::npos ? bytes_.size() : end + 1;
        ++newlinesPassed_;
    }

    // Walks `count` values of `type`; calls onInteger for each when the caller needs integers.
    template <class OnInteger>
    void walkValues(const std::string& section, uint64_t count, const std::string& type, OnInteger onInteger) {
        size_t size = legacyTypeSize(type);
        if (type.empty()) fail(section + ": file ends before the value type (truncated file)");
        if (size == 0) fail(section + ": unsupported value type " + quotedForMessage(type));
        lastSection_ = section;
        lastSectionValues_ = count;
        if (binary_) {
            skipToLineEnd();
            if (count > (bytes_.size() - position_) / size)
                fail(section + " needs " + std::to_string(count) + " values of " + type + " but the file ends first " +
                     "(truncated file or wrong count)");
            for (uint64_t k = 0; k < count; ++k) onInteger(binaryInteger(position_ + k * size, size, type));
            position_ += count * size;
            return;
        }
        for (uint64_t k = 0; k < count; ++k) {
            std::string_view token = nextToken();
            if (token.empty())
                fail(section + ": file ends after " + std::to_string(k) + " of " + std::to_string(count) +
                     " values (truncated file or wrong count)");
            // VTK reads ASCII values with operator>> into the declared type; a value that type
            // cannot hold (1e999 as float, 2^40 as int, nan) fails the stream, and the reader then
            // crashes instead of reporting it.
            if (isFloatingType(type)) {
                if (!fitsFloatingType(token, type))
                    fail(section + ": expected a finite " + type + ", found " + quotedForMessage(std::string(token)));
                onInteger(0);
                continue;
            }
            std::optional<int64_t> value = parseInteger(token);
            if (!value || !fitsIntegerType(*value, type))
                fail(section + ": expected an integer of type " + type + ", found " + quotedForMessage(std::string(token)));
            onInteger(*value);
        }
    }

    // Legacy binary data is big-endian.
    int64_t binaryInteger(size_t position, size_t size, const std::string& type) const {
        if (isFloatingType(type)) return 0;
        uint64_t raw = 0;
        for (size_t k = 0; k < size; ++k) raw = (raw << 8) | static_cast<unsigned char>(bytes_[position + k]);
        bool isSigned = type.find("unsigned") == std::string::npos && type.find("uint") == std::string::npos;
        if (isSigned && size < 8 && (raw >> (8 * size - 1)) & 1) raw |= ~uint64_t(0) << (8 * size);
        return static_cast<int64_t>(raw);
    }

    void walkPoints() {
        int64_t count = nextCount("point count");
        std::string type = lowerCase(nextToken());
        walkValues("POINTS", 3 * static_cast<uint64_t>(count), type, [](int64_t) {});
    }

    void walkField() {
        nextToken();  // field name
        int64_t arrayCount = nextCount("field array count");
        for (int64_t a = 0; a < arrayCount; ++a) {
            std::string name(nextToken());
            if (name == "NULL_ARRAY") continue;
            int64_t components = nextCount("component count");
            int64_t tuples = nextCount("tuple count");
            std::string type = lowerCase(nextToken());
            if (isUnwalkedType(type)) return stopChecking();
            walkValues("FIELD array " + quotedForMessage(name), static_cast<uint64_t>(components) * tuples, type, [](int64_t) {});
            skipMetadata();
        }
    }

    // VTK 9 writes an optional METADATA block after an array, ended by an empty line.
    void skipMetadata() {
        size_t savedPosition = position_, savedNewlines = newlinesPassed_;
        if (lowerCase(nextToken()) != "metadata") {
            position_ = savedPosition;
            newlinesPassed_ = savedNewlines;
            return;
        }
        skipToLineEnd();
        while (position_ < bytes_.size() && !nextLine().empty()) {
        }
    }

    void stopChecking() { position_ = bytes_.size(); }

    // Strings and bit arrays have their own layouts; VTK reads them without trusting counts.
    static bool isUnwalkedType(const std::string& type) {
        return type == "string" || type == "utf8_string" || type == "variant" || type == "bit" || type == "vtkbitarray";
    }

    void walkValuesOf(const std::string& section, uint64_t count, const std::string& type) {
        if (isUnwalkedType(type)) return stopChecking();
        walkValues(section, count, type, [](int64_t) {});
        skipMetadata();
    }

    // CELL_DATA / POINT_DATA sections: VTK 9.1 zero-fills attribute values missing from a cut file
    // without complaint, so a truncated "cluster_id" would otherwise read as all zeros.
    void walkAttributes(uint64_t count) {
        while (true) {
            std::string keyword = lowerCase(nextToken());
            if (keyword.empty()) return;
            std::string section = keyword;
            std::transform(section.begin(), section.end(), section.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
            if (keyword == "cell_data" || keyword == "point_data") {
                count = static_cast<uint64_t>(nextCount(keyword + " count"));
            } else if (keyword == "scalars") {
                walkScalars(count);
            } else if (keyword == "color_scalars") {
                nextToken();  // name
                uint64_t components = static_cast<uint64_t>(nextCount("colour component count"));
                walkValuesOf(section, count * components, binary_ ? "unsigned_char" : "float");
            } else if (keyword == "lookup_table") {
                nextToken();  // name
                uint64_t size = static_cast<uint64_t>(nextCount("lookup table size"));
                walkValuesOf(section, 4 * size, binary_ ? "unsigned_char" : "float");
            } else if (keyword == "vectors" || keyword == "normals") {
                nextToken();  // name
                walkValuesOf(section, 3 * count, lowerCase(nextToken()));
            } else if (keyword == "tensors" || keyword == "tensors6") {
                nextToken();  // name
                walkValuesOf(section, (keyword == "tensors" ? 9 : 6) * count, lowerCase(nextToken()));
            } else if (keyword == "texture_coordinates") {
                nextToken();  // name
                uint64_t dimension = static_cast<uint64_t>(nextCount("texture dimension"));
                walkValuesOf(section, dimension * count, lowerCase(nextToken()));
            } else if (keyword == "global_ids" || keyword == "pedigree_ids" || keyword == "edge_flags") {
                nextToken();  // name
                walkValuesOf(section, count, lowerCase(nextToken()));
            } else if (keyword == "field") {
                walkField();
            } else {
                failUnexpectedKeyword(keyword, " in attribute data");
            }
        }
    }

    // SCALARS name type [components] then LOOKUP_TABLE name, then count * components values.
    void walkScalars(uint64_t count) {
        nextToken();  // name
        std::string type = lowerCase(nextToken());
        std::string_view token = nextToken();
        uint64_t components = 1;
        if (std::optional<int64_t> number = parseInteger(token)) {
            if (*number < 1) fail("SCALARS: bad component count " + std::to_string(*number));
            components = static_cast<uint64_t>(*number);
            token = nextToken();
        }
        if (token.empty()) fail("SCALARS: file ends inside the header (truncated file)");
        if (lowerCase(token) != "lookup_table") fail("SCALARS: expected LOOKUP_TABLE, found " + quotedForMessage(std::string(token)));
        nextToken();  // table name
        walkValuesOf("SCALARS", count * components, type);
    }

    void walkCells(const std::string& keyword) {
        std::string section = keyword;
        std::transform(section.begin(), section.end(), section.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        int64_t first = nextCount(section + " count");
        int64_t second = nextCount(section + " size");
        if (usesOffsetsAndConnectivity_)
            walkOffsetsAndConnectivity(section, first, second);
        else
            walkCountPrefixedCells(section, first, second);
    }

    // 4.x: `size` integers, each cell as "n id_1 .. id_n". VTK builds the cells from the size
    // alone, so a cell count that disagrees with them is an inconsistent header.
    void walkCountPrefixedCells(const std::string& section, int64_t cellCount, int64_t size) {
        int64_t idsLeftInCell = 0, cellsFound = 0;
        walkValues(section, static_cast<uint64_t>(size), "int", [&](int64_t value) {
            if (idsLeftInCell > 0) {
                --idsLeftInCell;
                return;
            }
            if (value < 0) fail(section + ": negative cell size " + std::to_string(value));
            idsLeftInCell = value;
            ++cellsFound;
        });
        if (idsLeftInCell > 0) fail(section + ": the last cell runs past the declared size " + std::to_string(size));
        if (cellsFound != cellCount)
            fail(section + ": header declares " + std::to_string(cellCount) + " cells but its " + std::to_string(size) +
                 " values hold " + std::to_string(cellsFound) + " (wrong cell count or size)");
    }

    // 5.x: "OFFSETS type" with `offsetCount` values from 0 up to `connectivityCount`, then
    // "CONNECTIVITY type" with `connectivityCount` point ids.
    void walkOffsetsAndConnectivity(const std::string& section, int64_t offsetCount, int64_t connectivityCount) {
        if (lowerCase(nextToken()) != "offsets") fail(section + ": expected OFFSETS");
        std::string offsetType = lowerCase(nextToken());
        int64_t previous = 0, index = 0;
        walkValues(section + " OFFSETS", static_cast<uint64_t>(offsetCount), offsetType, [&](int64_t offset) {
            if ((index == 0 && offset != 0) || offset < previous || offset > connectivityCount)
                fail(section + ": offset " + std::to_string(index) + " is " + std::to_string(offset) +
                     " (offsets must rise from 0 to " + std::to_string(connectivityCount) + ")");
            previous = offset;
            ++index;
        });
        if (offsetCount > 0 && previous != connectivityCount)
            fail(section + ": last offset " + std::to_string(previous) + " differs from the connectivity size " +
                 std::to_string(connectivityCount));
        if (lowerCase(nextToken()) != "connectivity") fail(section + ": expected CONNECTIVITY");
        std::string connectivityType = lowerCase(nextToken());
        walkValues(section + " CONNECTIVITY", static_cast<uint64_t>(connectivityCount), connectivityType, [&](int64_t id) {
            if (id < 0) fail(section + ": negative point id " + std::to_string(id));
        });
    }

    const std::string& path_;
    std::string_view bytes_;
    size_t position_ = 0;
    size_t newlinesPassed_ = 0;
    size_t lineOfLastToken_ = 1;  // 1-based line of the token or line read last, for messages
    bool binary_ = false;
    bool usesOffsetsAndConnectivity_ = false;
    std::string lastSection_;         // the section whose values were walked last, for messages
    uint64_t lastSectionValues_ = 0;  // how many values its header declared
};

}  // namespace

void checkLegacyVtkFile(const std::string& path) {
    std::string bytes = readFileBytes(path);
    LegacyVtkChecker(path, bytes).check();
}

}  // namespace conescope
