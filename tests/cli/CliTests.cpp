// conescope-cli end to end: the built binary on the bundled datasets, checked against the core.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"
#include "core/Pipeline.h"
#include "io/MeshReader.h"
#include "io/StatisticsIO.h"

namespace conescope {
namespace {

using clitest::CliRun;
using clitest::dataset;
using clitest::datasetsDir;
using clitest::readTextFile;
using clitest::runCli;
using clitest::ScratchDirectory;
using clitest::splitLines;

using clitest::removeTimings;
using clitest::runStatsJson;

nlohmann::json inProcessJson(const std::string& path, const Settings& settings, const std::string& name) {
    nlohmann::json json = statisticsToJson(runStatistics(readMesh(path), settings, name));
    removeTimings(json);
    return json;
}

void expectSameDocument(nlohmann::json actual, const nlohmann::json& expected) {
    removeTimings(actual);
    const nlohmann::json differences = nlohmann::json::diff(expected, actual);
    EXPECT_TRUE(differences.empty()) << differences.dump().substr(0, 2000);
}

// VTK's formats and glTF are modules opened when a file needs one (io/FormatModules.h): a run on an
// OFF file loads neither VTK's libraries nor assimp's, whose loading cost every run 11 ms; a run on
// a .vtp file opens VTK's, one on a .glb assimp's. The dynamic loader's own log (LD_DEBUG=files)
// says which libraries the process opened.
std::string librariesOpenedFor(const std::string& mesh) {
    ScratchDirectory scratch;
    const std::string log = scratch.file("loader");
    const CliRun run = runCli({"stats", "--quiet", "--views", "1", mesh}, {"LD_DEBUG=files", "LD_DEBUG_OUTPUT=" + log});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    std::string opened;  // the loader adds the process id to the file's name
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(log).parent_path()))
        if (entry.path().filename().string().rfind("loader", 0) == 0) opened += readTextFile(entry.path().string());
    return opened;
}

TEST(CliStats, LoadsVtkAndAssimpOnlyForFilesThatNeedThem) {
    auto opens = [](const std::string& libraries, const char* name) { return libraries.find(name) != std::string::npos; };
    const std::string forOff = librariesOpenedFor(dataset("torus.off"));
    EXPECT_TRUE(opens(forOff, "libmeshoptimizer")) << "the loader's log is read";
    for (const char* name : {"libvtkCommonCore", "libassimp", "conescope_vtk_formats", "conescope_gltf_format"})
        EXPECT_FALSE(opens(forOff, name)) << name;
    const std::string forVtp = librariesOpenedFor(dataset("icosphere-clusters.vtp"));
    EXPECT_TRUE(opens(forVtp, "conescope_vtk_formats"));
    EXPECT_TRUE(opens(forVtp, "libvtkCommonCore"));
    EXPECT_FALSE(opens(forVtp, "libassimp"));
    const std::string forGlb = librariesOpenedFor(std::string(CONESCOPE_TESTDATA_DIR) + "/gltf/cube.glb");
    EXPECT_TRUE(opens(forGlb, "conescope_gltf_format"));
    EXPECT_TRUE(opens(forGlb, "libassimp"));
    EXPECT_FALSE(opens(forGlb, "libvtkCommonCore"));
}

// A real run, many clusters and views and two tests: the file, written without a tree, is nlohmann's
// layout of the same document.
// The text summary says when most clusters can never be culled, and only then.
TEST(CliStats, TextSaysWhenMostClustersCanNeverBeCulled) {
    const CliRun cube = runCli({"stats", dataset("cube.off"), "--quiet", "--views", "4", "--format", "text"});
    ASSERT_EQ(cube.exitCode, 0) << cube.err;
    EXPECT_NE(cube.out.find("can never be culled"), std::string::npos) << cube.out;
    const CliRun torus = runCli({"stats", dataset("torus.off"), "--quiet", "--views", "4", "--format", "text"});
    ASSERT_EQ(torus.exitCode, 0) << torus.err;
    EXPECT_EQ(torus.out.find("can never be culled"), std::string::npos) << torus.out;
}

