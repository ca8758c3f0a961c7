// conescope-cli end to end on what it says about a mesh and its partitions: the mesh checks and the
// winding repair (check, stats, the CSV totals), and partitions written and read back as files.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "CliTestSupport.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using clitest::CliRun;
using clitest::dataset;
using clitest::runCli;
using clitest::runStatsJson;
using clitest::ScratchDirectory;
using clitest::splitLines;

TEST(CliPartition, FileBuilderReadsThePartitionBack) {
    ScratchDirectory scratch;
    for (const std::vector<std::string>& builder :
         {std::vector<std::string>{"--builder", "meshlet", "--max-tris", "32"},
          std::vector<std::string>{"--builder", "kmeans", "--clusters", "17"}}) {
        SCOPED_TRACE(builder[1]);
        const std::string output = scratch.file("clusters-" + builder[1] + ".vtp");
        std::vector<std::string> command = {"partition", dataset("torus.off"), "-o", output, "--quiet"};
        command.insert(command.end(), builder.begin(), builder.end());
        const CliRun run = runCli(command);
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const Mesh written = readMesh(output);
        ASSERT_EQ(written.faceArrays.count("cluster_id"), 1u);

        std::vector<std::string> direct = {dataset("torus.off"), "--views", "6", "--test", "all"};
        direct.insert(direct.end(), builder.begin(), builder.end());
        nlohmann::json original = runStatsJson(direct);
        nlohmann::json readBack = runStatsJson({output, "--builder", "file", "--views", "6", "--test", "all"});
        EXPECT_EQ(readBack["clusters"], original["clusters"]);
        // Cluster numbering may differ; every total over all clusters may not.
        for (size_t r = 0; r < original["results"].size(); ++r) {
            for (const char* key : {"clusters_culled", "triangles_culled", "back_facing_triangles", "missed_clusters",
                                    "uncullable_clusters"})
                EXPECT_EQ(readBack["results"][r][key], original["results"][r][key]) << key;
            // A sum over clusters: another order may round the last bit differently.
            EXPECT_NEAR(readBack["results"][r]["expected_efficiency"].get<double>(),
                        original["results"][r]["expected_efficiency"].get<double>(), 1e-12);
        }
    }
}

TEST(CliPartition, BundledPartitionIsReadByTheFileBuilder) {
    const nlohmann::json json = runStatsJson({dataset("icosphere-clusters.vtp"), "--builder", "file", "--views", "4"});
    EXPECT_GT(json["clusters"].get<size_t>(), 1u);
    EXPECT_EQ(json["results"][0]["false_culls"], 0);
}

// A tetrahedron whose last face is wound against the other three.
constexpr const char* kMisWoundTetrahedron =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 3 2\n";

TEST(CliCheck, ReportsAndRepairsWinding) {
    ScratchDirectory scratch;
    const std::string input = scratch.writeFile("tetrahedron.off", kMisWoundTetrahedron);
    CliRun run = runCli({"check", input});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    nlohmann::json report = nlohmann::json::parse(run.out);
    EXPECT_EQ(report["mesh"]["faces"], 4);
    EXPECT_EQ(report["report"]["inconsistent_edges"], 3);
    EXPECT_EQ(report["report"]["open_edges"], 0);
    EXPECT_EQ(report["report"]["components"], 1);
    EXPECT_EQ(report["report"]["orientable"], true);
    EXPECT_FALSE(report.contains("winding_fixed_faces"));

    const std::string output = scratch.file("fixed.vtp");
    run = runCli({"check", input, "--fix-winding", "-o", output});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    report = nlohmann::json::parse(run.out);
    EXPECT_EQ(report["winding_fixed_faces"], 1);
    EXPECT_EQ(report["report_after_fix"]["inconsistent_edges"], 0);
    EXPECT_EQ(report["output"], output);

    run = runCli({"check", output});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["report"]["inconsistent_edges"], 0);
}

