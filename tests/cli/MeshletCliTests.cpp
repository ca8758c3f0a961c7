// An engine's meshlets through the command line: meshoptimizer's own loop (tests/reference, which
// links only the library) writes its meshlets as a meshlet JSON with bounds and as an OBJ with an
// object (and, rewritten, a group) per meshlet; conescope-cli reads each with meshoptimizer's
// meshlet count and scores the engine tests as that loop does. Bad files are refused before
// anything is measured.
#include <filesystem>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"

namespace conescope {
namespace {

using clitest::CliRun;
using clitest::dataset;
using clitest::readTextFile;
using clitest::runCli;
using clitest::runStatsJson;
using clitest::ScratchDirectory;

// meshopt_reference's numbers for a mesh, its files written into `scratch`.
nlohmann::json referenceLoop(const std::string& mesh, const ScratchDirectory& scratch) {
    const CliRun run = clitest::runProgram(CONESCOPE_REFERENCE_PATH, {mesh, "--views", "64", "--distance", "3", "--json", scratch.file("m.json"),
                                                                      "--obj", scratch.file("m.obj")});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return nlohmann::json::parse(run.out);
}

// The engine tests' efficiencies from conescope-cli, keyed by test name, with the cluster count.
std::map<std::string, double> engineEfficiencies(const std::vector<std::string>& input, size_t& clusters) {
    std::vector<std::string> arguments = input;
    for (const char* option : {"--builder", "file", "--test", "meshopt-apex-f32,meshopt-sphere-s8", "--views", "64", "--distance", "3",
                               "--no-per-view", "--no-per-cluster"})
        arguments.push_back(option);
    const nlohmann::json json = runStatsJson(arguments);
    clusters = json.value("clusters", size_t(0));
    std::map<std::string, double> efficiencies;
    for (const nlohmann::json& result : json["results"]) {
        EXPECT_EQ(result["engine_record"], true);
        EXPECT_GT(result["bytes_per_cluster"].get<size_t>(), 0u);
        efficiencies[result["test"].get<std::string>()] = result["efficiency"].get<double>();
    }
    return efficiencies;
}

// The OBJ's `o meshlet<i>` objects as `g` groups, which read the same.
std::string asGroups(const std::string& obj, const ScratchDirectory& scratch) {
    std::string text = readTextFile(obj);
    for (size_t at = text.find("\no "); at != std::string::npos; at = text.find("\no ", at + 1)) text[at + 1] = 'g';
    EXPECT_NE(text.find("\ng meshlet0\n"), std::string::npos);
    return scratch.writeFile("m-groups.obj", text);
}

void expectReferenceNumbers(const std::string& mesh) {
    SCOPED_TRACE(mesh);
    ScratchDirectory scratch;
    const nlohmann::json reference = referenceLoop(mesh, scratch);
    for (const std::vector<std::string>& input :
         {std::vector<std::string>{mesh, "--cluster-file", scratch.file("m.json")}, std::vector<std::string>{scratch.file("m.obj")},
          std::vector<std::string>{asGroups(scratch.file("m.obj"), scratch)}}) {
        size_t clusters = 0;
        const std::map<std::string, double> ours = engineEfficiencies(input, clusters);
        EXPECT_EQ(clusters, reference["meshlets"].get<size_t>()) << input.back();
        for (const char* test : {"meshopt-apex-f32", "meshopt-sphere-s8"})
            EXPECT_NEAR(ours.at(test), reference[test]["efficiency"].get<double>(), 0.002) << test << " from " << input.back();
    }
}

TEST(CliMeshlets, MeshoptimizersOwnLoopGivesTheEngineTestsNumbers) {
    for (const char* name : {"elephant.off", "fandisk.off"}) expectReferenceNumbers(dataset(name));
}

// CGAL's bunny00 and armadillo (about a second each) when scripts/fetch-datasets.sh has fetched
// them; a fresh clone skips them, visibly. bench/results/meshopt-reference.md has all three.
TEST(CliMeshlets, MeshoptimizersOwnLoopGivesTheEngineTestsNumbersOnFetchedMeshes) {
    size_t measured = 0;
    for (const char* name : {"cgal/bunny00.off", "cgal/armadillo.off"})
        if (std::filesystem::exists(dataset(name))) expectReferenceNumbers(dataset(name)), ++measured;
    if (measured == 0) GTEST_SKIP() << "datasets/cgal/ holds neither bunny00 nor armadillo (scripts/fetch-datasets.sh)";
}

// meshoptimizer's own meshlets written without their bounds score as with them: the bounds are the
// library's of the file's meshlets in the file's order (its triangle order is not the mesh's face
// order; elephant's bounds from the face order differ on most meshlets).
TEST(CliMeshlets, AFileWithoutBoundsScoresAsWithTheLibrarysOwn) {
    ScratchDirectory scratch;
    const std::string mesh = dataset("elephant.off");
    referenceLoop(mesh, scratch);
    nlohmann::json document = nlohmann::json::parse(readTextFile(scratch.file("m.json")));
    ASSERT_TRUE(document.contains("bounds"));
    document.erase("bounds");
    const std::string without = scratch.writeFile("m-without-bounds.json", document.dump());
    std::vector<nlohmann::json> runs;
    for (const std::string& file : {scratch.file("m.json"), without}) {
        nlohmann::json run = runStatsJson({mesh, "--builder", "file", "--cluster-file", file, "--test", "meshopt-apex-f32,meshopt-sphere-s8",
                                           "--views", "16", "--no-per-cluster"});
        clitest::removeTimings(run);
        runs.push_back(run["results"]);
    }
    ASSERT_EQ(runs[0].size(), 2u);
    EXPECT_EQ(runs[0], runs[1]);
}

TEST(CliMeshlets, PartitionOutputReadsBackInEveryCommand) {
    ScratchDirectory scratch;
    const std::string mesh = dataset("elephant.off"), meshlets = scratch.file("e.meshlets");
    const CliRun written = runCli({"partition", mesh, "--builder", "meshopt", "-o", meshlets, "--quiet"});
    ASSERT_EQ(written.exitCode, 0) << written.err;
    const nlohmann::json meshopt = runStatsJson({mesh, "--builder", "meshopt", "--views", "8", "--no-per-view"});
    const nlohmann::json file = runStatsJson({mesh, "--builder", "file", "--cluster-file", meshlets, "--views", "8", "--no-per-view"});
    EXPECT_EQ(file["clusters"], meshopt["clusters"]);
    EXPECT_EQ(file["results"][0]["triangles_culled"], meshopt["results"][0]["triangles_culled"]);
    const CliRun clusters = runCli({"clusters", mesh, "--builder", "file", "--cluster-file", meshlets, "--test", "meshopt-apex-f32",
                                    "--sort", "false-culls", "--top", "3", "--format", "json", "--quiet"});
    ASSERT_EQ(clusters.exitCode, 0) << clusters.err;
    EXPECT_EQ(nlohmann::json::parse(clusters.out)["rows"].size(), 3u);
    const CliRun compare = runCli({"compare", mesh, "--a", "builder=file,cluster-file=" + meshlets, "--views", "8", "--format", "json", "--quiet"});
    ASSERT_EQ(compare.exitCode, 0) << compare.err;
    EXPECT_EQ(nlohmann::json::parse(compare.out)["diff"]["clusters_a"], meshopt["clusters"]);
}

TEST(CliMeshlets, ABadMeshletFileIsRefusedAndNothingMeasured) {
    ScratchDirectory scratch;
    const std::string mesh = dataset("elephant.off");
    const std::string bad = scratch.writeFile("bad.json",
                                              "{\"format\": \"meshoptimizer-meshlets\", \"meshlets\": [[0, 0, 3, 1]], "
                                              "\"meshlet_vertices\": [0, 1, 99999], \"meshlet_triangles\": [0, 1, 2, 0]}");
    const CliRun run = runCli({"stats", mesh, "--builder", "file", "--cluster-file", bad, "--quiet"});
    EXPECT_NE(run.exitCode, 0);
    EXPECT_EQ(run.out, "") << "no statistics for a partition that did not load";
    EXPECT_NE(run.err.find(bad + ": meshlet 0: meshlet_vertices[2] = 99999 is past the mesh file's 2775 vertices"), std::string::npos) << run.err;
    const std::string partial = scratch.writeFile("partial.json",
                                                  "{\"format\": \"meshoptimizer-meshlets\", \"meshlets\": [[0, 0, 3, 1]], "
                                                  "\"meshlet_vertices\": [575, 1215, 1225], \"meshlet_triangles\": [0, 1, 2, 0]}");
    const CliRun some = runCli({"stats", mesh, "--builder", "file", "--cluster-file", partial, "--quiet"});
    EXPECT_NE(some.exitCode, 0);
    EXPECT_EQ(some.out, "");
    EXPECT_NE(some.err.find("5557 faces are in no meshlet"), std::string::npos) << some.err;
}

}  // namespace
}  // namespace conescope