TEST(CliStats, JsonOfARealRunIsLaidOutAsItsTree) {
    Settings settings;
    settings.views = 4;
    settings.tests = {CullTest::Octagon, CullTest::Apex};
    const RunStatistics run = runStatistics(readMesh(dataset("torus.off")), settings, "torus \"quoted\".off");
    std::ostringstream text;
    writeStatisticsJson(run, text);
    EXPECT_EQ(text.str(), statisticsToJson(run).dump(2) + "\n");
    EXPECT_EQ(statisticsToJson(run)["mesh"]["name"], "torus \"quoted\".off");
}

TEST(CliStats, DefaultRunEqualsTheCoreWithDefaultSettings) {
    const nlohmann::json json = runStatsJson({dataset("icosphere.off")});
    expectSameDocument(json, inProcessJson(dataset("icosphere.off"), Settings{}, "icosphere.off"));
}

TEST(CliStats, EveryFlagReachesTheCore) {
    const nlohmann::json json =
        runStatsJson({dataset("torus.off"), "--builder", "kmeans", "--clusters", "23", "--normal-weight", "0.5",
                      "--cone", "all", "--test", "oracle,vertices", "--test", "meshopt-sphere", "--sphere", "ritter",
                      "--views", "9", "--distance", "4.5", "--ortho"});
    Settings settings;
    settings.builder = Builder::KMeans;
    settings.clusterCount = 23;
    settings.normalWeight = 0.5;
    settings.cones = allConeMethods();
    settings.tests = {CullTest::Oracle, CullTest::Vertices, CullTest::MeshoptSphere};
    settings.sphere = SphereMethod::Ritter;
    settings.views = 9;
    settings.distance = 4.5;
    settings.orthographic = true;
    expectSameDocument(json, inProcessJson(dataset("torus.off"), settings, "torus.off"));
}

TEST(CliStats, MeshoptBuilderFlagsReachTheCore) {
    const nlohmann::json json = runStatsJson({dataset("icosphere.off"), "--builder", "meshopt", "--max-verts", "32",
                                              "--max-tris", "40", "--cone-weight", "0.25", "--cone", "meshopt",
                                              "--test", "apex", "--views", "5"});
    Settings settings;
    settings.builder = Builder::Meshopt;
    settings.limits.maxVertices = 32;
    settings.limits.maxTriangles = 40;
    settings.meshoptConeWeight = 0.25f;
    settings.cones = {ConeMethod::Meshopt};
    settings.tests = {CullTest::Apex};
    settings.views = 5;
    expectSameDocument(json, inProcessJson(dataset("icosphere.off"), settings, "icosphere.off"));
}

TEST(CliStats, JsonHasEveryKey) {
    const nlohmann::json json = runStatsJson({dataset("cube-quads.off"), "--views", "4"});
    for (const char* key : {"conescope_version", "mesh", "settings", "clusters", "view_count", "results"})
        EXPECT_TRUE(json.contains(key)) << key;
    for (const char* key : {"name", "vertices", "faces", "triangles", "degenerate_faces", "report", "winding_fixed_faces"})
        EXPECT_TRUE(json["mesh"].contains(key)) << key;
    EXPECT_EQ(json["mesh"]["name"], "cube-quads.off");
    EXPECT_EQ(json["mesh"]["faces"], 6);
    EXPECT_EQ(json["mesh"]["triangles"], 12);
    for (const char* key : {"builder", "max_vertices", "max_triangles", "clusters_target", "cluster_file", "normal_weight",
                            "cone_weight", "cones", "tests", "sphere", "views", "distance", "orthographic", "eye"})
        EXPECT_TRUE(json["settings"].contains(key)) << key;
    ASSERT_EQ(json["results"].size(), 1u);
    const nlohmann::json& result = json["results"][0];
    for (const char* key : {"cone", "test", "clusters_culled", "triangles_culled", "back_facing_triangles",
                            "missed_clusters", "false_culls", "efficiency", "expected_efficiency", "uncullable_clusters",
                            "ns_per_cluster", "views", "clusters"})
        EXPECT_TRUE(result.contains(key)) << key;
    ASSERT_EQ(result["views"].size(), 4u);
    for (const char* key : {"view", "eye", "direction", "orthographic", "clusters_culled", "triangles_culled",
                            "back_facing_triangles", "front_facing_triangles", "back_facing_clusters", "missed_clusters",
                            "false_culls", "efficiency", "ns_per_cluster"})
        EXPECT_TRUE(result["views"][0].contains(key)) << key;
    ASSERT_EQ(result["clusters"].size(), json["clusters"].get<size_t>());
    for (const char* key : {"cluster", "faces", "triangles", "vertices", "half_angle_deg", "cullable", "times_culled",
                            "times_back_facing", "false_culls"})
        EXPECT_TRUE(result["clusters"][0].contains(key)) << key;
}

