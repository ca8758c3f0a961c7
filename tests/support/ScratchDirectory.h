// A scratch directory for tests that write files, shared by the io and cli tests.
#pragma once

#include <filesystem>
#include <string>

namespace conescope::testing {

// A fresh directory under the system temp dir (unique even when ctest runs tests in parallel),
// removed with everything in it on destruction.
class ScratchDirectory {
public:
    ScratchDirectory();
    ~ScratchDirectory();
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    const std::filesystem::path& path() const { return path_; }
    // Writes bytes verbatim (binary mode) and returns the file's full path.
    std::string writeFile(const std::string& name, const std::string& bytes) const;
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

}  // namespace conescope::testing
