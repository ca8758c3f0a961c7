// Opens libconescope_vtk_formats.so the first time a VTK format is read or written (VtkFormats.h).
#include "io/VtkFormats.h"

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace conescope {

namespace {

// Where the module may be: beside the executable (the build's own layout for the CLI and tools),
// in ../lib/conescope (installed), and where this build made it.
std::vector<std::string> moduleCandidates() {
    std::vector<std::string> candidates;
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const std::filesystem::path folder = executable.parent_path();
        candidates.push_back((folder / CONESCOPE_VTK_FORMATS_NAME).string());
        candidates.push_back((folder / ".." / "lib" / "conescope" / CONESCOPE_VTK_FORMATS_NAME).string());
    }
    candidates.push_back(CONESCOPE_VTK_FORMATS_BUILT);
    return candidates;
}

const VtkFormats* openModule() {
    std::string tried;
    for (const std::string& path : moduleCandidates()) {
        if (!std::filesystem::exists(path)) {
            tried += (tried.empty() ? "" : ", ") + path;
            continue;
        }
        void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept open for the process
        if (!module) throw std::runtime_error(std::string("cannot open the VTK formats module: ") + dlerror());
        auto entry = reinterpret_cast<const VtkFormats* (*)()>(dlsym(module, "conescope_vtk_formats"));
        if (!entry) throw std::runtime_error(path + " is not the VTK formats module (no conescope_vtk_formats)");
        return entry();
    }
    throw std::runtime_error(std::string("reading and writing STL, VTP and VTK files needs ") + CONESCOPE_VTK_FORMATS_NAME +
                             ", which is not in " + tried);
}

}  // namespace

const VtkFormats& vtkFormats() {
    static const VtkFormats* formats = openModule();  // a failure is thrown again at the next call
    return *formats;
}

}  // namespace conescope
