#include "io/TextEncoding.h"

#include <cstdint>
#include <string_view>

#include "io/MeshReader.h"

namespace conescope {

namespace {

bool startsWith(const std::string& bytes, std::string_view prefix) {
    return bytes.size() >= prefix.size() && std::string_view(bytes).substr(0, prefix.size()) == prefix;
}

void appendUtf8(std::string& out, uint32_t codePoint) {
    if (codePoint < 0x80) {
        out += char(codePoint);
    } else if (codePoint < 0x800) {
        out += char(0xc0 | (codePoint >> 6));
        out += char(0x80 | (codePoint & 0x3f));
    } else if (codePoint < 0x10000) {
        out += char(0xe0 | (codePoint >> 12));
        out += char(0x80 | ((codePoint >> 6) & 0x3f));
        out += char(0x80 | (codePoint & 0x3f));
    } else {
        out += char(0xf0 | (codePoint >> 18));
        out += char(0x80 | ((codePoint >> 12) & 0x3f));
        out += char(0x80 | ((codePoint >> 6) & 0x3f));
        out += char(0x80 | (codePoint & 0x3f));
    }
}

// UTF-16 after its 2-byte BOM to UTF-8; surrogate pairs become one code point.
std::string utf8FromUtf16(const std::string& bytes, bool bigEndian, const std::string& path) {
    const std::string encoding = bigEndian ? "UTF-16 BE" : "UTF-16 LE";
    if (bytes.size() % 2 != 0)
        throw MeshReadError(path + ": " + encoding + " text (by its byte order mark) with an odd number of bytes, " +
                            std::to_string(bytes.size()) + " (truncated file?)");
    auto unitAt = [&](size_t position) {
        const uint32_t first = uint8_t(bytes[position]), second = uint8_t(bytes[position + 1]);
        return bigEndian ? (first << 8 | second) : (second << 8 | first);
    };
    std::string text;
    text.reserve(bytes.size() / 2);
    for (size_t position = 2; position < bytes.size(); position += 2) {
        uint32_t unit = unitAt(position);
        const bool high = unit >= 0xd800 && unit < 0xdc00, low = unit >= 0xdc00 && unit < 0xe000;
        if (high && position + 3 < bytes.size()) {
            const uint32_t next = unitAt(position + 2);
            if (next >= 0xdc00 && next < 0xe000) {
                appendUtf8(text, 0x10000 + ((unit - 0xd800) << 10) + (next - 0xdc00));
                position += 2;
                continue;
            }
        }
        if (high || low)
            throw MeshReadError(path + ": " + encoding + " text with an unpaired surrogate at byte " + std::to_string(position));
        appendUtf8(text, unit);
    }
    return text;
}

}  // namespace

Utf8Text utf8WithoutByteOrderMark(std::string bytes, const std::string& path) {
    // The UTF-32 marks first: UTF-32 LE's begins with UTF-16 LE's.
    if (startsWith(bytes, std::string_view("\xff\xfe\0\0", 4)) || startsWith(bytes, std::string_view("\0\0\xfe\xff", 4)))
        throw MeshReadError(path + ": UTF-32 text (by its byte order mark) is not supported; save the file as UTF-8 or ASCII");
    if (startsWith(bytes, "\xef\xbb\xbf")) {
        bytes.erase(0, 3);
        return {std::move(bytes), ""};
    }
    if (startsWith(bytes, "\xfe\xff")) return {utf8FromUtf16(bytes, true, path), "UTF-16 BE"};
    if (startsWith(bytes, "\xff\xfe")) return {utf8FromUtf16(bytes, false, path), "UTF-16 LE"};
    return {std::move(bytes), ""};
}

std::string conversionNote(const Utf8Text& text) {
    return "converted from " + text.convertedFrom + " to UTF-8 before reading";
}

}  // namespace conescope
