// conescope-cli lod end to end: the JSON's levels and cut, threshold 0 as `stats`, the CSV's rows,
// and bad thresholds as usage errors.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"

namespace conescope {
namespace {

using namespace clitest;

nlohmann::json runLodJson(const std::vector<std::string>& arguments) { return runJsonFormat("lod", arguments); }

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
    const nlohmann::json lod = runLodJson(withArguments(options, {"--threshold", "0"}));
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
    ScratchDirectory scratch;
    const std::string file = scratch.file("h.json");
    nlohmann::json built = runLodJson({dataset("elephant.off"), "--views", "16", "--write-hierarchy", file});
    nlohmann::json read = runLodJson({dataset("elephant.off"), "--views", "16", "--hierarchy", file});
    built.erase("build_seconds"), read.erase("build_seconds");
    EXPECT_EQ(built, read);
    nlohmann::json document = nlohmann::json::parse(readTextFile(file));
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
    ScratchDirectory scratch;
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
    ScratchDirectory scratch;
    const std::string lessonFile = scratch.file("lesson.md");
    const nlohmann::json lod = runLodJson({dataset("elephant.off"), "--views", "16", "--write-lesson", lessonFile, "--lesson-level", "2"});
    const std::string lesson = readTextFile(lessonFile);
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
                                                 {"--group-size", "1"}, {"--cones", "3"}}) {
        std::vector<std::string> command{"lod", "--quiet", dataset("torus.off")};
        command.insert(command.end(), bad.begin(), bad.end());
        const CliRun run = runCli(command);
        EXPECT_EQ(run.exitCode, 2) << bad[0];
        EXPECT_NE(run.err.find(bad[0]), std::string::npos) << run.err;
    }
}

// The binary form (.lod) written and read back gives the same numbers as the built hierarchy and as
// the JSON of the same hierarchy; a truncated or foreign file is refused, saying so.
TEST(CliLod, BinaryHierarchyRoundTripsAsTheJson) {
    ScratchDirectory scratch;
    const std::string binary = scratch.file("h.lod"), json = scratch.file("h.json");
    const std::vector<std::string> run = {dataset("elephant.off"), "--views", "12", "--cones", "4"};
    const auto with = [&](const std::vector<std::string>& more) {
        nlohmann::json lod = runLodJson(withArguments(run, more));
        lod.erase("build_seconds");
        return lod;
    };
    const nlohmann::json built = with({"--write-hierarchy", binary});
    EXPECT_EQ(with({"--write-hierarchy", json}), built);
    EXPECT_EQ(with({"--hierarchy", binary}), built);
    EXPECT_EQ(with({"--hierarchy", json}), built);
    const std::string bytes = readTextFile(binary);
    EXPECT_EQ(bytes.substr(0, 8), "CLUSTLOD");
    EXPECT_EQ(nlohmann::json::parse(readTextFile(json))["format"], "conescope-cluster-lod");
    // The JSON read and written again as binary is the same file.
    const std::string again = scratch.file("again.lod");
    with({"--hierarchy", json, "--write-hierarchy", again});
    EXPECT_EQ(readTextFile(again), bytes);
    std::ofstream(binary, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 9);
    CliRun refused = runCli({"lod", "--quiet", dataset("elephant.off"), "--hierarchy", binary});
    EXPECT_EQ(refused.exitCode, 1);
    EXPECT_NE(refused.err.find("h.lod: truncated: the header promises"), std::string::npos) << refused.err;
    std::ofstream(binary, std::ios::binary | std::ios::trunc) << "MESHLETS" << bytes.substr(8);
    refused = runCli({"lod", "--quiet", dataset("elephant.off"), "--hierarchy", binary});
    EXPECT_NE(refused.err.find("starts with the 8 bytes 'CLUSTLOD'"), std::string::npos) << refused.err;
}

// A mesh of polygons: level 0 read back is the mesh with its polygons whole, as built, so every
// number (the K-cone sub-groups split faces) and the file written again are the same.
TEST(CliLod, PolygonMeshHierarchyRoundTripsWithItsPolygons) {
    ScratchDirectory scratch;
    const std::string mesh = std::string(CONESCOPE_TESTDATA_DIR) + "/props/bread.obj", file = scratch.file("bread.lod"), again = scratch.file("again.lod");
    nlohmann::json built = runLodJson({mesh, "--views", "16", "--cones", "4", "--write-hierarchy", file});
    nlohmann::json read = runLodJson({mesh, "--views", "16", "--cones", "4", "--hierarchy", file, "--write-hierarchy", again});
    built.erase("build_seconds"), read.erase("build_seconds");
    EXPECT_EQ(built, read);
    EXPECT_EQ(readTextFile(again), readTextFile(file));
}

