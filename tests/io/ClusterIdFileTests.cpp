// Cluster id files, read by io for the file builder (io/ClusterIdFile.h): the ids, the errors with
// the path and line, and the settings carrying what was read to core's buildPartition.
#include <gtest/gtest.h>

#include <stdexcept>

#include "IoTestSupport.h"
#include "core/BuildPartition.h"
#include "io/ClusterIdFile.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

std::string errorOf(const std::function<void()>& run) {
    try {
        run();
    } catch (const std::exception& error) {
        return error.what();
    }
    return "(no error)";
}

TEST(ClusterIdFile, OneIdPerFaceWithComments) {
    const testing::ScratchDirectory scratch;
    const std::string path = scratch.writeFile("ids.txt", "# cluster per face\n4 4\n5 # trailing comment\n");
    EXPECT_EQ(readClusterIdFile(path), (std::vector<double>{4, 4, 5}));
    const std::string bad = scratch.writeFile("bad.txt", "1 2\n1 x 2\n");
    EXPECT_EQ(errorOf([&] { readClusterIdFile(bad); }), bad + ":2: 'x' is not a number");
    EXPECT_EQ(errorOf([&] { readClusterIdFile(path + ".missing"); }), path + ".missing: cannot open cluster id file");
}

TEST(ClusterIdFile, NumbersReadTheSameUnderACommaLocale) {
    const testing::ScratchDirectory scratch;
    const std::string path = scratch.writeFile("ids.txt", "1 2.5 3\n");
    const testing::ScopedCommaDecimalLocale german;
    EXPECT_EQ(readClusterIdFile(path), (std::vector<double>{1, 2.5, 3}));
}

TEST(ClusterIdFile, SettingsCarryTheIdsToTheFileBuilder) {
    const testing::ScratchDirectory scratch;
    const Mesh mesh = readMeshFile((testing::datasetsDir() / "cube.off").string()).mesh;
    std::string ids;
    for (size_t f = 0; f < mesh.faceCount(); ++f) ids += std::to_string(f / 4) + "\n";
    Settings settings;
    settings.clusterFile = scratch.writeFile("ids.txt", ids);
    EXPECT_FALSE(withClusterIds(settings).clusterIds) << "read only for the file builder";
    settings.builder = Builder::File;
    const Settings read = withClusterIds(settings);
    ASSERT_TRUE(read.clusterIds);
    EXPECT_EQ(read.clusterIds->ids.size(), mesh.faceCount());
    EXPECT_EQ(buildPartition(mesh, computeFaceGeometry(mesh), read).clusterCount, (mesh.faceCount() + 3) / 4);
    // A file that cannot be read: its error comes from buildPartition, where core once read it.
    settings.clusterFile = scratch.file("missing.txt");
    const Settings missing = withClusterIds(settings);
    EXPECT_EQ(errorOf([&] { buildPartition(mesh, computeFaceGeometry(mesh), missing); }),
              settings.clusterFile + ": cannot open cluster id file");
}

}  // namespace
}  // namespace conescope
