// Byte order marks and UTF-16 in text mesh files (internal to conescope_io). Editors on Windows
// save text as UTF-8 with a BOM or as UTF-16; the parsers read ASCII/UTF-8 only.
#pragma once

#include <string>

namespace conescope {

// A file's text as UTF-8 without a byte order mark, and the encoding it was converted from.
struct Utf8Text {
    std::string text;
    std::string convertedFrom;  // "UTF-16 LE" or "UTF-16 BE"; empty when the bytes were already UTF-8
};

// Drops a UTF-8 BOM; converts UTF-16 LE or BE, recognised by its BOM, to UTF-8. Other bytes are
// returned as they are. Throws MeshReadError naming `path` and the encoding for UTF-32 (refused)
// and for UTF-16 that cannot be decoded (an odd number of bytes, an unpaired surrogate).
Utf8Text utf8WithoutByteOrderMark(std::string bytes, const std::string& path);

// The note a reader leaves when it converted: "converted from UTF-16 BE to UTF-8 before reading".
std::string conversionNote(const Utf8Text& text);

}  // namespace conescope
