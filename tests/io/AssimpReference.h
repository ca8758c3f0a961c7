// An independent count for the readers' tests: what assimp makes of a file.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace conescope::testing {

// Triangles assimp reads from the file, each polygon of n corners counting n - 2 and every node
// instance of a mesh counted once per node; points and lines do not count. Empty when assimp
// refuses the file, with its message in `error` when given.
std::optional<size_t> assimpTriangleCount(const std::string& path, std::string* error = nullptr);

}  // namespace conescope::testing