// --cones K: level 0 is granularity's cones-K row on the same partition and views; no false culls
// at any level or in the cut; the cut's numbers are the sums of its views', and at threshold 0 the
// cut is level 0. Without --cones nothing changes.
TEST(CliLod, ConesPerClusterAsGranularityAndConservative) {
    const nlohmann::json lod = runLodJson({dataset("elephant.off"), "--views", "16", "--threshold", "1", "--cones", "4"});
    const nlohmann::json granularity = runJsonFormat("granularity", {dataset("elephant.off"), "--views", "16"});
    const nlohmann::json* row = granularityRow(granularity, "cones-4");
    ASSERT_NE(row, nullptr);
    const nlohmann::json& level0 = lod["levels"][0]["multi_cone"];
    EXPECT_EQ(level0["cones_per_cluster"], 4);
    EXPECT_EQ(level0["triangles_culled"], (*row)["triangles_culled"]);
    EXPECT_EQ(level0["back_facing_triangles"], (*row)["back_facing_triangles"]);
    EXPECT_EQ(level0["efficiency"], (*row)["efficiency"]);
    for (const nlohmann::json& level : lod["levels"]) {
        EXPECT_EQ(level["multi_cone"]["false_culls"], 0) << level["level"];
        EXPECT_EQ(level["multi_cone"]["back_facing_triangles"], level["back_facing_triangles"]) << level["level"];
    }
    const nlohmann::json& cut = lod["cut"];
    size_t culled = 0, back = 0;
    for (const nlohmann::json& view : cut["views"]) {
        culled += view["multi_cone"]["triangles_culled"].get<size_t>();
        back += view["multi_cone"]["back_facing_triangles"].get<size_t>();
        EXPECT_EQ(view["multi_cone"]["false_culls"], 0);
        EXPECT_EQ(view["multi_cone"]["back_facing_triangles"], view["back_facing_triangles"]);
    }
    EXPECT_EQ(cut["multi_cone"]["triangles_culled"], culled);
    EXPECT_EQ(cut["multi_cone"]["back_facing_triangles"], back);
    EXPECT_EQ(cut["multi_cone"]["false_culls"], 0);
    EXPECT_GT(culled, 0u);
    const nlohmann::json zero = runLodJson({dataset("elephant.off"), "--views", "16", "--threshold", "0", "--cones", "4"});
    EXPECT_EQ(zero["cut"]["multi_cone"]["triangles_culled"], zero["levels"][0]["multi_cone"]["triangles_culled"]);
    EXPECT_EQ(zero["cut"]["multi_cone"]["efficiency"], zero["levels"][0]["multi_cone"]["efficiency"]);
    const nlohmann::json plain = runLodJson({dataset("elephant.off"), "--views", "16", "--threshold", "1"});
    EXPECT_FALSE(plain["levels"][0].contains("multi_cone"));
    EXPECT_FALSE(plain["cut"].contains("multi_cone"));
    EXPECT_EQ(plain["levels"][2]["efficiency"], lod["levels"][2]["efficiency"]);
    EXPECT_EQ(plain["cut"]["efficiency"], lod["cut"]["efficiency"]);
}

// The CSV has the K-cone columns, the cut's row filled, only with --cones.
TEST(CliLod, CsvHasTheConesColumnsOnlyWhenAsked) {
    const CliRun with = runCli({"lod", "--quiet", dataset("torus.off"), "--views", "8", "--cones", "2", "--format", "csv"});
    ASSERT_EQ(with.exitCode, 0) << with.err;
    const std::vector<std::string> lines = splitLines(with.out);
    EXPECT_NE(lines.front().find(",multi_cone_cones_per_cluster,multi_cone_efficiency,multi_cone_false_culls"), std::string::npos) << lines.front();
    EXPECT_EQ(lines.back().rfind("cut,", 0), 0u);
    EXPECT_NE(lines.back().find(",2,"), std::string::npos) << lines.back();
    const CliRun without = runCli({"lod", "--quiet", dataset("torus.off"), "--views", "8", "--format", "csv"});
    EXPECT_EQ(splitLines(without.out).front().find("multi_cone"), std::string::npos);
}

}  // namespace
}  // namespace conescope
