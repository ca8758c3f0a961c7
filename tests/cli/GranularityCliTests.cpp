// conescope-cli granularity end to end: its one-cone rows are `stats`' numbers with each test, the
// K-cone and per-triangle rows are there with their keys, CSV and text carry the same rows.
#include <gtest/gtest.h>

#include <map>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"
#include "core/GranularityLesson.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using namespace clitest;

std::map<std::string, nlohmann::json> rowsByRecord(const nlohmann::json& report) {
    std::map<std::string, nlohmann::json> rows;
    for (const nlohmann::json& row : report["rows"]) rows[row["record"].get<std::string>()] = row;
    return rows;
}

// Every test of `stats --test all` (but the oracle) is a row with stats' own numbers.
TEST(CliGranularity, OneConeRowsEqualStats) {
    const std::vector<std::string> options{dataset("fandisk.off"), "--views", "24"};
    const nlohmann::json report = runJsonFormat("granularity", options);
    const nlohmann::json stats = runStatsJson(withArguments(options, {"--test", "all", "--no-per-view", "--no-per-cluster"}));
    const std::map<std::string, nlohmann::json> rows = rowsByRecord(report);
    EXPECT_EQ(report["clusters"], stats["clusters"]);
    size_t compared = 0;
    for (const nlohmann::json& result : stats["results"]) {
        const std::string test = result["test"];
        if (test == "oracle") continue;
        const std::string name = result["engine_record"].get<bool>() ? test : result["cone"].get<std::string>() + "/" + test;
        ASSERT_TRUE(rows.count(name)) << name;
        EXPECT_EQ(rows.at(name)["efficiency"], result["efficiency"]) << name;
        EXPECT_EQ(rows.at(name)["triangles_culled"], result["triangles_culled"]) << name;
        EXPECT_EQ(rows.at(name)["false_culls"], result["false_culls"]) << name;
        EXPECT_EQ(rows.at(name)["bytes_per_cluster"], result["bytes_per_cluster"]) << name;
        ++compared;
    }
    EXPECT_EQ(compared, 11u);
    EXPECT_EQ(report["rows"][0]["record"], "chosen/octagon");  // the default first
    for (const char* name : {"cones-2", "cones-4", "cones-8", "cones-2-compact", "cones-4-compact", "cones-8-compact", "triangle"}) {
        ASSERT_TRUE(rows.count(name)) << name;
        for (const char* key : {"record", "bytes_per_cluster", "bits_per_triangle", "efficiency", "culled_share", "tests_per_view", "false_culls"})
            EXPECT_TRUE(rows.at(name).contains(key)) << name << " " << key;
        EXPECT_EQ(rows.at(name)["false_culls"], 0) << name;
    }
    EXPECT_LE(rows.at("cones-4-compact")["bytes_per_cluster"].get<int>(), 32);
    EXPECT_GT(rows.at("cones-4")["efficiency"].get<double>(), rows.at("chosen/octagon")["efficiency"].get<double>());
    EXPECT_EQ(rows.at("triangle")["efficiency"], 1.0);
}

TEST(CliGranularity, CsvAndTextCarryTheRows) {
    const std::vector<std::string> options{"granularity", "--quiet", dataset("elephant.off"), "--views", "16", "--test", "apex"};
    const CliRun csvRun = runCli(withArguments(options, {"--format", "csv"}));
    const CliRun textRun = runCli(withArguments(options, {"--format", "text"}));
    ASSERT_EQ(csvRun.exitCode, 0) << csvRun.err;
    ASSERT_EQ(textRun.exitCode, 0) << textRun.err;
    const std::vector<std::string> lines = splitLines(csvRun.out);
    ASSERT_EQ(lines.size(), 1u + 1u + 6u + 1u);  // header, the apex test, six K-cone records, triangle
    EXPECT_EQ(lines[0].rfind("record,bytes_per_cluster,bits_per_triangle,efficiency,culled_share,tests_per_view,false_culls", 0), 0u);
    EXPECT_EQ(lines[1].rfind("chosen/apex,28,", 0), 0u);
    EXPECT_EQ(lines.back().rfind("triangle,28,", 0), 0u);  // per-triangle after the apex test
    EXPECT_NE(textRun.out.find("cones-4-compact"), std::string::npos);
    EXPECT_NE(textRun.out.find("per-triangle culling after the chosen/apex cluster test"), std::string::npos);
}

// --write-lesson writes the core's lesson on the same report as Markdown, beside the rows.
TEST(CliGranularity, WritesTheLessonOfItsReport) {
    ScratchDirectory scratch;
    const std::string lessonPath = scratch.file("lesson.md");
    const CliRun run = runCli({"granularity", "--quiet", dataset("elephant.off"), "--views", "16", "--write-lesson", lessonPath, "-o",
                               scratch.file("rows.json")});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    Settings settings = granularitySettings(Settings{}, false);
    settings.views = 16;
    const GranularityReport report = runGranularity(readMesh(dataset("elephant.off")), settings, "elephant.off");
    const std::string lesson = readTextFile(lessonPath);
    EXPECT_EQ(lesson, granularityLessonMarkdown(makeGranularityLesson(report)));
    EXPECT_EQ(lesson.rfind("# Why more cones cull more, and what they cost: elephant.off\n", 0), 0u);
    // It quotes the rows the command wrote.
    const nlohmann::json rows = nlohmann::json::parse(readTextFile(scratch.file("rows.json")));
    for (const nlohmann::json& row : rows["rows"]) {
        if (row["record"] == "cones-4-compact") {
            EXPECT_NE(lesson.find(std::to_string(row["bytes_per_cluster"].get<int>()) + " bytes"), std::string::npos);
        }
    }
}

TEST(CliGranularity, BadMeshIsAnError) {
    const CliRun run = runCli({"granularity", "--quiet", dataset("no-such-mesh.off")});
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.err.find("no-such-mesh.off"), std::string::npos);
}

}  // namespace
}  // namespace conescope
