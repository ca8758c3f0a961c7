// Opens the format modules the first time a file needs one (FormatModules.h).
#include "io/FormatModules.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace conescope {

namespace {

// Where a module may be: beside the executable (the build's own layout for the CLI and tools), in
// ../lib/conescope (installed), and where this build made it.
std::vector<std::string> moduleCandidates(const std::string& name, const std::string& built) {
    std::vector<std::string> candidates;
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const std::filesystem::path folder = executable.parent_path();
        candidates.push_back((folder / name).string());
        candidates.push_back((folder / ".." / "lib" / "conescope" / name).string());
    }
    candidates.push_back(built);
    return candidates;
}

// The table a module's entry point returns; `what` names the formats for the message when the
// module cannot be found.
template <class Table>
const Table* openModule(const std::string& name, const std::string& built, const char* entryName, const std::string& what) {
    std::string tried;
    for (const std::string& path : moduleCandidates(name, built)) {
        if (!std::filesystem::exists(path)) {
            tried += (tried.empty() ? "" : ", ") + path;
            continue;
        }
        void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open for the process
        if (!module) throw std::runtime_error("cannot open " + name + ": " + dlerror());
        auto entry = reinterpret_cast<const Table* (*)()>(dlsym(module, entryName));
        if (!entry) throw std::runtime_error(path + " is not ConeScope's module (no " + entryName + ")");
        return entry();
    }
    throw std::runtime_error(what + " needs " + name + ", which is not in " + tried);
}

}  // namespace

const VtkFormats& vtkFormats() {
    // A failure is thrown again at the next call.
    static const VtkFormats* formats = openModule<VtkFormats>(CONESCOPE_VTK_FORMATS_NAME, CONESCOPE_VTK_FORMATS_BUILT,
                                                              "conescope_vtk_formats", "reading and writing STL, VTP and VTK files");
    return *formats;
}

const GltfFormat& gltfFormat() {
    static const GltfFormat* format = openModule<GltfFormat>(CONESCOPE_GLTF_FORMAT_NAME, CONESCOPE_GLTF_FORMAT_BUILT,
                                                             "conescope_gltf_format", "reading glTF files");
    return *format;
}

}  // namespace conescope
