// Every reader behind readMesh, on arbitrary bytes: the first byte picks the format, the rest is the
// file. Either a valid mesh or a MeshReadError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "io/MeshReader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    static const char* const extensions[] = {".off", ".ply", ".obj", ".stl", ".vtp", ".vtk", ".gltf", ".glb"};
    const std::string path = "/tmp/conescope-fuzz-" + std::to_string(getpid()) + extensions[data[0] % 8];
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    try {
        const conescope::Mesh mesh = conescope::readMesh(path);
        if (mesh.faceCount() == 0) __builtin_trap();
    } catch (const conescope::MeshReadError&) {
    }
    return 0;
}
