// checkStlFile; the other checks declared in HeaderChecks.h live in LegacyVtkCheck.cpp and
// VtpCheck.cpp (with VtpXml.cpp and VtpEncoding.cpp).
#include "io/HeaderChecks.h"

#include <cctype>
#include <cstdint>
#include <fstream>

#include <vtksys/SystemTools.hxx>

#include "io/FileChecks.h"
#include "io/MeshReader.h"

namespace conescope {

namespace {

std::string readPrefix(const std::string& path, size_t maximumBytes) {
    std::ifstream input(path, std::ios::binary);
    if (!input) throw MeshReadError(path + ": cannot open file for reading");
    std::string bytes(maximumBytes, '\0');
    input.read(bytes.data(), static_cast<std::streamsize>(maximumBytes));
    bytes.resize(static_cast<size_t>(input.gcount()));
    return bytes;
}

// Little-endian uint32 at position (the caller checked the four bytes are there).
uint32_t littleEndianUint32(const std::string& bytes, size_t position) {
    uint32_t value = 0;
    for (int k = 3; k >= 0; --k) value = (value << 8) | static_cast<unsigned char>(bytes[position + k]);
    return value;
}

// vtkSTLReader's ASCII parser requires the keyword 'solid' first (whitespace before it is fine).
bool startsWithSolid(const std::string& prefix) {
    size_t first = prefix.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || prefix.size() - first < 5) return false;
    std::string keyword = prefix.substr(first, 5);
    for (char& c : keyword) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return keyword == "solid";
}

}  // namespace

void checkStlFile(const std::string& path) {
    const uint64_t headerBytes = 84, triangleBytes = 50;
    std::string header = readPrefix(path, headerBytes);
    // VTK reads a file it sniffs as text as ASCII STL. A short binary file whose 80-byte comment is
    // text (no triangles, or cut off) sniffs as text too, and VTK would report a missing 'solid'
    // instead of the real problem; so such files get the binary checks, with both readings named.
    const bool sniffedAsText = vtksys::SystemTools::DetectFileType(path.c_str()) == vtksys::SystemTools::FileTypeText;
    if (sniffedAsText && startsWithSolid(header)) return;  // ASCII STL: VTK's parser reports its problems
    const std::string what = path + (sniffedAsText ? ": neither ASCII STL (it does not start with 'solid') nor binary STL: "
                                                   : ": binary STL: ");
    uint64_t size = fileSizeOrThrow(path);
    if (size < headerBytes)
        throw MeshReadError(what + "the file is " + std::to_string(size) +
                            " bytes, shorter than the 84-byte header (80-byte comment and triangle count)");
    uint32_t declaredTriangles = littleEndianUint32(header, 80);
    uint64_t storedTriangles = (size - headerBytes) / triangleBytes;
    if (declaredTriangles > storedTriangles)
        throw MeshReadError(what + "header declares " + std::to_string(declaredTriangles) +
                            " triangles but the file holds only " + std::to_string(storedTriangles) +
                            " (truncated file or wrong count)");
    // vtkSTLReader reads only the triangles the header declares. Fewer than 50 bytes after them
    // can be an exporter's padding; a whole triangle more would be dropped without a word.
    if (declaredTriangles < storedTriangles)
        throw MeshReadError(what + "header declares " + std::to_string(declaredTriangles) + " triangles but the file's " +
                            std::to_string(size) + " bytes hold " + std::to_string(storedTriangles) +
                            " (84 + 50 per triangle; is the count in the header too small?)");
    if (declaredTriangles == 0)
        throw MeshReadError(what + "header declares 0 triangles (no faces; the file is " + std::to_string(size) + " bytes)");
}

}  // namespace conescope