// The safety property: no cone method with no test ever culls a cluster holding a visible face.
TEST(CliStats, NoFalseCullsForAnyConeAndTest) {
    for (const char* mesh : {"torus.off", "hexagonal-prism.off", "icosphere.off"}) {
        SCOPED_TRACE(mesh);
        const nlohmann::json json = runStatsJson({dataset(mesh), "--cone", "all", "--test", "all", "--views", "24"});
        ASSERT_EQ(json["results"].size(), allConeMethods().size() * allCullTests().size());
        for (const nlohmann::json& result : json["results"]) {
            SCOPED_TRACE(result["cone"].get<std::string>() + "/" + result["test"].get<std::string>());
            EXPECT_EQ(result["false_culls"], 0);
            EXPECT_GE(result["efficiency"].get<double>(), 0.0);
            EXPECT_LE(result["efficiency"].get<double>(), 1.0);
            size_t culled = 0;
            ASSERT_EQ(result["views"].size(), 24u);
            for (const nlohmann::json& view : result["views"]) {
                EXPECT_EQ(view["false_culls"], 0);
                EXPECT_GE(view["efficiency"].get<double>(), 0.0);
                EXPECT_LE(view["efficiency"].get<double>(), 1.0);
                culled += view["clusters_culled"].get<size_t>();
            }
            EXPECT_EQ(result["clusters_culled"].get<size_t>(), culled);
            for (const nlohmann::json& cluster : result["clusters"]) EXPECT_EQ(cluster["false_culls"], 0);
        }
    }
}

// Every bundled mesh, every builder that takes it, every cone and every test: no false cull.
TEST(CliStats, NoFalseCullsOnAnyBundledMeshWithAnyBuilder) {
    size_t runs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(datasetsDir())) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".off" && extension != ".vtp") continue;
        std::vector<std::string> builders = {"optimized", "meshlet", "kmeans", "meshopt"};
        if (extension == ".vtp") builders.push_back("file");  // the bundled .vtp carries cluster_id
        for (const std::string& builder : builders) {
            SCOPED_TRACE(entry.path().filename().string() + " " + builder);
            const nlohmann::json json = runStatsJson({entry.path().string(), "--builder", builder, "--cone", "all",
                                                      "--test", "all", "--views", "8", "--no-per-view", "--no-per-cluster"});
            ASSERT_EQ(json["results"].size(), allConeMethods().size() * allCullTests().size());
            for (const nlohmann::json& result : json["results"])
                EXPECT_EQ(result["false_culls"], 0) << result["cone"] << "/" << result["test"];
            ++runs;
        }
    }
    EXPECT_GE(runs, 30u);  // 8 bundled meshes
}

// Tidy tables: each file one header row and rows of as many cells, loadable by pandas.read_csv as is.
std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    for (const std::string& line : splitLines(text)) {
        std::vector<std::string> cells;
        std::istringstream stream(line);
        for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
        EXPECT_TRUE(rows.empty() || cells.size() == rows.front().size()) << line;
        EXPECT_EQ(line.rfind("#", 0), std::string::npos) << "no comment lines in a tidy table";
        rows.push_back(cells);
    }
    return rows;
}

