#include "io/GltfReader.h"

#include <cmath>
#include <cstdint>

#include <assimp/mesh.h>

#include "io/GltfDecoding.h"
#include "io/GltfDocument.h"
#include "io/FormatModules.h"
#include "io/MeshReader.h"
#include "io/PositionMerging.h"

namespace conescope {

namespace {

std::string counted(size_t count, const std::string& singular, const std::string& plural) {
    return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

void reportOrCancel(const ProgressCallback& progress, double fraction, const std::string& stage) {
    if (progress && !progress(fraction, stage)) throw OperationCancelled();
}

std::vector<std::string> skippedNotes(const GltfSkipped& skipped) {
    std::vector<std::string> notes;
    if (skipped.pointOrLinePrimitives)
        notes.push_back("Skipped " + counted(skipped.pointOrLinePrimitives, "primitive", "primitives") +
                        " of points or lines: they have no faces.");
    if (skipped.shortPrimitives)
        notes.push_back("Skipped " + counted(skipped.shortPrimitives, "triangle primitive", "triangle primitives") +
                        " with fewer than 3 vertices.");
    if (skipped.unfinishedTriangles)
        notes.push_back(counted(skipped.unfinishedTriangles, "triangle list ends", "triangle lists end") +
                        " with 1 or 2 vertices that make no whole triangle; they were ignored.");
    if (skipped.skinnedOrMorphed)
        notes.push_back(counted(skipped.skinnedOrMorphed, "mesh instance has", "mesh instances have") +
                        " a skin or morph targets, which are not applied: read in the rest shape.");
    if (skipped.gpuInstancing)
        notes.push_back("The file uses EXT_mesh_gpu_instancing, which is not applied: each mesh counts once per node.");
    return notes;
}

std::string describeNoTriangles(const GltfSkipped& skipped) {
    std::string text = "no triangles in the scene";
    if (skipped.pointOrLinePrimitives)
        text += " (it holds " + counted(skipped.pointOrLinePrimitives, "primitive", "primitives") + " of points or lines)";
    else if (skipped.shortPrimitives)
        text += " (its triangle primitives have fewer than 3 vertices)";
    return text;
}

// Appends one instance of a decoded primitive: world positions, and its triangles with the corner
// order reversed when the instance is mirrored.
void appendInstance(const aiMesh& primitive, const glm::dmat4& world, bool mirrored, Mesh& mesh) {
    const uint32_t base = uint32_t(mesh.positions.size());
    for (unsigned v = 0; v < primitive.mNumVertices; ++v) {
        const aiVector3D& p = primitive.mVertices[v];
        mesh.positions.push_back(glm::vec3(world * glm::dvec4(p.x, p.y, p.z, 1.0)));
    }
    for (unsigned f = 0; f < primitive.mNumFaces; ++f) {
        const unsigned* corners = primitive.mFaces[f].mIndices;
        if (mirrored)
            mesh.faceVertices.insert(mesh.faceVertices.end(), {base + corners[2], base + corners[1], base + corners[0]});
        else
            mesh.faceVertices.insert(mesh.faceVertices.end(), {base + corners[0], base + corners[1], base + corners[2]});
        mesh.faceStarts.push_back(uint32_t(mesh.faceVertices.size()));
    }
}

// Fails when a node's transform carried a vertex out of float range.
void requireFiniteWorld(const std::string& path, const GltfInstance& instance, const Mesh& mesh, size_t from) {
    for (size_t v = from; v < mesh.positions.size(); ++v)
        if (!std::isfinite(mesh.positions[v].x) || !std::isfinite(mesh.positions[v].y) || !std::isfinite(mesh.positions[v].z))
            throw MeshReadError(path + ": nodes[" + std::to_string(instance.node) +
                                "]: its world transform moves a vertex beyond the range of float coordinates");
}

// Every instance in world space; progress by vertices placed.
Mesh placeInstances(const std::string& path, const GltfScene& scene, const GltfDecoded& decoded,
                    const ProgressCallback& progress) {
    uint64_t vertices = 0, triangles = 0;
    for (const GltfInstance& instance : scene.instances)
        for (const GltfPrimitive& primitive : scene.meshes[instance.mesh].primitives) {
            vertices += primitive.vertexCount;
            triangles += primitive.triangleCount;
        }
    if (vertices > UINT32_MAX || 3 * triangles > UINT32_MAX)
        throw MeshReadError(path + ": the scene's instances hold " + std::to_string(vertices) + " vertices and " +
                            std::to_string(triangles) + " triangles, more than 32-bit indices can number");
    Mesh mesh;
    mesh.positions.reserve(size_t(vertices));
    mesh.faceVertices.reserve(size_t(3 * triangles));
    mesh.faceStarts.reserve(size_t(triangles + 1));
    double reported = 0.0;
    // Each placed primitive is a group: a cluster per primitive for the file builder.
    std::vector<double>& groupOfFace = mesh.faceArrays["group_id"];
    double group = 0.0;
    for (const GltfInstance& instance : scene.instances) {
        const size_t firstVertex = mesh.positions.size();
        const bool mirrored = glm::determinant(glm::dmat3(instance.world)) < 0;
        const std::vector<const aiMesh*>& primitives = decoded.primitives[instance.mesh];
        for (const aiMesh* primitive : primitives) {
            appendInstance(*primitive, instance.world, mirrored, mesh);
            groupOfFace.resize(mesh.faceCount(), group++);
        }
        requireFiniteWorld(path, instance, mesh, firstVertex);
        const double fraction = double(mesh.positions.size()) / double(vertices);
        if (fraction - reported >= 0.01 || fraction == 1.0) reportOrCancel(progress, reported = fraction, "placing glTF instances");
    }
    return mesh;
}

}  // namespace

Mesh readGltf(const std::string& path, std::vector<std::string>& notes, const ProgressCallback& progress) {
    reportOrCancel(progress, 0.0, "reading glTF");
    const GltfScene scene = loadGltfScene(path);
    if (scene.instances.empty()) throw MeshReadError(path + ": " + describeNoTriangles(scene.skipped));
    const GltfDecoded decoded = decodeGltfPrimitives(path, scene, progressWithin(progress, 0.05, 0.6));
    Mesh mesh = placeInstances(path, scene, decoded, progressWithin(progress, 0.6, 0.95));
    for (std::string& note : skippedNotes(scene.skipped)) notes.push_back(std::move(note));
    return mesh;
}

extern "C" const GltfFormat* conescope_gltf_format() {
    static const GltfFormat format{readGltf};
    return &format;
}

}  // namespace conescope
