// Output files that appear whole or not at all: everything is written to a temporary file next to
// the target and renamed over it only once complete, so a failed or interrupted run never leaves a
// half-written file and an older file of the same name survives the failure.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace conescope::cli {

// Calls write(temporaryPath) with a path in the same folder that ends in the same extension as
// `path` (writers choose the format by extension), then renames it to `path`. When write throws,
// the temporary file is removed and a std::runtime_error with the same message is thrown, the
// temporary name in it replaced by `path`. Throws std::runtime_error naming `path` when the rename
// fails.
void replaceFileAtomically(const std::string& path, const std::function<void(const std::string& temporaryPath)>& write);

// Text through replaceFileAtomically. Throws std::runtime_error naming `path` on an I/O failure.
void writeTextFileAtomically(const std::string& path, const std::string& text);

// True when the lower-cased extension of `path` (with the dot) is one of `extensions`.
bool hasExtension(const std::string& path, const std::vector<std::string>& extensions);

}  // namespace conescope::cli
