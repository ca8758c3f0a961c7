// Small file helpers shared by the readers (internal to conescope_io).
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "core/Progress.h"

namespace conescope {

// Throws MeshReadError "path: what" unless path names an existing, readable, non-empty regular
// file. Done before handing a path to VTK, whose readers report these cases unevenly.
void requireReadableFile(const std::string& path);

// Size in bytes; throws MeshReadError when it cannot be determined.
std::uintmax_t fileSizeOrThrow(const std::string& path);

// The whole file as bytes. Throws MeshReadError on open or read failure.
std::string readFileBytes(const std::string& path);

// A parser's progress through its bytes, reported about once per megabyte as stage "reading";
// throws OperationCancelled when the callback says stop. Does nothing without a callback.
class ReadProgress {
public:
    ReadProgress(const ProgressCallback& progress, size_t totalBytes) : progress_(progress), total_(totalBytes) {}
    void at(size_t position) {
        if (position >= next_) report(position);
    }

private:
    void report(size_t position);
    const ProgressCallback& progress_;
    size_t total_;
    size_t next_ = step;
    static constexpr size_t step = size_t(1) << 20;
};

// "x y z\n": each the shortest text that reads back to the same float, '.' whatever the locale.
void appendPointLine(std::string& text, const glm::vec3& point);

// Lower-case extension with the dot (".off"), or "" when the name has none.
std::string lowerCaseExtension(const std::string& path);

// A token or header fragment made safe to quote in a message: printable ASCII kept, other bytes
// as \xNN, cut to maxLength characters with "..." so binary garbage cannot flood the message.
std::string quotedForMessage(const std::string& text, size_t maxLength = 32);

}  // namespace conescope