// The CSV has no mesh object: its totals rows carry the mesh check and the winding repair instead,
// with the JSON's values.
TEST(CliStats, CsvTotalsCarryTheMeshReport) {
    ScratchDirectory scratch;
    const std::string input = scratch.writeFile("tetrahedron.off", kMisWoundTetrahedron);
    const std::vector<std::string> arguments = {input, "--fix-winding", "--views", "3", "--cone", "average,minimal"};
    const nlohmann::json mesh = runStatsJson(arguments)["mesh"];
    std::vector<std::string> command = {"stats", "--quiet", "--format", "csv", "--no-per-view", "--no-per-cluster"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const CliRun run = runCli(command);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::string> lines = splitLines(run.out);
    ASSERT_EQ(lines.size(), 3u) << run.out;  // header, one row per cone

    auto cells = [](const std::string& line) {
        std::vector<std::string> values;
        std::istringstream stream(line);
        for (std::string value; std::getline(stream, value, ',');) values.push_back(value);
        return values;
    };
    const std::vector<std::string> header = cells(lines[0]);
    for (size_t row = 1; row < lines.size(); ++row) {
        const std::vector<std::string> values = cells(lines[row]);
        ASSERT_EQ(values.size(), header.size()) << lines[row];
        std::map<std::string, std::string> byColumn;
        for (size_t c = 0; c < header.size(); ++c) byColumn[header[c]] = values[c];
        EXPECT_EQ(byColumn["inconsistent_edges"], "3");
        EXPECT_EQ(byColumn["winding_fixed_faces"], "1");
        for (const auto& [key, value] : mesh["report"].items())
            EXPECT_EQ(byColumn.at(key), value.is_boolean() ? (value.get<bool>() ? "1" : "0") : value.dump()) << key;
        EXPECT_EQ(byColumn["winding_fixed_faces"], mesh["winding_fixed_faces"].dump());
    }
}

TEST(CliCheck, CleanMeshHasNoProblems) {
    const CliRun run = runCli({"check", dataset("cube.off")});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const nlohmann::json report = nlohmann::json::parse(run.out)["report"];
    for (const char* key : {"open_edges", "non_manifold_edges", "inconsistent_edges", "duplicate_faces", "degenerate_faces"})
        EXPECT_EQ(report[key], 0) << key;
    EXPECT_EQ(report["components"], 1);
    EXPECT_EQ(report["orientable"], true);
}

// A cube whose every triangle is followed by its reverse (double-sided, as some exporters write
// props): nothing can be culled, and the run says why, with the count, in stats and in check.
TEST(CliCheck, DoubleSidedMeshIsWarnedAboutWithItsCount) {
    std::istringstream cube(clitest::readTextFile(dataset("cube.off")));
    std::string line, faces;
    std::vector<std::string> vertices;
    while (std::getline(cube, line)) {
        int a, b, c;
        if (std::sscanf(line.c_str(), "3 %d %d %d", &a, &b, &c) == 3)
            faces += line + "\n3 " + std::to_string(c) + " " + std::to_string(b) + " " + std::to_string(a) + "\n";
        else if (!line.empty() && line[0] != '#' && line != "OFF" && line.find(' ') != std::string::npos && line != "8 12 0")
            vertices.push_back(line);
    }
    ASSERT_EQ(vertices.size(), 8u);
    std::string text = "OFF\n8 24 0\n";
    for (const std::string& v : vertices) text += v + "\n";
    ScratchDirectory scratch;
    const std::string path = scratch.writeFile("double-sided.off", text + faces);
    const CliRun run = runCli({"stats", path, "--views", "16", "--no-per-view", "--no-per-cluster", "--format", "json", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("double-sided: 12 faces lie back to back"), std::string::npos) << run.err;
    const nlohmann::json stats = nlohmann::json::parse(run.out);
    EXPECT_EQ(stats["mesh"]["report"]["double_sided_faces"], 12);
    EXPECT_EQ(stats["results"][0]["triangles_culled"], 0);
    EXPECT_GT(stats["results"][0]["back_facing_triangles"], 0);
    const CliRun check = runCli({"check", path});
    ASSERT_EQ(check.exitCode, 0) << check.err;
    EXPECT_EQ(nlohmann::json::parse(check.out)["report"]["double_sided_faces"], 12);
    const CliRun single = runCli({"stats", dataset("cube.off"), "--views", "4", "--format", "json", "--quiet"});
    EXPECT_EQ(single.err.find("double-sided"), std::string::npos) << single.err;
}

// A tetrahedron in ASCII STL plus a triangle with two equal corners, which VTK's STL reader used to
// drop: the check and the statistics must count it.
constexpr const char* kStlWithDegenerateTriangle =
    "solid t\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\n"
    "facet normal 0 0 0\nouter loop\nvertex 1 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
    "endsolid t\n";

TEST(CliCheck, CountsTheDegenerateTrianglesOfAnStl) {
    ScratchDirectory scratch;
    const std::string input = scratch.writeFile("degenerate.stl", kStlWithDegenerateTriangle);
    const CliRun run = runCli({"check", input});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const nlohmann::json report = nlohmann::json::parse(run.out);
    EXPECT_EQ(report["mesh"]["faces"], 5);
    EXPECT_EQ(report["report"]["degenerate_faces"], 1);

    const nlohmann::json mesh = runStatsJson({input, "--views", "3"})["mesh"];
    EXPECT_EQ(mesh["faces"], 5);
    EXPECT_EQ(mesh["degenerate_faces"], 1);
    EXPECT_EQ(mesh["report"]["degenerate_faces"], 1);
}

TEST(CliCheck, MissingFileFails) {
    const CliRun run = runCli({"check", "/nonexistent/mesh.ply"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.err.find("/nonexistent/mesh.ply"), std::string::npos) << run.err;
}

// A bundled mesh with every face turned over: consistent winding, every normal pointing in.
std::string insideOut(const ScratchDirectory& scratch, const std::string& name) {
    const Mesh mesh = readMesh(dataset(name));
    std::ostringstream text;
    text << "OFF\n" << mesh.positions.size() << ' ' << mesh.faceCount() << " 0\n";
    for (const glm::vec3& p : mesh.positions) text << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        text << mesh.faceSize(f);
        for (size_t k = mesh.faceSize(f); k-- > 0;) text << ' ' << mesh.faceBegin(f)[k];
        text << '\n';
    }
    return scratch.writeFile("inside-out-" + name, text.str());
}

TEST(CliStats, InsideOutMeshIsWarnedAboutEvenWhenQuietAndFixedOnRequest) {
    ScratchDirectory scratch;
    const std::string mesh = insideOut(scratch, "icosphere.off");
    CliRun run = runCli({"stats", mesh, "--views", "4", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("conescope-cli: warning: the mesh has 1 closed component turned inside out"), std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("--fix-winding"), std::string::npos) << run.err;
    nlohmann::json json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["mesh"]["report"]["inside_out_components"], 1);
    EXPECT_EQ(json["mesh"]["winding_fixed_faces"], 0);

    run = runCli({"stats", mesh, "--views", "4", "--quiet", "--fix-winding"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["mesh"]["winding_fixed_faces"], json["mesh"]["faces"]);
    EXPECT_EQ(json["mesh"]["report"]["inside_out_components"], 1) << "the report describes the file as read";

    run = runCli({"stats", mesh, "--views", "4", "--quiet", "--format", "csv", "--no-per-view", "--no-per-cluster"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::vector<std::string> lines = splitLines(run.out);
    ASSERT_GE(lines.size(), 2u);
    auto cells = [](const std::string& line) {
        std::vector<std::string> parts;
        std::stringstream stream(line);
        for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
        return parts;
    };
    const std::vector<std::string> header = cells(lines[0]), totals = cells(lines[1]);
    const auto column = std::find(header.begin(), header.end(), "inside_out_components");
    ASSERT_NE(column, header.end()) << lines[0];
    EXPECT_EQ(totals.at(size_t(column - header.begin())), "1");

    run = runCli({"check", mesh});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["report"]["inside_out_components"], 1);
}

// A budget the limits allow no nearer is said even when quiet, with both counts; a budget met is not.
TEST(CliStats, ABudgetNotMetIsWarnedAbout) {
    CliRun run = runCli({"stats", dataset("elephant.off"), "--clusters", "50", "--views", "1", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const size_t made = nlohmann::json::parse(run.out)["clusters"].get<size_t>();
    EXPECT_GT(made, 50u);
    EXPECT_NE(run.err.find("conescope-cli: warning: asked for 50 clusters, made " + std::to_string(made)), std::string::npos)
        << run.err;
    run = runCli({"stats", dataset("elephant.off"), "--clusters", "60", "--builder", "kmeans", "--views", "1", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["clusters"], 60);
    EXPECT_EQ(run.err, "");
    run = runCli({"compare", dataset("elephant.off"), "--a", "clusters=50", "--views", "1", "--quiet"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("conescope-cli: warning: A: asked for 50 clusters"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace conescope
