#include "io/FileChecks.h"

#include <charconv>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "io/MeshReader.h"

namespace conescope {

namespace filesystem = std::filesystem;

void requireReadableFile(const std::string& path) {
    std::error_code error;
    filesystem::file_status status = filesystem::status(path, error);
    if (error || !filesystem::exists(status)) throw MeshReadError(path + ": file does not exist");
    if (filesystem::is_directory(status)) throw MeshReadError(path + ": is a directory, not a mesh file");
    if (!filesystem::is_regular_file(status)) throw MeshReadError(path + ": is not a regular file");
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw MeshReadError(path + ": cannot open file for reading (" + std::strerror(errno) + ")");
    if (fileSizeOrThrow(path) == 0) throw MeshReadError(path + ": file is empty");
}

std::uintmax_t fileSizeOrThrow(const std::string& path) {
    std::error_code error;
    std::uintmax_t size = filesystem::file_size(path, error);
    if (error) throw MeshReadError(path + ": cannot determine file size (" + error.message() + ")");
    return size;
}

std::string readFileBytes(const std::string& path) {
    std::ifstream input(path, std::ios::binary);
    if (!input) throw MeshReadError(path + ": cannot open file for reading (" + std::strerror(errno) + ")");
    std::string bytes;
    // Sized from the file system, not from anything the file claims about itself.
    bytes.resize(static_cast<size_t>(fileSizeOrThrow(path)));
    input.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (input.bad()) throw MeshReadError(path + ": read error");
    bytes.resize(static_cast<size_t>(input.gcount()));
    return bytes;
}

void appendPointLine(std::string& text, const glm::vec3& point) {
    char buffer[32];
    for (int k = 0; k < 3; ++k) {
        text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, point[k]).ptr);
        text += k < 2 ? ' ' : '\n';
    }
}

void ReadProgress::report(size_t position) {
    while (next_ <= position) next_ += step;
    if (progress_ && !progress_(double(position) / double(total_), "reading")) throw OperationCancelled();
}

std::string lowerCaseExtension(const std::string& path) {
    std::string extension = filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::string quotedForMessage(const std::string& text, size_t maxLength) {
    static const char hexDigits[] = "0123456789abcdef";
    std::string quoted = "'";
    for (size_t i = 0; i < text.size() && i < maxLength; ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) {
            quoted += static_cast<char>(c);
        } else {
            quoted += "\\x";
            quoted += hexDigits[c >> 4];
            quoted += hexDigits[c & 15];
        }
    }
    if (text.size() > maxLength) quoted += "...";
    return quoted + "'";
}

}  // namespace conescope
