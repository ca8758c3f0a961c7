#include "BenchSupport.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <stdexcept>
#include <unordered_map>

#include "core/Adjacency.h"

namespace conescope::bench {

std::string sourceDirectory() { return CONESCOPE_SOURCE_DIR; }

std::vector<std::string> meshFiles(const std::string& directoryOrFile) {
    namespace fs = std::filesystem;
    if (fs::is_regular_file(directoryOrFile)) return {directoryOrFile};
    if (!fs::is_directory(directoryOrFile))
        throw std::runtime_error(directoryOrFile + ": no such file or directory (run scripts/fetch-datasets.sh?)");
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(directoryOrFile)) {
        std::string extension = entry.path().extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
        if (entry.is_regular_file() && extension == ".off") files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) throw std::runtime_error(directoryOrFile + ": holds no .off meshes");
    return files;
}

std::string meshName(const std::string& path) { return std::filesystem::path(path).stem().string(); }

namespace {

// One 1->4 split of a triangle list; midpoints are shared through an edge -> vertex map.
Mesh subdivideOnce(const Mesh& mesh) {
    Mesh finer;
    finer.model = mesh.model;
    finer.positions = mesh.positions;
    finer.faceVertices.reserve(mesh.faceVertices.size() * 4);
    finer.faceStarts.reserve(mesh.faceCount() * 4 + 1);
    std::unordered_map<uint64_t, uint32_t> midpoints;
    midpoints.reserve(mesh.faceCount() * 2);
    auto midpoint = [&](uint32_t a, uint32_t b) {
        auto [it, inserted] = midpoints.try_emplace(edgeKey(a, b), uint32_t(finer.positions.size()));
        if (inserted) finer.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
        return it->second;
    };
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* face = mesh.faceBegin(f);
        const uint32_t a = face[0], b = face[1], c = face[2];
        const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        finer.addFace({a, ab, ca});
        finer.addFace({b, bc, ab});
        finer.addFace({c, ca, bc});
        finer.addFace({ab, bc, ca});
    }
    return finer;
}

}  // namespace

Mesh subdivideToAtLeast(const Mesh& mesh, size_t minTriangles) {
    Mesh triangles;
    triangles.model = mesh.model;
    triangles.positions = mesh.positions;
    const std::vector<unsigned int> fan = fanTriangles(mesh);
    for (size_t t = 0; t < fan.size(); t += 3) triangles.addFace({fan[t], fan[t + 1], fan[t + 2]});
    if (triangles.faceCount() == 0) throw std::invalid_argument("subdivideToAtLeast: the mesh has no faces");
    while (triangles.faceCount() < minTriangles) triangles = subdivideOnce(triangles);
    return triangles;
}

MeshoptClusters buildMeshoptClusters(const std::vector<unsigned int>& indices, const std::vector<glm::vec3>& world,
                                     const MeshletLimits& limits, float coneWeight) {
    MeshoptClusters clusters;
    const size_t maxMeshlets = meshopt_buildMeshletsBound(indices.size(), limits.maxVertices, limits.maxTriangles);
    clusters.meshlets.resize(maxMeshlets);
    clusters.vertices.resize(maxMeshlets * limits.maxVertices);
    clusters.triangles.resize(maxMeshlets * limits.maxTriangles * 3);
    const size_t count = meshopt_buildMeshlets(clusters.meshlets.data(), clusters.vertices.data(), clusters.triangles.data(),
                                               indices.data(), indices.size(), &world[0].x, world.size(),
                                               sizeof(glm::vec3), limits.maxVertices, limits.maxTriangles, coneWeight);
    // Trim to what was used, as meshoptimizer's demo does.
    clusters.meshlets.resize(count);
    if (count > 0) {
        const meshopt_Meshlet& last = clusters.meshlets.back();
        clusters.vertices.resize(last.vertex_offset + last.vertex_count);
        clusters.triangles.resize(last.triangle_offset + ((last.triangle_count * 3 + 3) & ~3u));
    }
    clusters.bounds.resize(count);
    for (size_t m = 0; m < count; ++m) {
        const meshopt_Meshlet& meshlet = clusters.meshlets[m];
        clusters.bounds[m] = meshopt_computeMeshletBounds(&clusters.vertices[meshlet.vertex_offset],
                                                          &clusters.triangles[meshlet.triangle_offset],
                                                          meshlet.triangle_count, &world[0].x, world.size(),
                                                          sizeof(glm::vec3));
    }
    return clusters;
}

MeshletTriangles meshletTriangleMesh(const MeshoptClusters& clusters, const std::vector<glm::vec3>& world) {
    MeshletTriangles result;
    result.mesh.positions = world;  // already in world space: the model matrix stays the identity
    result.faceStarts.push_back(0);
    for (const meshopt_Meshlet& meshlet : clusters.meshlets) {
        for (size_t t = 0; t < meshlet.triangle_count; ++t) {
            uint32_t face[3];
            for (int k = 0; k < 3; ++k)
                face[k] = clusters.vertices[meshlet.vertex_offset + clusters.triangles[meshlet.triangle_offset + 3 * t + k]];
            result.mesh.addFace(face, 3);
        }
        result.faceStarts.push_back(uint32_t(result.mesh.faceCount()));
    }
    return result;
}

double peakResidentMiB() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // in kB
    throw std::runtime_error("no VmHWM in /proc/self/status");
}

bool resetPeakResident() {
    std::ofstream clearRefs("/proc/self/clear_refs");
    clearRefs << "5" << std::flush;  // 5: the peak resident size back to the current one
    return bool(clearRefs);
}

}  // namespace conescope::bench
