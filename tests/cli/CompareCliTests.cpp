// conescope-cli compare end to end: each side is the plain stats run, the diff adds up to them, A = B
// differs nowhere, the CSV is one tidy table and bad configurations are usage errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"

namespace conescope {
namespace {

using clitest::CliRun;
using clitest::dataset;
using clitest::removeTimings;
using clitest::runCli;
using clitest::runStatsJson;
using clitest::ScratchDirectory;
using clitest::splitLines;

nlohmann::json runCompareJson(const std::vector<std::string>& arguments, std::string* err = nullptr) {
    std::vector<std::string> command = {"compare", "--quiet", "--format", "json"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const CliRun run = runCli(command);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    if (err) *err = run.err;
    const nlohmann::json json = nlohmann::json::parse(run.out);
    // Each side is written as it is made, never as a tree: the text must still be the tree's layout.
    EXPECT_EQ(run.out, json.dump(2) + "\n");
    return json;
}

void expectSame(nlohmann::json actual, nlohmann::json expected) {
    removeTimings(actual);
    removeTimings(expected);
    const nlohmann::json differences = nlohmann::json::diff(expected, actual);
    EXPECT_TRUE(differences.empty()) << differences.dump().substr(0, 1500);
}

// The best effort never culls less than balanced as the run measures it, nor makes more clusters:
// with no options (the default cone, test and orbit) and from other views. rock1 culled 0.211 at best
// against 0.215 at balanced when best picked its run by the expected culling from far views; bread
// culled 0.124 against 0.137 from 16 views when best picked it from the default orbit. Its
// "best_effort" says which search it kept, with the figures the plain runs give: the kept
// partition's and, where best kept balanced's, the run's.
TEST(CliCompare, BestNeverCullsLessThanBalancedAsTheRunMeasures) {
    std::vector<std::string> meshes = {dataset("torus.off"), dataset("icosphere.off"), dataset("bumpy-plane.off")};
    for (const char* prop : {"rock1", "bread", "emergencySign", "technicalTable1", "verticalShelves"})
        meshes.push_back(std::string(CONESCOPE_TESTDATA_DIR) + "/props/" + prop + ".obj");
    for (const std::vector<std::string>& run : {std::vector<std::string>{}, {"--views", "16"}}) {
        std::set<std::string> kept;
        for (const std::string& mesh : meshes) {
            SCOPED_TRACE(mesh + (run.empty() ? "" : " from 16 views"));
            std::vector<std::string> arguments = {mesh, "--a", "effort=best"};
            arguments.insert(arguments.end(), run.begin(), run.end());
            const nlohmann::json json = runCompareJson(arguments);
            const nlohmann::json &best = json["a"], &balanced = json["b"];
            ASSERT_LE(best["clusters"].get<size_t>(), balanced["clusters"].get<size_t>());
            const double bestEfficiency = best["results"][0]["efficiency"], balancedEfficiency = balanced["results"][0]["efficiency"];
            if (best["clusters"] == balanced["clusters"]) {
                EXPECT_GE(bestEfficiency, balancedEfficiency);
            }
            EXPECT_FALSE(balanced.contains("best_effort"));
            const nlohmann::json& choice = best.at("best_effort");
            kept.insert(choice["kept"].get<std::string>());
            EXPECT_EQ(choice["balanced_clusters"], balanced["clusters"]);
            EXPECT_DOUBLE_EQ(choice["balanced_efficiency"].get<double>(), balancedEfficiency);
            if (choice["kept"] == "balanced") {
                EXPECT_EQ(best["clusters"], balanced["clusters"]);
                EXPECT_EQ(best["results"][0]["triangles_culled"], balanced["results"][0]["triangles_culled"]);
                EXPECT_TRUE(choice["own_clusters"] != choice["balanced_clusters"] ||
                            choice["own_efficiency"].get<double>() < choice["balanced_efficiency"].get<double>() ||
                            choice["own_expected_efficiency"].get<double>() < choice["balanced_expected_efficiency"].get<double>());
            } else {
                EXPECT_EQ(choice["own_clusters"], best["clusters"]);
                EXPECT_DOUBLE_EQ(choice["own_efficiency"].get<double>(), bestEfficiency);
            }
        }
        EXPECT_EQ(kept, (std::set<std::string>{"best", "balanced"}));  // both cases are met
    }
}

// A single eye does not choose best's partition: the window moves its eye over the partition its orbit
// chose, and `stats --eye` gives that partition's numbers.
TEST(CliCompare, BestChoosesByTheOrbitNotBySingleEye) {
    for (const char* prop : {"bread", "rock1"}) {
        const std::string mesh = std::string(CONESCOPE_TESTDATA_DIR) + "/props/" + prop + ".obj";
        SCOPED_TRACE(mesh);
        const nlohmann::json orbit = runStatsJson({mesh, "--effort", "best"});
        const nlohmann::json eye = runStatsJson({mesh, "--effort", "best", "--eye", "30,-20,45"});
        EXPECT_EQ(eye["view_count"], 1);
        EXPECT_EQ(eye["best_effort"], orbit["best_effort"]);
        EXPECT_EQ(eye["clusters"], orbit["clusters"]);
    }
}

// Where best keeps balanced's partition, the text summary says so and why, with the figures of each
// measure by which its own search culled less; where it keeps its own, and at the default effort, it
// says nothing of it.
TEST(CliCompare, BestSaysWhenItKeepsTheBalancedPartition) {
    const std::string sign = std::string(CONESCOPE_TESTDATA_DIR) + "/props/emergencySign.obj";
    const nlohmann::json choice = runStatsJson({sign, "--effort", "best"})["best_effort"];
    ASSERT_EQ(choice["kept"], "balanced");
    ASSERT_EQ(choice["own_clusters"], choice["balanced_clusters"]);
    const CliRun text = runCli({"stats", sign, "--quiet", "--effort", "best", "--format", "text"});
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("the best effort kept the balanced search's partition: at " + choice["balanced_clusters"].dump() +
                            " clusters each it culls more than best's own search"),
              std::string::npos)
        << text.out;
    size_t measures = 0;
    for (const auto& [measure, key] : {std::pair<std::string, std::string>{"from the run's orbit", "efficiency"},
                                       {"in expectation over far views", "expected_efficiency"}}) {
        const double balanced = choice["balanced_" + key], own = choice["own_" + key];
        char figures[96];
        std::snprintf(figures, sizeof figures, " (%.3f against %.3f)", balanced, own);
        EXPECT_EQ(text.out.find(measure + figures) != std::string::npos, own < balanced) << measure << "\n" << text.out;
        measures += own < balanced;
    }
    EXPECT_GE(measures, 1u);
    for (const char* effort : {"balanced", "best"}) {
        const std::string mesh = effort == std::string("best") ? dataset("torus.off") : sign;
        const CliRun other = runCli({"stats", mesh, "--quiet", "--effort", effort, "--format", "text"});
        EXPECT_EQ(other.out.find("kept the balanced"), std::string::npos) << effort << ": " << other.out;
    }
}

TEST(CliCompare, EachSideIsThePlainStatsRunAndTheDiffAddsUpToThem) {
    const std::string mesh = dataset("elephant.off");
    std::string err;
    const nlohmann::json json =
        runCompareJson({mesh, "--views", "12", "--max-tris", "96", "--a", "builder=meshopt,cone=meshopt", "--b", "test=sphere"}, &err);
    expectSame(json["a"], runStatsJson({mesh, "--views", "12", "--max-tris", "96", "--builder", "meshopt", "--cone", "meshopt"}));
    expectSame(json["b"], runStatsJson({mesh, "--views", "12", "--max-tris", "96", "--test", "sphere"}));
    const nlohmann::json& diff = json["diff"];
    const nlohmann::json& a = json["a"]["results"][0];
    const nlohmann::json& b = json["b"]["results"][0];
    EXPECT_EQ(diff["triangles_culled_only_a"].get<size_t>() + diff["triangles_culled_both"].get<size_t>(), a["triangles_culled"]);
    EXPECT_EQ(diff["triangles_culled_only_b"].get<size_t>() + diff["triangles_culled_both"].get<size_t>(), b["triangles_culled"]);
    EXPECT_EQ(diff["back_facing_triangles"], a["back_facing_triangles"]);
    EXPECT_EQ(diff["efficiency_a"], a["efficiency"]);
    EXPECT_EQ(diff["efficiency_b"], b["efficiency"]);
    EXPECT_EQ(diff["test_a"], "octagon");
    EXPECT_EQ(diff["cone_a"], "meshopt");
    EXPECT_EQ(diff["test_b"], "sphere");
    EXPECT_EQ(diff["clusters_a"], json["a"]["clusters"]);
    EXPECT_EQ(diff["clusters_b"], json["b"]["clusters"]);
    ASSERT_EQ(diff["views"].size(), 12u);
    for (size_t v = 0; v < 12; ++v) {
        const nlohmann::json& view = diff["views"][v];
        EXPECT_EQ(view["eye"], a["views"][v]["eye"]);
        EXPECT_EQ(view["triangles_culled_only_a"].get<size_t>() + view["triangles_culled_both"].get<size_t>(),
                  a["views"][v]["triangles_culled"]);
        EXPECT_EQ(view["triangles_culled_only_b"].get<size_t>() + view["triangles_culled_both"].get<size_t>(),
                  b["views"][v]["triangles_culled"]);
    }
    EXPECT_GT(diff["triangles_culled_only_a"].get<size_t>() + diff["triangles_culled_only_b"].get<size_t>(), 0u);
}

TEST(CliCompare, SameConfigurationDiffersNowhere) {
    const nlohmann::json diff = runCompareJson({dataset("torus.off"), "--views", "9", "--a", "", "--b", ""})["diff"];
    EXPECT_EQ(diff["triangles_culled_only_a"], 0);
    EXPECT_EQ(diff["triangles_culled_only_b"], 0);
    EXPECT_GT(diff["triangles_culled_both"].get<size_t>(), 0u);
    for (const nlohmann::json& view : diff["views"]) {
        EXPECT_EQ(view["triangles_culled_only_a"], 0);
        EXPECT_EQ(view["triangles_culled_only_b"], 0);
    }
    EXPECT_TRUE(diff["cluster_count_warning"].is_null());
}

// Without --b, B is the plain run of the common options: the question a user asks most.
TEST(CliCompare, WithoutBTheCommonOptionsAreB) {
    const std::string mesh = dataset("torus.off");
    const nlohmann::json json = runCompareJson({mesh, "--views", "6", "--a", "builder=meshopt,cone=meshopt,test=apex"});
    expectSame(json["b"], runStatsJson({mesh, "--views", "6"}));
    EXPECT_EQ(json["diff"]["test_a"], "apex");
    EXPECT_EQ(json["diff"]["test_b"], "octagon");
}

// An imported partition is a side like any other, a path with a comma in it included; one eye is one row.
TEST(CliCompare, AClusterFileSideIsTheStatsRunOfThatFile) {
    const std::string mesh = dataset("torus.off");
    const size_t faces = runStatsJson({mesh, "--views", "1"})["mesh"]["faces"].get<size_t>();
    ScratchDirectory scratch;
    std::string ids;
    for (size_t f = 0; f < faces; ++f) ids += std::to_string(f / 12) + "\n";  // runs of 12 faces
    const std::string idFile = scratch.writeFile("ids,rings.txt", ids);
    const nlohmann::json json =
        runCompareJson({mesh, "--eye", "0.3,-0.4,3", "--a", "builder=file,cluster-file=" + idFile + ",test=sphere", "--b", ""});
    expectSame(json["a"], runStatsJson({mesh, "--eye", "0.3,-0.4,3", "--builder", "file", "--cluster-file", idFile, "--test", "sphere"}));
    expectSame(json["b"], runStatsJson({mesh, "--eye", "0.3,-0.4,3"}));
    const nlohmann::json& diff = json["diff"];
    EXPECT_EQ(diff["clusters_a"], (faces + 11) / 12);
    ASSERT_EQ(diff["views"].size(), 1u);
    EXPECT_EQ(diff["views"][0]["back_facing_triangles"], diff["back_facing_triangles"]);
    EXPECT_GT(diff["triangles_culled_only_a"].get<size_t>() + diff["triangles_culled_only_b"].get<size_t>(), 0u);
    EXPECT_EQ(diff["triangles_culled_only_a"].get<size_t>() + diff["triangles_culled_both"].get<size_t>(),
              json["a"]["results"][0]["triangles_culled"]);
    EXPECT_EQ(diff["triangles_culled_only_b"].get<size_t>() + diff["triangles_culled_both"].get<size_t>(),
              json["b"]["results"][0]["triangles_culled"]);
}

TEST(CliCompare, UnequalClusterCountsAreWarnedAboutEvenWhenQuiet) {
    std::string err;
    const nlohmann::json diff =
        runCompareJson({dataset("elephant.off"), "--views", "4", "--a", "max-tris=32,max-verts=32", "--b", ""}, &err)["diff"];
    ASSERT_TRUE(diff["cluster_count_warning"].is_string());
    EXPECT_NE(diff["cluster_count_warning"].get<std::string>().find("more than 5%"), std::string::npos);
    EXPECT_NE(err.find("conescope-cli: warning: A has"), std::string::npos) << err;
}

TEST(CliCompare, CsvIsOneTidyTableAndTextASummary) {
    const CliRun csv = runCli({"compare", dataset("torus.off"), "--views", "5", "--a", "cone=average", "--b", "", "--format", "csv", "-q"});
    ASSERT_EQ(csv.exitCode, 0) << csv.err;
    const std::vector<std::string> lines = splitLines(csv.out);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0], "view,eye_x,eye_y,eye_z,back_facing_triangles,triangles_culled_only_a,triangles_culled_only_b,"
                        "triangles_culled_both,efficiency_a,efficiency_b");
    for (const std::string& line : lines) EXPECT_EQ(std::count(line.begin(), line.end(), ','), 9) << line;
    const CliRun text = runCli({"compare", dataset("torus.off"), "--views", "5", "--a", "cone=average", "--b", "", "--format", "text", "-q"});
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_NE(text.out.find("A: cone=average"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("culled by A only"), std::string::npos) << text.out;
    EXPECT_LT(splitLines(text.out).size(), 10u);
    const CliRun oneEye = runCli({"compare", dataset("cube.off"), "--eye", "0,0,5", "--a", "", "--b", "", "--format", "text", "-q"});
    ASSERT_EQ(oneEye.exitCode, 0) << oneEye.err;
    EXPECT_NE(oneEye.out.find(" triangles, 1 view\n"), std::string::npos) << oneEye.out;
}

TEST(CliCompare, BadConfigurationsAreUsageErrors) {
    for (const std::vector<std::string>& sides : {std::vector<std::string>{"--a", "colour=red", "--b", ""},
                                                  std::vector<std::string>{"--a", "", "--b", "views=3"},
                                                  std::vector<std::string>{"--a", "max-tris=0", "--b", ""}}) {
        std::vector<std::string> command = {"compare", dataset("cube.off"), "-q"};
        command.insert(command.end(), sides.begin(), sides.end());
        const CliRun run = runCli(command);
        EXPECT_EQ(run.exitCode, 2) << sides[1] << sides[3];
        EXPECT_NE(run.err.find("conescope-cli: error: "), std::string::npos) << run.err;
        EXPECT_EQ(run.out, "");
    }
    EXPECT_EQ(runCli({"compare", dataset("cube.off"), "--b", ""}).exitCode, 2) << "--a is required";
}

}  // namespace
}  // namespace conescope
