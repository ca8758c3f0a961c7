// conescope-cli stats with K cones per cluster (--cones K): the K-cone record's "multi_cone" object,
// CSV columns and text line are the core's in-process run, granularity's cones-K row on the same
// partition and views; with one cone (the default) the output is as before.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"
#include "core/Pipeline.h"
#include "core/SettingsSchema.h"
#include "io/MeshReader.h"
#include "io/StatisticsIO.h"

namespace conescope {
namespace {

using namespace clitest;

const char* const kMultiConeKeys[] = {"cones_per_cluster", "efficiency", "false_culls", "triangles_culled",
                                      "back_facing_triangles", "bytes_per_cluster"};

TEST(CliMultiCone, StatsWithFourConesIsTheCoresRun) {
    const nlohmann::json stats = runStatsJson({dataset("fandisk.off"), "--views", "24", "--cones-per-cluster", "4", "--no-per-view", "--no-per-cluster"});
    ASSERT_TRUE(stats.contains("multi_cone"));
    const nlohmann::json& multi = stats["multi_cone"];
    EXPECT_EQ(multi.size(), std::size(kMultiConeKeys));
    for (const char* key : kMultiConeKeys) EXPECT_TRUE(multi.contains(key)) << key;
    EXPECT_EQ(multi["cones_per_cluster"], 4);
    EXPECT_EQ(multi["false_culls"], 0);
    EXPECT_EQ(stats["settings"]["cones_per_cluster"], 4);

    Settings settings;
    parseSetting(settingField("views"), "24", settings);
    parseSetting(settingField("cones_per_cluster"), "4", settings);  // the key: "cones" is the cone methods' key
    const RunStatistics run = runStatistics(readMesh(dataset("fandisk.off")), settings, "fandisk.off");
    EXPECT_EQ(run.multiCones.cones, 4u);
    EXPECT_EQ(multi["triangles_culled"].get<size_t>(), run.multiCones.trianglesCulled);
    EXPECT_EQ(multi["back_facing_triangles"].get<size_t>(), run.multiCones.backFacingTriangles);
    EXPECT_EQ(multi["efficiency"].get<double>(), run.multiCones.efficiency);
    EXPECT_EQ(multi["bytes_per_cluster"].get<size_t>(), run.multiCones.bytesPerCluster);
    // The back faces are the one-cone test's, and four cones cull at least as much here.
    EXPECT_EQ(multi["back_facing_triangles"], stats["results"][0]["back_facing_triangles"]);
    EXPECT_GT(multi["triangles_culled"].get<size_t>(), stats["results"][0]["triangles_culled"].get<size_t>());

    // granularity's cones-4 row: the same record on the same partition (built for 4 cones) and views.
    const nlohmann::json granularity = runJsonFormat("granularity", {dataset("fandisk.off"), "--views", "24", "--cones-per-cluster", "4"});
    const nlohmann::json* row = granularityRow(granularity, "cones-4");
    ASSERT_NE(row, nullptr);
    EXPECT_EQ((*row)["efficiency"], multi["efficiency"]);
    EXPECT_EQ((*row)["bytes_per_cluster"], multi["bytes_per_cluster"]);
    EXPECT_EQ((*row)["false_culls"], multi["false_culls"]);
}

TEST(CliMultiCone, CsvAndTextCarryTheSameNumbers) {
    const std::vector<std::string> options{"stats", "--quiet", dataset("torus.off"), "--views", "8", "--cones-per-cluster", "2", "--test", "octagon,sphere"};
    const nlohmann::json json = runStatsJson({dataset("torus.off"), "--views", "8", "--cones-per-cluster", "2", "--test", "octagon,sphere"});
    const CliRun csv = runCli(withArguments(options, {"--format", "csv"}));
    ASSERT_EQ(csv.exitCode, 0) << csv.err;
    const std::vector<std::string> lines = splitLines(csv.out);
    ASSERT_EQ(lines.size(), 3u);  // header, one row per test
    std::vector<std::string> header, row;
    std::stringstream headerText(lines[0]), rowText(lines[2]);
    for (std::string cell; std::getline(headerText, cell, ',');) header.push_back(cell);
    for (std::string cell; std::getline(rowText, cell, ',');) row.push_back(cell);
    ASSERT_EQ(header.size(), row.size());
    size_t columns = 0;
    for (size_t i = 0; i < header.size(); ++i) {
        if (header[i].rfind("multi_cone_", 0) != 0) continue;
        ++columns;
        const nlohmann::json value = json["multi_cone"][header[i].substr(11)];
        if (value.is_number_float())
            EXPECT_DOUBLE_EQ(std::stod(row[i]), value.get<double>()) << header[i];
        else
            EXPECT_EQ(row[i], value.dump()) << header[i];
    }
    EXPECT_EQ(columns, std::size(kMultiConeKeys));
    const CliRun text = runCli(withArguments(options, {"--format", "text"}));
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("2 cones per cluster"), std::string::npos) << text.out;
}

// One cone per cluster, given or not, writes what stats wrote before the setting existed: no
// multi_cone object, column or line, and no settings key.
TEST(CliMultiCone, OneConeLeavesTheOutputAlone) {
    for (const char* format : {"json", "csv", "text"}) {
        const CliRun plain = runCli({"stats", "--quiet", dataset("torus.off"), "--views", "8", "--format", format});
        const CliRun one = runCli({"stats", "--quiet", dataset("torus.off"), "--views", "8", "--cones-per-cluster", "1", "--format", format});
        ASSERT_EQ(plain.exitCode, 0) << plain.err;
        ASSERT_EQ(one.exitCode, 0) << one.err;
        EXPECT_EQ(plain.out.find("multi_cone"), std::string::npos) << format;
        EXPECT_EQ(plain.out.find("cones_per_cluster"), std::string::npos) << format;
        EXPECT_EQ(plain.out.find("cones per cluster"), std::string::npos) << format;
        // Timings aside (ns_per_cluster), the same document.
        if (std::string(format) == "json") {
            nlohmann::json a = nlohmann::json::parse(plain.out), b = nlohmann::json::parse(one.out);
            removeTimings(a);
            removeTimings(b);
            EXPECT_EQ(a, b);
        }
    }
}

TEST(CliMultiCone, RefusesOtherCounts) {
    for (const char* k : {"0", "3", "16"}) {
        const CliRun run = runCli({"stats", "--quiet", dataset("torus.off"), "--cones-per-cluster", k});
        EXPECT_NE(run.exitCode, 0) << k;
        EXPECT_NE(run.err.find("--cones-per-cluster"), std::string::npos) << run.err;
    }
    const CliRun batch = runCli({"batch", "--quiet", dataset("torus.off"), "-o", "/nonexistent/never", "--cones-per-cluster", "4"});
    EXPECT_NE(batch.exitCode, 0);
    EXPECT_NE(batch.err.find("--granularity"), std::string::npos) << batch.err;
}

}  // namespace
}  // namespace conescope
