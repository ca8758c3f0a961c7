// conescope-cli lod end to end: the JSON's levels and cut, threshold 0 as `stats`, the CSV's rows,
// and bad thresholds as usage errors.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"

namespace conescope {
namespace {

using clitest::CliRun;
using clitest::dataset;
using clitest::runCli;
using clitest::runStatsJson;
using clitest::splitLines;

nlohmann::json runLodJson(const std::vector<std::string>& arguments) {
    std::vector<std::string> command = {"--format", "json"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    return clitest::runJsonCommand("lod", command);
}

TEST(CliLod, LevelsHalveAndTheCutIsConservative) {
    const nlohmann::json lod = runLodJson({dataset("elephant.off"), "--views", "32", "--threshold", "2"});
    const nlohmann::json& levels = lod["levels"];
    ASSERT_GE(levels.size(), 4u);
    for (size_t l = 0; l < levels.size(); ++l) {
        EXPECT_EQ(levels[l]["level"], l);
        EXPECT_EQ(levels[l]["false_culls"], 0);
        for (const char* key : {"clusters", "triangles", "efficiency", "expected_efficiency", "mean_half_angle_deg", "max_error"})
            EXPECT_TRUE(levels[l].contains(key)) << key;
        if (l > 0) {
            EXPECT_LT(levels[l]["triangles"].get<double>(), 0.85 * levels[l - 1]["triangles"].get<double>());
        }
    }
    EXPECT_EQ(levels.back()["clusters"], 1);
    const nlohmann::json& cut = lod["cut"];
    EXPECT_EQ(cut["false_culls"], 0);
    EXPECT_EQ(cut["views"].size(), 32u);
    EXPECT_FALSE(cut["levels_used"].empty());
    for (const char* key : {"triangles", "efficiency", "false_culls", "levels_used"}) EXPECT_TRUE(cut.contains(key)) << key;
    EXPECT_EQ(lod["threshold"]["unit"], "pixels");
}

// At threshold 0 the cut is level 0 from every view: the numbers of `stats` with the same options.
TEST(CliLod, ThresholdZeroIsStats) {
    const std::vector<std::string> options{dataset("fandisk.off"), "--views", "24", "--test", "apex"};
    std::vector<std::string> lodArguments = options;
    lodArguments.insert(lodArguments.end(), {"--threshold", "0"});
    const nlohmann::json lod = runLodJson(lodArguments);
    const nlohmann::json stats = runStatsJson(options);
    const nlohmann::json& flat = stats["results"][0];
    EXPECT_EQ(lod["cut"]["levels_used"], nlohmann::json::array({0}));
    EXPECT_EQ(lod["cut"]["triangles_culled"], flat["triangles_culled"]);
    EXPECT_EQ(lod["cut"]["efficiency"], flat["efficiency"]);
    EXPECT_EQ(lod["levels"][0]["clusters"], stats["clusters"]);
    EXPECT_EQ(lod["levels"][0]["efficiency"], flat["efficiency"]);
}

TEST(CliLod, CsvHasALevelRowEachAndTheCut) {
    const CliRun run = runCli({"lod", "--quiet", dataset("torus.off"), "--views", "8", "--format", "csv", "--world", "--threshold", "0.01"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::string> lines = splitLines(run.out);
    ASSERT_GE(lines.size(), 3u);
    EXPECT_EQ(lines[0].rfind("level,clusters,triangles,groups,efficiency,", 0), 0u) << lines[0];
    EXPECT_EQ(lines[1].rfind("0,", 0), 0u);
    EXPECT_EQ(lines.back().rfind("cut,", 0), 0u) << lines.back();
}

// --write-hierarchy, then --hierarchy: the same numbers from the file; a spoiled file is refused
// naming the cluster.
TEST(CliLod, HierarchyFileRoundTrips) {
    clitest::ScratchDirectory scratch;
    const std::string file = scratch.file("h.json");
    nlohmann::json built = runLodJson({dataset("elephant.off"), "--views", "16", "--write-hierarchy", file});
    nlohmann::json read = runLodJson({dataset("elephant.off"), "--views", "16", "--hierarchy", file});
    built.erase("build_seconds"), read.erase("build_seconds");
    EXPECT_EQ(built, read);
    nlohmann::json document = nlohmann::json::parse(clitest::readTextFile(file));
    EXPECT_EQ(document["format"], "conescope-cluster-lod");
    EXPECT_EQ(document["clusters"].size(), document["meshlets"].size());
    document["clusters"][7]["error"] = 1e9;
    std::ofstream(file) << document.dump();
    const CliRun run = runCli({"lod", "--quiet", dataset("elephant.off"), "--hierarchy", file});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("cluster 7"), std::string::npos) << run.err;
    document["format"] = "meshoptimizer-meshlets";
    std::ofstream(file) << document.dump();
    EXPECT_NE(runCli({"lod", "--quiet", dataset("elephant.off"), "--hierarchy", file}).err.find("conescope-cluster-lod"), std::string::npos);
}

// Each level written as a mesh is read back by the file builder with the level's clusters and
// numbers; the cut's mesh holds the clusters the first view draws.
TEST(CliLod, LevelMeshesReadBackWithTheirClusters) {
    clitest::ScratchDirectory scratch;
    const std::string folder = scratch.file("levels");
    const nlohmann::json lod = runLodJson({dataset("torus.off"), "--views", "8", "--write-levels", folder});
    const nlohmann::json level1 = runStatsJson({folder + "/level-01.vtp", "--builder", "file", "--views", "8"});
    EXPECT_EQ(level1["clusters"], lod["levels"][1]["clusters"]);
    EXPECT_EQ(level1["results"][0]["efficiency"], lod["levels"][1]["efficiency"]);
    const nlohmann::json cut = runStatsJson({folder + "/cut.vtp", "--builder", "file", "--views", "8"});
    EXPECT_EQ(cut["mesh"]["triangles"], lod["cut"]["views"][0]["triangles"]);
    EXPECT_EQ(cut["clusters"], lod["cut"]["views"][0]["clusters"]);
}

// The lesson on why coarse clusters cull less quotes the run's own levels, as the JSON has them.
TEST(CliLod, LessonQuotesTheRunsLevels) {
    clitest::ScratchDirectory scratch;
    const std::string lessonFile = scratch.file("lesson.md");
    const nlohmann::json lod = runLodJson({dataset("elephant.off"), "--views", "16", "--write-lesson", lessonFile, "--lesson-level", "2"});
    const std::string lesson = clitest::readTextFile(lessonFile);
    const auto percent = [](double share) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f%%", 100.0 * share);
        return std::string(text);
    };
    EXPECT_NE(lesson.find("level 0 and level 2"), std::string::npos) << lesson;
    for (size_t l : {0, 2}) {
        const nlohmann::json& level = lod["levels"][l];
        EXPECT_NE(lesson.find(percent(level["efficiency"].get<double>())), std::string::npos) << l << lesson;
        EXPECT_NE(lesson.find(percent(level["expected_efficiency"].get<double>())), std::string::npos) << l << lesson;
        EXPECT_NE(lesson.find(std::to_string(level["triangles"].get<size_t>()) + " triangles"), std::string::npos) << l << lesson;
    }
    EXPECT_NE(lesson.find(percent(lod["cut"]["efficiency"].get<double>())), std::string::npos) << lesson;
    // A level the hierarchy does not have is refused, naming it.
    const CliRun bad = runCli({"lod", "--quiet", dataset("torus.off"), "--views", "4", "--write-lesson", scratch.file("bad.md"),
                               "--lesson-level", "99"});
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.err.find("level 99"), std::string::npos) << bad.err;
}

TEST(CliLod, BadThresholdsAreUsageErrors) {
    for (const std::vector<std::string>& bad : {std::vector<std::string>{"--threshold", "-1"}, {"--fov", "180"}, {"--screen-height", "0"},
                                                 {"--group-size", "1"}}) {
        std::vector<std::string> command{"lod", "--quiet", dataset("torus.off")};
        command.insert(command.end(), bad.begin(), bad.end());
        const CliRun run = runCli(command);
        EXPECT_EQ(run.exitCode, 2) << bad[0];
        EXPECT_NE(run.err.find(bad[0]), std::string::npos) << run.err;
    }
}

}  // namespace
}  // namespace conescope
