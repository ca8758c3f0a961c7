// report.html as a browser shows it: a batch's page opened in Debian's headless chromium, whose DOM
// after the page's script ran (--dump-dom) must hold a plot point per mesh in each plot, a table row per
// mesh linking to its JSON, the error row and the totals of results.csv.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <locale>
#include <regex>
#include <sstream>

#include "BatchTestSupport.h"
#include "CliTestSupport.h"

namespace conescope {
namespace {

namespace fs = std::filesystem;
using clitest::readResults;
using clitest::readTextFile;
using clitest::ScratchDirectory;

size_t occurrences(const std::string& text, const std::regex& pattern) {
    return size_t(std::distance(std::sregex_iterator(text.begin(), text.end(), pattern), std::sregex_iterator()));
}

// The page's DOM once its scripts ran, as headless chromium serialises it (a fresh profile, no network
// services, no sandbox: the tests may run as root).
std::string renderedDom(const std::string& page, const ScratchDirectory& scratch) {
    const std::string profile = scratch.file("chromium-profile"), out = scratch.file("dom.html"), err = scratch.file("chromium.err");
    const std::vector<std::string> command = {CONESCOPE_CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                                              "--no-first-run", "--disable-background-networking", "--disable-component-update",
                                              "--disable-sync", "--user-data-dir=" + profile, "--dump-dom",
                                              "file://" + fs::absolute(page).string()};
    const pid_t child = ::fork();
    if (child == 0) {
        std::freopen(out.c_str(), "w", stdout);
        std::freopen(err.c_str(), "w", stderr);
        std::vector<char*> argv;
        for (const std::string& word : command) argv.push_back(const_cast<char*>(word.c_str()));
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    EXPECT_EQ(clitest::waitCli(child), 0) << CONESCOPE_CHROMIUM << " (install it: scripts/install-dependencies.sh)\n"
                                          << readTextFile(err);
    return readTextFile(out);
}

std::string withThousands(unsigned long value) {
    std::string digits = std::to_string(value);
    for (int at = int(digits.size()) - 3; at > 0; at -= 3) digits.insert(size_t(at), ",");
    return digits;
}

TEST(BatchReport, RendersPlotsTablesAndTotalsInHeadlessChromium) {
    ScratchDirectory scratch;
    clitest::copyBundledDatasets(scratch.path() / "library");
    scratch.writeFile("library/broken.off", "OFF\n3 1 0\n0 0 0\n");
    const std::string out = scratch.file("out");
    const clitest::CliRun batch =
        clitest::runCli({"batch", scratch.file("library"), "-o", out, "--views", "8", "--compare-meshopt", "--quiet"});
    ASSERT_EQ(batch.exitCode, 3) << batch.err;
    const std::vector<std::map<std::string, std::string>> rows = readResults(out + "/results.csv");
    ASSERT_EQ(rows.size(), 9u);
    const std::string page = readTextFile(out + "/report.html");
    // Self-contained: nothing for the browser to fetch.
    EXPECT_FALSE(std::regex_search(page, std::regex(R"((src|href)\s*=\s*["']?(https?:)?//)")));
    EXPECT_EQ(page.find("<link"), std::string::npos);

    const std::string dom = renderedDom(out + "/report.html", scratch);
    ASSERT_NE(dom.find("data-rendered=\"yes\""), std::string::npos) << dom.substr(0, 2000);
    const std::string triangles = dom.substr(dom.find("id=\"plot-triangles\""), dom.find("id=\"plot-compare\"") - dom.find("id=\"plot-triangles\""));
    const std::string compare = dom.substr(dom.find("id=\"plot-compare\""), dom.find("id=\"plot-losses\"") - dom.find("id=\"plot-compare\""));
    EXPECT_EQ(occurrences(triangles, std::regex("<circle class=\"point\"")), 8u);
    EXPECT_EQ(occurrences(compare, std::regex("<circle class=\"point\"")), 8u);
    EXPECT_EQ(occurrences(dom, std::regex("<rect class=\"bar culled\"")), 8u);  // a bar per mesh
    EXPECT_EQ(occurrences(dom, std::regex("<rect class=\"bar culled library\"")), 1u);  // and the whole library's
    EXPECT_EQ(occurrences(dom, std::regex("<tr class=\"mesh-row\"")), 8u);
    EXPECT_EQ(occurrences(dom, std::regex("<tr class=\"error-row\"")), 1u);
    EXPECT_NE(dom.find("header declares 3 vertices"), std::string::npos);
    unsigned long trianglesTotal = 0;
    for (const auto& row : rows) {
        if (row.at("status") != "ok") continue;
        trianglesTotal += std::stoul(row.at("triangles"));
        EXPECT_NE(dom.find("href=\"" + row.at("json") + "\""), std::string::npos) << row.at("json");
        EXPECT_TRUE(fs::exists(out + "/" + row.at("json")));
    }
    EXPECT_NE(dom.find("<b>" + withThousands(trianglesTotal) + "</b><span class=\"muted\">triangles</span>"), std::string::npos)
        << trianglesTotal;
    // The worst first: the table starts with the least efficient mesh.
    double least = 2;
    std::string worst;
    for (const auto& row : rows)
        if (row.at("status") == "ok" && std::stod(row.at("efficiency")) < least) least = std::stod(row.at("efficiency")), worst = row.at("file");
    EXPECT_NE(dom.find("<tr class=\"mesh-row\" data-file=\"" + worst + "\""), std::string::npos) << worst;
}

// The uncullable note counts the meshes whose rows carry a note, and `--granularity` adds the plot
// of culled share against bytes: the batch's own record, 2, 4 and 8 cones (float and compact) and
// per-triangle culling, each a point; `--lod` the bars of efficiency by level.
TEST(BatchReport, GranularityPlotAndTheUncullableNoteFollowTheRows) {
    ScratchDirectory scratch;
    clitest::copyBundledDatasets(scratch.path() / "library");
    const std::string out = scratch.file("out");
    const clitest::CliRun batch = clitest::runCli({"batch", scratch.file("library"), "-o", out, "--views", "8", "--granularity", "--lod", "--quiet"});
    ASSERT_EQ(batch.exitCode, 0) << batch.err;
    const std::vector<std::map<std::string, std::string>> rows = readResults(out + "/results.csv");
    size_t noted = 0;
    for (const auto& row : rows) {
        noted += row.at("note").empty() ? 0 : 1;
        EXPECT_FALSE(row.at("cones_4_culled_share").empty()) << row.at("file");
        EXPECT_LE(std::stoul(row.at("cones_4_compact_bytes_per_cluster")), 32u);
    }
    ASSERT_GT(noted, 0u);
    ASSERT_LT(noted, rows.size());
    const std::string dom = renderedDom(out + "/report.html", scratch);
    ASSERT_NE(dom.find("data-rendered=\"yes\""), std::string::npos) << dom.substr(0, 2000);
    EXPECT_NE(dom.find(std::to_string(noted) + " of " + std::to_string(rows.size()) + " meshes cull little or nothing"), std::string::npos);
    const size_t at = dom.find("id=\"plot-granularity\"");
    ASSERT_NE(at, std::string::npos);
    const std::string plot = dom.substr(at, dom.find("</figure>", at) - at);
    EXPECT_EQ(occurrences(plot, std::regex("<circle class=\"point\"")), 8u);
    EXPECT_NE(plot.find(">4 compact<"), std::string::npos);
    EXPECT_NE(plot.find(">per triangle<"), std::string::npos);
    // --lod: a bar per level some mesh has, and the cut's.
    size_t levels = 0;
    for (const auto& row : rows) levels = std::max<size_t>(levels, std::stoul(row.at("lod_levels")));
    const size_t lodAt = dom.find("id=\"plot-lod\"");
    ASSERT_NE(lodAt, std::string::npos);
    const std::string lod = dom.substr(lodAt, dom.find("</figure>", lodAt) - lodAt);
    EXPECT_EQ(occurrences(lod, std::regex("<rect class=\"bar culled\"")), std::min<size_t>(levels, 8) + 1);
    EXPECT_NE(lod.find(">the cut at 1 px<"), std::string::npos);
}

}  // namespace
}  // namespace conescope
