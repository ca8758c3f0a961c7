// checkStlFile; the other checks declared in HeaderChecks.h live in PlyCheck.cpp, ObjCheck.cpp,
// LegacyVtkCheck.cpp and VtpCheck.cpp.
#include "io/HeaderChecks.h"

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

}  // namespace

void checkStlFile(const std::string& path) {
    if (vtksys::SystemTools::DetectFileType(path.c_str()) == vtksys::SystemTools::FileTypeText) return;
    const uint64_t headerBytes = 84, triangleBytes = 50;
    uint64_t size = fileSizeOrThrow(path);
    if (size < headerBytes)
        throw MeshReadError(path + ": binary STL is " + std::to_string(size) + " bytes, shorter than its 84-byte header");
    std::string header = readPrefix(path, headerBytes);
    uint32_t declaredTriangles = 0;
    // Little-endian uint32 after the 80-byte comment.
    for (int k = 3; k >= 0; --k) declaredTriangles = (declaredTriangles << 8) | static_cast<unsigned char>(header[80 + k]);
    uint64_t storedTriangles = (size - headerBytes) / triangleBytes;
    if (declaredTriangles > storedTriangles)
        throw MeshReadError(path + ": binary STL header declares " + std::to_string(declaredTriangles) +
                            " triangles but the file holds only " + std::to_string(storedTriangles) +
                            " (truncated file or wrong count)");
    if (storedTriangles == 0) throw MeshReadError(path + ": binary STL has no triangles (no faces)");
}

}  // namespace conescope