TEST(CliStats, CsvTablesAreTidyWithOneRowPerViewAndCluster) {
    ScratchDirectory scratch;
    const std::vector<std::string> options = {"--cone", "minimal,average", "--test", "vertices,aabb", "--views", "7"};
    std::vector<std::string> command = {"stats", dataset("torus.off"), "--quiet", "-o", scratch.file("torus.csv")};
    command.insert(command.end(), options.begin(), options.end());
    const CliRun run = runCli(command);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    std::vector<std::string> jsonArguments = {dataset("torus.off")};
    jsonArguments.insert(jsonArguments.end(), options.begin(), options.end());
    const size_t clusters = runStatsJson(jsonArguments)["clusters"].get<size_t>();
    ASSERT_GT(clusters, 1u);

    const auto totals = csvRows(readTextFile(scratch.file("torus.csv")));
    const auto views = csvRows(readTextFile(scratch.file("torus.views.csv")));
    const auto clusterRows = csvRows(readTextFile(scratch.file("torus.clusters.csv")));
    ASSERT_EQ(totals.size(), 1u + 4u);
    EXPECT_EQ(views.size(), 1u + 4u * 7u);
    EXPECT_EQ(clusterRows.size(), 1u + 4u * clusters);
    for (const auto* table : {&totals, &views, &clusterRows}) {
        EXPECT_EQ(table->front().at(0), "cone");
        EXPECT_EQ(table->front().at(1), "test");
    }
    EXPECT_EQ(totals[1][0] + "," + totals[1][1], "minimal,vertices");
    EXPECT_EQ(totals[4][0] + "," + totals[4][1], "average,aabb");

    // On stdout one table: the totals, or the one --table names.
    command = {"stats", dataset("torus.off"), "--quiet", "--format", "csv", "--table", "views"};
    command.insert(command.end(), options.begin(), options.end());
    const auto shown = csvRows(runCli(command).out);
    ASSERT_EQ(shown.size(), views.size());
    EXPECT_EQ(shown.front(), views.front());  // same header (ns_per_cluster differs from run to run)
    const CliRun wrong = runCli({"stats", dataset("torus.off"), "--quiet", "--format", "json", "--table", "views"});
    EXPECT_EQ(wrong.exitCode, 2);
}

TEST(CliStats, OutputFileTakesTheFormatFromItsExtension) {
    ScratchDirectory scratch;
    const std::string output = scratch.file("result.csv");
    const CliRun run = runCli({"stats", dataset("cube.off"), "--views", "3", "-o", output});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_NE(run.err.find("%"), std::string::npos) << "progress goes to stderr unless --quiet";
    EXPECT_EQ(readTextFile(output).rfind("cone,test,clusters,", 0), 0u);
    // Only the tables are left in the folder: the temporary files were renamed, not copied.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(scratch.path()), {}), 3);
}

TEST(CliStats, EyeGivesOneView) {
    const nlohmann::json json = runStatsJson({dataset("icosphere.off"), "--eye", "-4,0.5,2", "--cone", "all"});
    EXPECT_EQ(json["view_count"], 1);
    EXPECT_EQ(json["settings"]["eye"], nlohmann::json::array({-4.0, 0.5, 2.0}));
    for (const nlohmann::json& result : json["results"]) {
        ASSERT_EQ(result["views"].size(), 1u);
        EXPECT_EQ(result["views"][0]["eye"], nlohmann::json::array({-4.0, 0.5, 2.0}));
        EXPECT_EQ(result["views"][0]["orthographic"], false);
        EXPECT_GT(result["views"][0]["back_facing_triangles"].get<size_t>(), 0u);
    }
}

TEST(CliStats, TablesCanBeLeftOut) {
    const nlohmann::json json = runStatsJson({dataset("cube.off"), "--views", "3", "--no-per-view", "--no-per-cluster"});
    ASSERT_EQ(json["results"].size(), 1u);
    EXPECT_FALSE(json["results"][0].contains("views"));
    EXPECT_FALSE(json["results"][0].contains("clusters"));
    EXPECT_TRUE(json["results"][0].contains("efficiency"));
}

