// meshoptimizer's builder as ConeScope reproduces it (core/meshopt/Meshopt.h) against the linked
// library on files nobody here wrote: the bundled meshes, the CGAL meshes when fetched, and every
// assimp test model that reads. The meshlet counts are equal; so are the partitions of faces
// wherever no two faces share their corners (the library's output is matched back to faces by
// corners, which cannot tell such faces apart). Triangle-by-triangle equality is in tests/core.
#include <algorithm>
#include <array>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "core/Partition.h"
#include "core/meshopt/Meshopt.h"
#include "core/meshopt/Reproduction.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

bool facesShareCorners(const Mesh& mesh) {
    std::set<std::vector<uint32_t>> seen;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        std::vector<uint32_t> corners(mesh.faceBegin(f), mesh.faceBegin(f) + mesh.faceSize(f));
        std::sort(corners.begin(), corners.end());
        if (!seen.insert(corners).second) return true;
    }
    return false;
}

// Returns how many files were compared.
size_t compareFilesUnder(const std::filesystem::path& folder, bool recursive) {
    if (!std::filesystem::is_directory(folder)) return 0;
    std::vector<std::filesystem::path> files;
    auto add = [&](const std::filesystem::directory_entry& entry) {
        if (entry.is_regular_file() && hasSupportedMeshExtension(entry.path().string())) files.push_back(entry.path());
    };
    if (recursive)
        for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) add(entry);
    else
        for (const auto& entry : std::filesystem::directory_iterator(folder)) add(entry);
    std::sort(files.begin(), files.end());
    size_t compared = 0;
    for (const std::filesystem::path& file : files) {
        Mesh mesh;
        try {
            mesh = readMeshFile(file.string()).mesh;
        } catch (const std::exception&) {
            continue;  // refused files are the readers' tests' business
        }
        if (mesh.faceCount() == 0) continue;
        SCOPED_TRACE(file.string());
        for (const MeshletLimits limits : {MeshletLimits{64, 124}, MeshletLimits{32, 64}}) {
            const Partition library = meshoptLibraryMeshlets(mesh, limits, 1.0f);
            const Partition ours = meshoptReproducedMeshlets(mesh, limits, 1.0f);
            EXPECT_EQ(ours.clusterCount, library.clusterCount);
            if (!facesShareCorners(mesh)) {
                EXPECT_EQ(ours.clusterOfFace, library.clusterOfFace);
            }
            // Of polygons split across meshlets, a meshlet may hold no polygon's first triangle
            // and then no face: the meshlet count and the partition's agree on triangles only.
            if (triangleCount(mesh) == mesh.faceCount()) {
                EXPECT_EQ(meshoptMeshletCount(mesh, limits, 1.0f), library.clusterCount);
            }
        }
        ++compared;
    }
    return compared;
}

TEST(MeshoptReproduction, SameMeshletsAsTheLibraryOnBundledAndFetchedMeshes) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    EXPECT_GE(compareFilesUnder(testing::datasetsDir(), false), 7u);
    compareFilesUnder(testing::datasetsDir() / "cgal", false);  // scripts/fetch-datasets.sh
}

TEST(MeshoptReproduction, SameMeshletsAsTheLibraryOnAssimpsModels) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();
    const size_t compared = compareFilesUnder("/usr/share/assimp/models", true);
    if (compared == 0) GTEST_SKIP() << "install assimp-testmodels to run this test";
    EXPECT_GE(compared, 50u);
}

}  // namespace
}  // namespace conescope
