// A cluster LOD hierarchy's records as files: the JSON and the binary form hold the same records and
// give back the built hierarchy's numbers; every fault of a binary file is refused, named.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <memory>

#include "IcosphereHierarchy.h"
#include "io/MeshletFiles.h"

namespace conescope {
namespace {

#define EXPECT_HAS(text, fragment) EXPECT_NE(std::string(text).find(fragment), std::string::npos) << (text)

// The icosphere(4) hierarchy every LOD suite walks, and its records.
class HierarchyFiles : public testmesh::IcosphereHierarchy<4> {
protected:
    static void SetUpTestSuite() {
        IcosphereHierarchy::SetUpTestSuite();
        records_ = std::make_unique<HierarchyRecords>(hierarchyRecordsOf(*hierarchy_, {}));
    }
    static void TearDownTestSuite() {
        records_.reset();
        IcosphereHierarchy::TearDownTestSuite();
    }
    static inline std::unique_ptr<HierarchyRecords> records_;
};

void expectSameRecords(const HierarchyRecords& a, const HierarchyRecords& b) {
    EXPECT_EQ(a.arrays.meshlets, b.arrays.meshlets);
    EXPECT_EQ(a.arrays.vertices, b.arrays.vertices);
    EXPECT_EQ(a.arrays.triangles, b.arrays.triangles);
    ASSERT_EQ(a.clusters.size(), b.clusters.size());
    for (size_t m = 0; m < a.clusters.size(); ++m) {
        EXPECT_EQ(a.clusters[m].level, b.clusters[m].level) << m;
        EXPECT_EQ(a.clusters[m].group, b.clusters[m].group) << m;
        EXPECT_EQ(a.clusters[m].refined, b.clusters[m].refined) << m;
        EXPECT_EQ(a.clusters[m].sphere.center, b.clusters[m].sphere.center) << m;
        EXPECT_EQ(a.clusters[m].sphere.radius, b.clusters[m].sphere.radius) << m;
        EXPECT_EQ(a.clusters[m].error, b.clusters[m].error) << m;
    }
    ASSERT_EQ(a.groups.size(), b.groups.size());
    for (size_t g = 0; g < a.groups.size(); ++g) {
        EXPECT_EQ(a.groups[g].level, b.groups[g].level) << g;
        EXPECT_EQ(a.groups[g].sphere.center, b.groups[g].sphere.center) << g;
        EXPECT_EQ(a.groups[g].sphere.radius, b.groups[g].sphere.radius) << g;
        EXPECT_EQ(a.groups[g].error, b.groups[g].error) << g;
    }
}

// Per level and for the cut: what `lod` reports.
void expectSameNumbers(const LodStatistics& a, const LodStatistics& b) {
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (size_t l = 0; l < a.levels.size(); ++l) {
        EXPECT_EQ(a.levels[l].clusters, b.levels[l].clusters) << l;
        EXPECT_EQ(a.levels[l].triangles, b.levels[l].triangles) << l;
        EXPECT_EQ(a.levels[l].culling.trianglesCulled, b.levels[l].culling.trianglesCulled) << l;
        EXPECT_EQ(a.levels[l].multiCones.trianglesCulled, b.levels[l].multiCones.trianglesCulled) << l;
        EXPECT_EQ(a.levels[l].minError, b.levels[l].minError) << l;
        EXPECT_EQ(a.levels[l].maxError, b.levels[l].maxError) << l;
    }
    EXPECT_EQ(a.cut.trianglesCulled, b.cut.trianglesCulled);
    EXPECT_EQ(a.cut.backFacingTriangles, b.cut.backFacingTriangles);
    EXPECT_EQ(a.cut.meanClusters, b.cut.meanClusters);
    EXPECT_EQ(a.cut.levelsUsed, b.cut.levelsUsed);
    EXPECT_EQ(a.cut.multiCones.trianglesCulled, b.cut.multiCones.trianglesCulled);
}

TEST_F(HierarchyFiles, JsonAndBinaryHoldTheSameRecordsAndNumbers) {
    const std::string binary = hierarchyBinary(*records_);
    const HierarchyRecords fromBinary = parseHierarchyBinary(binary, "h.lod");
    const HierarchyRecords fromJson = parseHierarchyJson(hierarchyJson(*records_), "h.json");
    expectSameRecords(*records_, fromBinary);
    expectSameRecords(fromJson, fromBinary);
    EXPECT_EQ(hierarchyBinary(fromJson), binary);
    // The size is the header's promise: 32 + 16 M + 4 V + T padded to 8, 56 M, 48 G.
    const size_t arrays = 32 + 16 * records_->clusters.size() + 4 * records_->arrays.vertices.size() + records_->arrays.triangles.size();
    EXPECT_EQ(binary.size(), (arrays + 7) / 8 * 8 + 56 * records_->clusters.size() + 48 * records_->groups.size());

    Settings settings;
    settings.views = 12;
    LodThreshold threshold;
    threshold.value = 2.0;
    const LodStatistics built = measureHierarchy(*hierarchy_, settings, threshold, {}, 4);
    expectSameNumbers(built, measureHierarchy(hierarchyFromRecords(*sphere_, fromBinary, settings), settings, threshold, {}, 4));
    expectSameNumbers(built, measureHierarchy(hierarchyFromRecords(*sphere_, fromJson, settings), settings, threshold, {}, 4));
}

TEST_F(HierarchyFiles, BinaryFaultsAreRefusedNamed) {
    const std::string good = hierarchyBinary(*records_);
    const size_t clusters = records_->clusters.size(), groups = records_->groups.size();
    const size_t clusterRecords = good.size() - 56 * clusters - 48 * groups, groupRecords = good.size() - 48 * groups;
    const auto refused = [&](const std::function<void(std::string&)>& spoil, const std::string& message) {
        std::string bytes = good;
        spoil(bytes);
        try {
            parseHierarchyBinary(bytes, "h.lod");
            ADD_FAILURE() << "not refused: " << message;
        } catch (const MeshletFileError& error) {
            EXPECT_HAS(error.what(), message);
            EXPECT_HAS(error.what(), "h.lod: ");
        }
    };
    const auto putU32 = [](std::string& bytes, size_t at, uint32_t value) { std::memcpy(&bytes[at], &value, 4); };
    const auto putF64 = [](std::string& bytes, size_t at, double value) { std::memcpy(&bytes[at], &value, 8); };
    refused([](std::string& b) { b[0] = 'X'; }, "a binary one starts with the 8 bytes 'CLUSTLOD'");
    refused([](std::string& b) { b = b.substr(0, 8) + "{"; }, "truncated: the file ends at byte 9, inside the 32-byte header");
    refused([](std::string& b) { b.resize(20); }, "truncated: the file ends at byte 20");
    refused([&](std::string& b) { putU32(b, 8, 2); }, "byte 8: version 2, this reader knows version 1");
    refused([&](std::string& b) { putU32(b, 12, 1); }, "byte 12: flags 1");
    refused([](std::string& b) { b.pop_back(); }, "truncated: the header promises");
    refused([](std::string& b) { b.push_back('\0'); }, "but the file has " + std::to_string(good.size() + 1));
    // Counts that would need terabytes are refused by the size check before anything is allocated.
    refused([&](std::string& b) { putU32(b, 16, 0xffffffffu); }, "4294967295 clusters");
    refused([&](std::string& b) { putU32(b, 28, 0xfffffff0u); }, "4294967280 groups");
    refused([&](std::string& b) { putU32(b, clusterRecords + 56 * 3, uint32_t(clusters) + 1); }, "cluster 3: level " + std::to_string(clusters + 1));
    refused([&](std::string& b) { putU32(b, clusterRecords + 56 * 5 + 4, uint32_t(groups)); }, "cluster 5: group " + std::to_string(groups) + " is not a group");
    refused([&](std::string& b) { putU32(b, clusterRecords + 56 * 5 + 8, uint32_t(-2)); }, "cluster 5: refined group -2 is not a group");
    refused([&](std::string& b) { putU32(b, clusterRecords + 56 * 6 + 12, 7); }, "cluster 6: its reserved field is not 0");
    refused([&](std::string& b) { putF64(b, clusterRecords + 56 * 2 + 16, std::nan("")); }, "cluster 2: its centre is not a finite number");
    refused([&](std::string& b) { putF64(b, clusterRecords + 56 * 2 + 48, HUGE_VAL); }, "cluster 2: its error is not a finite number");
    refused([&](std::string& b) { putU32(b, groupRecords + 48 + 4, 1); }, "group 1: its reserved field is not 0");
    refused([&](std::string& b) { putF64(b, groupRecords + 48 * 2 + 32, -HUGE_VAL); }, "group 2: its radius is not a finite number");
    refused([&](std::string& b) { putU32(b, groupRecords + 48 * (groups - 1), uint32_t(clusters) + 9); }, "group " + std::to_string(groups - 1) + ": level");
    if (clusterRecords > 0 && good[clusterRecords - 1] == '\0' &&
        (32 + 16 * clusters + 4 * records_->arrays.vertices.size() + records_->arrays.triangles.size()) % 8 != 0)
        refused([&](std::string& b) { b[clusterRecords - 1] = 1; }, "padding after meshlet_triangles is not zero");
}

// Records the binary reads but that do not make a hierarchy are refused by the same checks as the
// JSON's, naming the cluster or group.
TEST_F(HierarchyFiles, BinaryRecordsAreCheckedAsTheJsons) {
    HierarchyRecords records = *records_;
    records.clusters[4].error = 1e9;
    const HierarchyRecords back = parseHierarchyBinary(hierarchyBinary(records), "h.lod");
    try {
        hierarchyFromRecords(*sphere_, back, Settings{});
        ADD_FAILURE() << "not refused";
    } catch (const HierarchyError& error) {
        EXPECT_HAS(error.what(), "cluster 4");
    }
    records = *records_;
    records.arrays.vertices[0] = 1u << 30;
    try {
        hierarchyFromRecords(*sphere_, parseHierarchyBinary(hierarchyBinary(records), "h.lod"), Settings{});
        ADD_FAILURE() << "not refused";
    } catch (const HierarchyError& error) {
        EXPECT_HAS(error.what(), "past the mesh file's");
    }
}

// The fuzz target's seeds: the same records in both forms, two levels of the target's 2 x 2 grid.
TEST(HierarchyFileNames, TheFuzzersSeedsHoldAHierarchyOfTheGrid) {
    Mesh grid;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) grid.positions.emplace_back(float(x), float(y), 0.0f);
    for (uint32_t y = 0; y < 2; ++y)
        for (uint32_t x = 0; x < 2; ++x) {
            const uint32_t a = 3 * y + x;
            grid.addFace({a, a + 1, a + 4});
            grid.addFace({a, a + 4, a + 3});
        }
    const std::string folder = std::string(CONESCOPE_TESTDATA_DIR) + "/meshlets/";
    const HierarchyRecords json = readHierarchyFile(folder + "grid-hierarchy.json"), binary = readHierarchyFile(folder + "grid-hierarchy.lod");
    expectSameRecords(json, binary);
    const PreparedMesh prepared = prepareMesh(std::make_shared<const Mesh>(grid), "grid", false);
    const ClusterHierarchy hierarchy = hierarchyFromRecords(prepared, binary, Settings{});
    ASSERT_EQ(hierarchy.levels.size(), 2u);
    EXPECT_EQ(hierarchy.levels[0].triangles(), 8u);
    EXPECT_EQ(hierarchy.levels[0].clusters.partition.clusterCount, 6u);
}

TEST(HierarchyFileNames, BinaryByExtension) {
    EXPECT_TRUE(isHierarchyBinaryPath("a/h.lod"));
    EXPECT_TRUE(isHierarchyBinaryPath("H.BIN"));
    EXPECT_FALSE(isHierarchyBinaryPath("h.json"));
    EXPECT_FALSE(isHierarchyBinaryPath("h"));
}

}  // namespace
}  // namespace conescope