TEST(CliStats, MissingOrBrokenMeshFailsNamingTheFile) {
    ScratchDirectory scratch;
    const std::string missing = scratch.file("no-such-mesh.off");
    CliRun run = runCli({"stats", missing});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.out, "");
    EXPECT_NE(run.err.find("conescope-cli: error: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(missing), std::string::npos) << run.err;

    const std::string broken = scratch.writeFile("broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
    run = runCli({"stats", broken, "--quiet"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("conescope-cli: error: " + broken), std::string::npos) << run.err;
}

TEST(CliStats, FailedRunKeepsTheOldOutput) {
    ScratchDirectory scratch;
    const std::string output = scratch.writeFile("result.json", "old\n");
    const CliRun run = runCli({"stats", scratch.file("missing.off"), "-o", output, "--quiet"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(readTextFile(output), "old\n");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(scratch.path()), {}), 1);

    const CliRun good = runCli({"stats", dataset("cube.off"), "--views", "2", "-o", output, "--quiet"});
    ASSERT_EQ(good.exitCode, 0) << good.err;
    EXPECT_EQ(nlohmann::json::parse(readTextFile(output))["view_count"], 2);
}

TEST(CliStats, BadArgumentsExitWithTwo) {
    const std::string mesh = dataset("cube.off");
    const std::vector<std::vector<std::string>> commands = {
        {},
        {"frobnicate"},
        {"stats"},
        {"stats", mesh, "--frobnicate"},
        {"stats", mesh, "--cone", "widest"},
        {"stats", mesh, "--test", "vertices,bogus"},
        {"stats", mesh, "--builder", "octree"},
        {"stats", mesh, "--sphere", "cube"},
        {"stats", mesh, "--views", "0"},
        {"stats", mesh, "--views", "many"},
        {"stats", mesh, "--distance", "-1"},
        {"stats", mesh, "--eye", "1,2"},
        {"stats", mesh, "--eye", "1,2,x"},
        {"stats", mesh, "--eye", "1,2,3", "--views", "5"},
        {"stats", mesh, "--format", "xml"},
        {"stats", mesh, "--cone-weight", "2"},
        // Accepted by the parser, refused by the core: meshoptimizer needs max-tris divisible by 4.
        {"stats", mesh, "--builder", "meshopt", "--max-tris", "10"},
        {"check", mesh, "-o", "fixed.off"},
        {"partition", mesh},
        {"partition", mesh, "-o", "clusters.off"},
    };
    for (const std::vector<std::string>& command : commands) {
        std::string text;
        for (const std::string& word : command) text += word + " ";
        SCOPED_TRACE(text);
        const CliRun run = runCli(command);
        EXPECT_EQ(run.exitCode, 2) << run.err;
        EXPECT_NE(run.err.find("conescope-cli: error: "), std::string::npos) << run.err;
    }
    const CliRun unknownCone = runCli({"stats", mesh, "--cone", "widest"});
    EXPECT_NE(unknownCone.err.find("minimal"), std::string::npos) << "the message lists the accepted names";
}

TEST(CliStats, HelpShowsTheDefaultSettings) {
    const CliRun run = runCli({"stats", "--help"});
    ASSERT_EQ(run.exitCode, 0);
    const Settings defaults;
    // CLI11 shows a default as "--option TYPE:CHECK=value" on the option's line.
    auto shownDefault = [&](const std::string& option, const std::string& value) {
        const size_t line = run.out.find("  " + option + " ");
        if (line == std::string::npos) return std::string("option not listed");
        const std::string text = run.out.substr(line, run.out.find('\n', line) - line);
        const size_t equals = text.find('=');
        if (equals == std::string::npos) return "no default in: " + text;
        const std::string shown = text.substr(equals + 1, text.find(' ', equals) - equals - 1);
        return shown == value ? std::string() : "shows '" + shown + "' in: " + text;
    };
    EXPECT_EQ(shownDefault("--max-verts", std::to_string(defaults.limits.maxVertices)), "");
    EXPECT_EQ(shownDefault("--max-tris", std::to_string(defaults.limits.maxTriangles)), "");
    EXPECT_EQ(shownDefault("--views", std::to_string(defaults.views)), "");
    EXPECT_EQ(shownDefault("--builder", toString(defaults.builder)), "");
    EXPECT_EQ(shownDefault("--cone", toString(defaults.cones.front())), "");
    EXPECT_EQ(shownDefault("--test", toString(defaults.tests.front())), "");
    EXPECT_EQ(shownDefault("--sphere", toString(defaults.sphere)), "");
}

// Back faces that were not culled are lost to the test or to the partition, nowhere else, on every
// bundled mesh (also the view-independent shares: the oracle's never below the test's).
TEST(CliStats, LossesAccountForEveryBackFaceOnEveryBundledMesh) {
    for (const auto& entry : std::filesystem::directory_iterator(datasetsDir())) {
        if (!hasSupportedMeshExtension(entry.path().string())) continue;
        const nlohmann::json json = runStatsJson({entry.path().string(), "--views", "12", "--test", "apex,sphere,oracle"});
        for (const nlohmann::json& result : json["results"]) {
            const std::string name = entry.path().filename().string() + " " + result["test"].get<std::string>();
            EXPECT_EQ(result["triangles_culled"].get<size_t>() + result["test_loss_triangles"].get<size_t>() +
                          result["partition_loss_triangles"].get<size_t>(),
                      result["back_facing_triangles"].get<size_t>())
                << name;
            for (const nlohmann::json& view : result["views"])
                EXPECT_EQ(view["triangles_culled"].get<size_t>() + view["test_loss_triangles"].get<size_t>() +
                              view["partition_loss_triangles"].get<size_t>(),
                          view["back_facing_triangles"].get<size_t>())
                    << name;
            for (const nlohmann::json& cluster : result["clusters"])
                EXPECT_GE(cluster["oracle_fraction"].get<double>(), cluster["cull_fraction"].get<double>()) << name;
            EXPECT_EQ(result["false_culls"], 0) << name;
        }
    }
}

TEST(CliClusters, RanksTheDisplayedTestsClustersWorstFirst) {
    const std::string mesh = dataset("torus.off");
    const nlohmann::json stats = runStatsJson({mesh, "--views", "16", "--max-tris", "32", "--max-verts", "32"});
    const nlohmann::json& all = stats["results"][0]["clusters"];
    for (const std::string sort : {"test-loss", "partition-loss", "radius", "cull-fraction"}) {
        const CliRun run = runCli({"clusters", mesh, "--views", "16", "--max-tris", "32", "--max-verts", "32", "--sort", sort,
                                   "--top", "5", "--format", "json", "--quiet"});
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const nlohmann::json json = nlohmann::json::parse(run.out);
        EXPECT_EQ(json["sort"], sort);
        const nlohmann::json& rows = json["rows"];
        ASSERT_EQ(rows.size(), 5u);
        // Each row is the stats run's row of that cluster, and no cluster left out is worse.
        const std::string key = sort == "test-loss" ? "test_loss_triangles"
                                : sort == "partition-loss" ? "partition_loss_triangles"
                                : sort == "radius" ? "sphere_radius" : "cull_fraction";
        const double sign = sort == "cull-fraction" ? -1.0 : 1.0;
        for (size_t i = 0; i < rows.size(); ++i) {
            EXPECT_EQ(rows[i], all[rows[i]["cluster"].get<size_t>()]) << sort;
            if (i > 0) {
                EXPECT_GE(sign * rows[i - 1][key].get<double>(), sign * rows[i][key].get<double>()) << sort;
            }
        }
        size_t worseLeftOut = 0;
        for (const nlohmann::json& cluster : all)
            worseLeftOut += sign * cluster[key].get<double>() > sign * rows.back()[key].get<double>() &&
                            std::find(rows.begin(), rows.end(), cluster) == rows.end();
        EXPECT_EQ(worseLeftOut, 0u) << sort;
    }
    const CliRun csv = runCli({"clusters", mesh, "--top", "3", "--format", "csv", "--quiet"});
    ASSERT_EQ(csv.exitCode, 0) << csv.err;
    EXPECT_EQ(splitLines(csv.out).size(), 4u);
    EXPECT_EQ(splitLines(csv.out)[0].rfind("cone,test,cluster,", 0), 0u);
    const CliRun text = runCli({"clusters", mesh, "--top", "3", "--quiet"});
    EXPECT_NE(text.out.find("clusters by test-loss"), std::string::npos) << text.out;
    const CliRun bad = runCli({"clusters", mesh, "--sort", "prettiest"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("test-loss"), std::string::npos) << "the message lists the keys";
}

TEST(CliStats, TextSummaryNamesEfficiencyLossesAndWorstClusters) {
    const CliRun run = runCli({"stats", dataset("fandisk.off"), "--views", "8", "--format", "text", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (const char* expected : {"fandisk.off:", "efficiency", "lost by the test", "by the partition", "worst clusters by test loss"})
        EXPECT_NE(run.out.find(expected), std::string::npos) << expected << "\n" << run.out;
    EXPECT_LT(splitLines(run.out).size(), 20u) << "a summary, not every view";
}

}  // namespace
}  // namespace conescope
