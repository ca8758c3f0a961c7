// assimp's glTF 2.0 test models (Debian assimp-testmodels) against counts that do not come from
// assimp: assimp decodes glTF for the reader, so AssimpModelsTests' count is not independent here.
// The triangle count of the default scene is worked out from the JSON alone (accessor counts and
// primitive modes per node), and the glTF Asset Generator's primitive-mode models, all one square
// facing +z, are checked for winding.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "IoTestSupport.h"
#include "io/FileChecks.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using nlohmann::json;

const std::filesystem::path gltfModels = "/usr/share/assimp/models/glTF2";

json documentOf(const std::string& path) {
    const std::string bytes = readFileBytes(path);
    if (bytes.compare(0, 4, "glTF") != 0) return json::parse(bytes);
    uint32_t jsonLength = 0;
    for (int k = 0; k < 4; ++k) jsonLength |= uint32_t(uint8_t(bytes[12 + k])) << (8 * k);
    return json::parse(bytes.substr(20, jsonLength));
}

// Triangles per drawn primitive: count / 3 for lists, count - 2 for strips and fans (count being
// the indices' count, else the positions'), none for points and lines; per node that uses the mesh,
// over the default scene ("scene", else scene 0, else every node that is nobody's child).
size_t jsonTriangleCount(const json& d) {
    std::vector<size_t> roots;
    if (d.contains("scenes") && !d["scenes"].empty()) {
        for (const json& node : d["scenes"][d.value("scene", 0)].value("nodes", json::array())) roots.push_back(node);
    } else {
        std::vector<bool> isChild(d["nodes"].size());
        for (const json& node : d["nodes"])
            for (const json& child : node.value("children", json::array())) isChild[child.get<size_t>()] = true;
        for (size_t n = 0; n < isChild.size(); ++n)
            if (!isChild[n]) roots.push_back(n);
    }
    std::function<size_t(size_t)> under = [&](size_t n) {
        const json& node = d["nodes"][n];
        size_t triangles = 0;
        if (node.contains("mesh"))
            for (const json& primitive : d["meshes"][node["mesh"].get<size_t>()]["primitives"]) {
                const int mode = primitive.value("mode", 4);
                const json& counted = primitive.contains("indices") ? d["accessors"][primitive["indices"].get<size_t>()]
                                                                    : d["accessors"][primitive["attributes"]["POSITION"].get<size_t>()];
                const size_t count = counted["count"];
                triangles += mode == 4 ? count / 3 : (mode == 5 || mode == 6) && count >= 3 ? count - 2 : 0;
            }
        for (const json& child : node.value("children", json::array())) triangles += under(child.get<size_t>());
        return triangles;
    };
    size_t triangles = 0;
    for (size_t root : roots) triangles += under(root);
    return triangles;
}

std::vector<std::filesystem::path> modelFiles(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    if (!std::filesystem::is_directory(folder)) return files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
        const std::string extension = lowerCaseExtension(entry.path().string());
        if (extension == ".gltf" || extension == ".glb") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(GltfModels, EveryModelReadHasTheTriangleCountOfItsJson) {
    const std::vector<std::filesystem::path> files = modelFiles(gltfModels);
    if (files.empty()) GTEST_SKIP() << "install assimp-testmodels to run this test";
    size_t read = 0;
    for (const std::filesystem::path& file : files) {
        Mesh mesh;
        try {
            mesh = readMesh(file.string());
        } catch (const MeshReadError&) {
            continue;  // AssimpModelsTests checks every refusal has a reason
        }
        ++read;
        EXPECT_EQ(triangleCount(mesh), jsonTriangleCount(documentOf(file.string()))) << file;
    }
    EXPECT_GE(read, 25u);
}

// Models 04-06 and 11-15 draw one square facing the viewer on +z as a strip, fan or list, indexed by
// bytes, shorts or ints or not at all; 00-03 and 07-10 draw points and lines, which are no faces.
TEST(GltfModels, AssetGeneratorPrimitiveModesFaceTheViewer) {
    const std::filesystem::path folder = gltfModels / "glTF-Asset-Generator" / "Mesh_PrimitiveMode";
    const std::vector<std::filesystem::path> files = modelFiles(folder);
    if (files.empty()) GTEST_SKIP() << "install assimp-testmodels to run this test";
    ASSERT_EQ(files.size(), 16u);
    for (int model = 0; model < 16; ++model) {
        const std::string path = (folder / ("Mesh_PrimitiveMode_" + std::string(model < 10 ? "0" : "") +
                                            std::to_string(model) + ".gltf")).string();
        const bool triangles = (model >= 4 && model <= 6) || model >= 11;
        if (!triangles) {
            EXPECT_READ_ERROR(path, "no triangles in the scene (it holds 1 primitive of points or lines)");
            continue;
        }
        const Mesh mesh = readMesh(path);
        EXPECT_EQ(mesh.faceCount(), 2u) << path;
        EXPECT_EQ(mesh.positions.size(), 4u) << path;
        const FaceGeometry faces = computeFaceGeometry(mesh);
        for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_NEAR(faces.normals[f].z, 1.0, 1e-9) << path << " face " << f;
    }
}

// The Draco-compressed engine, decoded by assimp's Draco, fills the box of the uncompressed engine
// (Draco quantises positions, so the boxes agree to a small part of their size).
TEST(GltfModels, DracoEngineDecodesIntoThePlainEnginesBox) {
    const std::filesystem::path draco = gltfModels / "draco" / "2CylinderEngine.gltf";
    const std::filesystem::path plain = gltfModels / "2CylinderEngine-glTF-Binary" / "2CylinderEngine.glb";
    if (!std::filesystem::exists(draco) || !std::filesystem::exists(plain)) GTEST_SKIP() << "install assimp-testmodels";
    const Mesh dracoMesh = readMesh(draco.string());
    EXPECT_EQ(triangleCount(dracoMesh), jsonTriangleCount(documentOf(draco.string())));
    const Aabb dracoBox = computeAabb(dracoMesh.positions), plainBox = computeAabb(readMesh(plain.string()).positions);
    const float tolerance = 1e-3f * glm::length(plainBox.max - plainBox.min);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(dracoBox.min[k], plainBox.min[k], tolerance) << k;
        EXPECT_NEAR(dracoBox.max[k], plainBox.max[k], tolerance) << k;
    }
}

}  // namespace
}  // namespace conescope
