#include "batch/OutputFiles.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <unistd.h>

namespace conescope::cli {

namespace {

// ".name.partial-PID.ext" beside the target: hidden, unique per process, and on the same file
// system so the final rename is atomic.
std::filesystem::path temporaryPathFor(const std::filesystem::path& target) {
    const std::string name = "." + target.filename().string() + ".partial-" + std::to_string(::getpid()) +
                             target.extension().string();
    return target.parent_path() / name;
}

}  // namespace

void replaceFileAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    const std::filesystem::path target(path);
    if (target.filename().empty()) throw std::runtime_error(path + ": not a file name");
    const std::filesystem::path temporary = temporaryPathFor(target);
    try {
        write(temporary.string());
    } catch (const std::exception& error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        // Writers name the file they were given; the user knows only the target.
        std::string message = error.what();
        const std::string temporaryName = temporary.string();
        for (size_t at = message.find(temporaryName); at != std::string::npos; at = message.find(temporaryName, at + path.size()))
            message.replace(at, temporaryName.size(), path);
        throw std::runtime_error(message);
    }
    if (std::rename(temporary.c_str(), target.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error(path + ": cannot write (" + reason + ")");
    }
}

void writeTextFileAtomically(const std::string& path, const std::string& text) {
    replaceFileAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
        out.write(text.data(), std::streamsize(text.size()));
        out.close();
        if (!out) throw std::runtime_error(path + ": write failed");
    });
}

bool hasExtension(const std::string& path, const std::vector<std::string>& extensions) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

}  // namespace conescope::cli
