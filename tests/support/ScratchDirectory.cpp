#include "ScratchDirectory.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace conescope::testing {

ScratchDirectory::ScratchDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "conescope-test-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch directory");
    path_ = pattern;
}

ScratchDirectory::~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

std::string ScratchDirectory::writeFile(const std::string& name, const std::string& bytes) const {
    std::string fullPath = file(name);
    std::ofstream out(fullPath, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + fullPath);
    return fullPath;
}

}  // namespace conescope::testing
