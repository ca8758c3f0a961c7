// Every reader behind readMesh, on arbitrary bytes: the first byte picks the format, the rest is the
// file. Either a valid mesh or a MeshReadError. Formats 8 and 9 are meshlet files (JSON, binary) put
// on a 2 x 2 grid of squares: either a partition of its faces or a ClusterFileError. Formats 10 and
// 11 are cluster LOD hierarchy files (JSON, binary) of the same grid: either a hierarchy whose every
// level covers the grid or a MeshletFileError / HierarchyError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/lod/HierarchyRecords.h"
#include "io/ClusterFiles.h"
#include "io/MeshReader.h"
#include "io/MeshletFiles.h"

namespace {

// 9 vertices, 8 triangles: what tests/data/meshlets' seeds partition.
conescope::Mesh grid() {
    conescope::Mesh mesh;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) mesh.positions.emplace_back(float(x), float(y), 0.0f);
    for (uint32_t y = 0; y < 2; ++y)
        for (uint32_t x = 0; x < 2; ++x) {
            const uint32_t a = 3 * y + x;
            mesh.addFace({a, a + 1, a + 4});
            mesh.addFace({a, a + 4, a + 3});
        }
    return mesh;
}

void meshletFile(const std::string& path) {
    conescope::Mesh mesh = grid();
    std::vector<std::string> notes;
    try {
        conescope::readClusterFile(mesh, path, notes);
        const conescope::FileClusters& clusters = mesh.fileClusters.at(path);
        if (clusters.clusterOfFace.size() != mesh.faceCount()) __builtin_trap();
        for (uint32_t c : clusters.clusterOfFace)
            if (c >= clusters.clusterCount) __builtin_trap();
    } catch (const conescope::ClusterFileError&) {
    }
}

void hierarchyFile(const std::string& path) {
    static const conescope::PreparedMesh prepared = conescope::prepareMesh(std::make_shared<const conescope::Mesh>(grid()), "grid", false);
    try {
        const conescope::ClusterHierarchy hierarchy = conescope::hierarchyFromRecords(prepared, conescope::readHierarchyFile(path), {});
        if (hierarchy.levels.empty()) __builtin_trap();
        for (const conescope::LodLevel& level : hierarchy.levels)
            if (level.place.size() != level.clusters.partition.clusterCount) __builtin_trap();
    } catch (const conescope::MeshletFileError&) {
    } catch (const conescope::HierarchyError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    static const char* const extensions[] = {".off", ".ply", ".obj", ".stl", ".vtp", ".vtk", ".gltf", ".glb", ".json", ".meshlets", ".json", ".lod"};
    const size_t format = data[0] % 12;
    const std::string path = "/tmp/conescope-fuzz-" + std::to_string(getpid()) + extensions[format];
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    if (format >= 10) {
        hierarchyFile(path);
        return 0;
    }
    if (format >= 8) {
        meshletFile(path);
        return 0;
    }
    try {
        const conescope::Mesh mesh = conescope::readMesh(path);
        if (mesh.faceCount() == 0) __builtin_trap();
    } catch (const conescope::MeshReadError&) {
    }
    return 0;
}
