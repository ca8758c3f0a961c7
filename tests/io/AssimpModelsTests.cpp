// Files nobody here wrote: assimp's test models (Debian assimp-testmodels). Every mesh file there in
// a format readMesh supports either reads with the triangle count assimp finds, or is refused with
// a reason: assimp refuses it too, or it is listed below (and in docs/user/file-formats.md) with why; the few
// read with another count than assimp's are listed with why as well.
#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "AssimpReference.h"
#include "IoTestSupport.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using testing::assimpTriangleCount;

const std::filesystem::path assimpModels = "/usr/share/assimp/models";

// Files assimp reads but readMesh refuses on purpose, relative to assimpModels, with the reason.
const std::map<std::string, std::string> refusedOnPurpose = {
    {"OBJ/number_formats.obj", "'3.1+e2' is not a number; assimp reads it as 3.1"},
    {"OFF/invalid.off", "declares 4 faces and holds 2; assimp reads the 2"},
    {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "positions are infinite; assimp reads them as they are"},
    {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf",
     "a triangle uses vertex index 24 of 24 vertices; assimp drops that triangle and reads 11"},
};

// Files readMesh reads with another triangle count than assimp on purpose, with the reason.
const std::map<std::string, std::string> readDifferentlyOnPurpose = {
    {"OBJ/box_UTF16BE.obj", "UTF-16 BE text: assimp 5.2.5 finds no mesh in it; converted, it is box.obj (ObjReaderTests)"},
};

// Every file under the formats' folders whose extension readMesh takes, sorted for stable output.
std::vector<std::filesystem::path> modelFiles() {
    std::vector<std::filesystem::path> files;
    for (const char* folder : {"OBJ", "PLY", "STL", "OFF", "glTF2"}) {
        if (!std::filesystem::is_directory(assimpModels / folder)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(assimpModels / folder))
            if (entry.is_regular_file() && hasSupportedMeshExtension(entry.path().string())) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(AssimpModels, EveryFileReadsWithAssimpsTriangleCountOrIsRefusedForAReason) {
    const std::vector<std::filesystem::path> files = modelFiles();
    if (files.empty()) GTEST_SKIP() << "install assimp-testmodels to run this test";
    size_t read = 0, refused = 0;
    for (const std::filesystem::path& file : files) {
        const std::string relative = std::filesystem::relative(file, assimpModels).string();
        std::string assimpError;
        const std::optional<size_t> expected = assimpTriangleCount(file.string(), &assimpError);
        try {
            const Mesh mesh = readMesh(file.string());
            ++read;
            EXPECT_FALSE(refusedOnPurpose.count(relative)) << relative << " is listed as refused but reads";
            if (expected && readDifferentlyOnPurpose.count(relative)) {
                EXPECT_NE(triangleCount(mesh), *expected) << relative << " is listed as read differently but agrees";
            } else if (expected) {
                EXPECT_EQ(triangleCount(mesh), *expected) << relative;
            }
        } catch (const MeshReadError& error) {
            ++refused;
            // A file assimp finds no triangles in (points, lines) is one readMesh refuses as faceless.
            EXPECT_TRUE(!expected || *expected == 0 || refusedOnPurpose.count(relative))
                << relative << ": refused, but assimp reads " << *expected << " triangles: " << error.what();
        }
    }
    RecordProperty("read", int(read));
    RecordProperty("refused", int(refused));
    EXPECT_GT(read, refused);
}

// The bundled samples, written by hand, agree with assimp as well: the reference counts what it should.
TEST(AssimpModels, ReferenceCountAgreesOnTheBundledCube) {
    for (const char* file : {"cube.ply", "cube-binary.ply", "cube.obj", "cube-ascii.stl", "cube-binary.stl"}) {
        const std::string path = (testing::formatSamplesDir() / file).string();
        EXPECT_EQ(assimpTriangleCount(path), std::optional<size_t>(12)) << file;
        EXPECT_EQ(triangleCount(readMesh(path)), 12u) << file;
    }
}

}  // namespace
}  // namespace conescope
