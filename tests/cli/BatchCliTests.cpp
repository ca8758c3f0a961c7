// conescope-cli batch end to end: a library of 16 meshes (one broken, three polygon OBJ files in a
// subfolder) gives 16 rows whose numbers are `stats`'s; a second run skips every mesh; a worker that
// crashes, allocates without bound or hangs costs only its mesh; Ctrl-C leaves whole rows and the same
// command resumes.
#include <gtest/gtest.h>

#include <algorithm>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "BatchTestSupport.h"
#include "CliTestSupport.h"

namespace conescope {
namespace {

namespace fs = std::filesystem;
using clitest::CliRun;
using clitest::dataset;
using clitest::readResults;
using clitest::readTextFile;
using clitest::removeTimings;
using clitest::runCli;
using clitest::runStatsJson;
using clitest::ScratchDirectory;
using Row = std::map<std::string, std::string>;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

struct TimedRun {
    CliRun run;
    double seconds = 0;
};

TimedRun runBatch(const std::vector<std::string>& arguments, const std::vector<std::string>& environment = {}) {
    std::vector<std::string> command = {"batch"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const auto start = std::chrono::steady_clock::now();
    TimedRun timed{runCli(command, environment), 0};
    timed.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return timed;
}

const Row& rowEndingIn(const std::vector<Row>& rows, const std::string& end) {
    for (const Row& row : rows)
        if (row.at("file").size() >= end.size() && row.at("file").compare(row.at("file").size() - end.size(), end.size(), end) == 0)
            return row;
    throw std::runtime_error("no row for " + end);
}

// The row's numbers are the document's: every scalar of the displayed result (but its timing), the
// counts of the run and of the mesh.
void expectRowEqualsDocument(const Row& row, const nlohmann::json& document) {
    const nlohmann::json& result = document["results"][0];
    for (const auto& [key, value] : result.items()) {
        if (key == "ns_per_cluster" || value.is_array() || value.is_object()) continue;
        ASSERT_TRUE(row.count(key)) << key;
        if (value.is_string())
            EXPECT_EQ(row.at(key), value.get<std::string>()) << key;
        else if (value.is_boolean())  // CSV writes booleans as 1 and 0
            EXPECT_EQ(row.at(key), value.get<bool>() ? "1" : "0") << row.at("file") << ": " << key;
        else
            EXPECT_EQ(std::stod(row.at(key)), value.get<double>()) << row.at("file") << ": " << key;
    }
    EXPECT_EQ(row.at("triangles"), document["mesh"]["triangles"].dump());
    EXPECT_EQ(row.at("faces"), document["mesh"]["faces"].dump());
    EXPECT_EQ(row.at("clusters"), document["clusters"].dump());
    EXPECT_EQ(row.at("views"), document["view_count"].dump());
}

void expectSameDocument(nlohmann::json actual, nlohmann::json expected) {
    removeTimings(actual);
    removeTimings(expected);
    const nlohmann::json differences = nlohmann::json::diff(expected, actual);
    EXPECT_TRUE(differences.empty()) << differences.dump().substr(0, 1500);
}

// The message `stats` prints for a file it cannot read.
std::string statsError(const std::string& mesh) {
    const CliRun run = runCli({"stats", "--quiet", mesh});
    const std::string prefix = "conescope-cli: error: ";
    EXPECT_EQ(run.exitCode, 1);
    const size_t at = run.err.find(prefix);
    return at == std::string::npos ? run.err : run.err.substr(at + prefix.size(), run.err.find('\n', at) - at - prefix.size());
}

TEST(CliBatch, SixteenMeshesGiveSixteenRowsEqualToStats) {
    ScratchDirectory scratch;
    const std::vector<std::string> files = clitest::makeMeshLibrary(scratch.path() / "library");
    ASSERT_EQ(files.size(), 16u);
    const std::string out = scratch.file("out");
    const TimedRun batch = runBatch({scratch.file("library"), "-o", out, "--views", "16", "--jobs", "2"});
    EXPECT_EQ(batch.run.exitCode, 3) << batch.run.err;  // finished, one error row
    const std::vector<Row> rows = readResults(out + "/results.csv");
    ASSERT_EQ(rows.size(), 16u);
    std::set<std::string> named, jsons;
    for (const Row& row : rows) {
        named.insert(row.at("file"));
        jsons.insert(row.at("json"));
        if (row.at("file").find("broken.off") != std::string::npos) {
            EXPECT_EQ(row.at("status"), "error");
            EXPECT_EQ(row.at("error_kind"), "read");
            EXPECT_EQ(row.at("error"), statsError(row.at("file")));
            continue;
        }
        ASSERT_EQ(row.at("status"), "ok") << row.at("file") << ": " << row.at("error");
        const nlohmann::json stats = runStatsJson({row.at("file"), "--views", "16"});
        expectSameDocument(nlohmann::json::parse(readTextFile(out + "/" + row.at("json"))), stats);
        expectRowEqualsDocument(row, stats);
        EXPECT_EQ(row.at("setting_views"), "16");
    }
    EXPECT_EQ(named, std::set<std::string>(files.begin(), files.end()));
    EXPECT_EQ(jsons.size(), 16u);  // torus.off twice, in two folders: two files
    for (const char* polygons : {"quad-sphere.obj", "dodecahedron.obj", "hexagon-tube.obj"}) {
        const Row& row = rowEndingIn(rows, std::string("polygons/") + polygons);
        EXPECT_LT(std::stoul(row.at("faces")), std::stoul(row.at("triangles"))) << polygons;
        EXPECT_EQ(row.at("warnings"), "") << polygons;  // consistently wound, outward
    }
    std::cout << "first batch of 16 meshes: " << batch.seconds << " s" << std::endl;
}

// A mesh whose clusters can never be culled gets a note and its share; one that culls, neither.
TEST(CliBatch, MostlyUncullableMeshesAreNoted) {
    ScratchDirectory scratch;
    const std::string out = scratch.file("out");
    const TimedRun batch = runBatch({dataset("cube.off"), dataset("torus.off"), "-o", out, "--views", "4", "--jobs", "1"});
    ASSERT_EQ(batch.run.exitCode, 0) << batch.run.err;
    const std::vector<Row> rows = readResults(out + "/results.csv");
    const Row& cube = rowEndingIn(rows, "cube.off");
    const Row& torus = rowEndingIn(rows, "torus.off");
    EXPECT_NE(cube.at("note").find("can never be culled"), std::string::npos) << cube.at("note");
    EXPECT_EQ(std::stod(cube.at("uncullable_share")), 1.0);
    EXPECT_EQ(torus.at("note"), "");
    EXPECT_LT(std::stod(torus.at("uncullable_share")), 0.5);
    EXPECT_NE(readTextFile(out + "/report.html").find("uncullable-note"), std::string::npos);
}

// --granularity and --lod add their columns: level 0 and the one-cone record are the row's own
// (stats') numbers, the finer records and the levels are `granularity`'s and `lod`'s; without them
// the columns stay empty, and a comparison refuses them.
TEST(CliBatch, GranularityAndLodColumnsAreTheirCommandsNumbers) {
    ScratchDirectory scratch;
    const std::string out = scratch.file("out");
    const TimedRun batch = runBatch({dataset("elephant.off"), dataset("torus.off"), "-o", out, "--views", "8", "--granularity", "--lod"});
    ASSERT_EQ(batch.run.exitCode, 0) << batch.run.err;
    for (const Row& row : readResults(out + "/results.csv")) {
        EXPECT_EQ(std::stod(row.at("lod_level_0_efficiency")), std::stod(row.at("efficiency"))) << row.at("file");
        EXPECT_EQ(row.at("lod_false_culls"), "0");
        const nlohmann::json lod = clitest::runJsonCommand("lod", {row.at("file"), "--views", "8", "--format", "json", "--no-per-view"});
        EXPECT_EQ(std::stoul(row.at("lod_levels")), lod["levels"].size());
        EXPECT_EQ(std::stod(row.at("lod_cut_efficiency")), lod["cut"]["efficiency"].get<double>());
        EXPECT_EQ(std::stod(row.at("lod_level_1_efficiency")), lod["levels"][1]["efficiency"].get<double>());
        const nlohmann::json granularity = clitest::runJsonCommand("granularity", {row.at("file"), "--views", "8", "--test", "octagon", "--format", "json"});
        for (const nlohmann::json& record : granularity["rows"]) {
            std::string prefix = record["record"];
            if (prefix.rfind("cones-", 0) != 0 && prefix != "triangle") continue;
            std::replace(prefix.begin(), prefix.end(), '-', '_');
            EXPECT_EQ(std::stod(row.at(prefix + "_culled_share")), record["culled_share"].get<double>()) << prefix;
            EXPECT_EQ(std::stoul(row.at(prefix + "_bytes_per_cluster")), record["bytes_per_cluster"].get<size_t>()) << prefix;
        }
    }
    const std::string plain = scratch.file("plain");
    ASSERT_EQ(runBatch({dataset("torus.off"), "-o", plain, "--views", "4"}).run.exitCode, 0);
    EXPECT_EQ(readResults(plain + "/results.csv").front().at("lod_levels"), "");
    EXPECT_EQ(runBatch({dataset("torus.off"), "-o", scratch.file("refused"), "--lod", "--compare-meshopt"}).run.exitCode, 2);
}

TEST(CliBatch, ASecondRunSkipsEveryMeshAndRunsAChangedOneAgain) {
    ScratchDirectory scratch;
    clitest::makeMeshLibrary(scratch.path() / "library");
    const std::string out = scratch.file("out"), library = scratch.file("library");
    const TimedRun first = runBatch({library, "-o", out, "--views", "16"});
    ASSERT_EQ(first.run.exitCode, 3) << first.run.err;
    const std::string csv = readTextFile(out + "/results.csv");
    std::map<std::string, fs::file_time_type> written;
    for (const auto& entry : fs::directory_iterator(out + "/meshes")) written[entry.path().string()] = entry.last_write_time();

    const TimedRun second = runBatch({library, "-o", out, "--views", "16"});
    EXPECT_EQ(second.run.exitCode, 3);
    EXPECT_NE(second.run.err.find("16 meshes, 16 skipped"), std::string::npos) << second.run.err;
    EXPECT_EQ(readTextFile(out + "/results.csv"), csv);
    for (const auto& [path, time] : written) EXPECT_EQ(fs::last_write_time(path), time) << path;
    std::cout << "first run " << first.seconds << " s, second run " << second.seconds << " s" << std::endl;

    // Other bytes: that mesh alone runs again.
    std::ofstream(library + "/polygons/dodecahedron.obj", std::ios::app) << "# changed\n";
    const TimedRun changed = runBatch({library, "-o", out, "--views", "16"});
    EXPECT_NE(changed.run.err.find("16 meshes, 15 skipped"), std::string::npos) << changed.run.err;
    const std::vector<Row> rows = readResults(out + "/results.csv");
    ASSERT_EQ(rows.size(), 16u);
    EXPECT_EQ(rowEndingIn(rows, "dodecahedron.obj").at("status"), "ok");

    // Other settings: every mesh runs again.
    const TimedRun resettled = runBatch({library, "-o", out, "--views", "8"});
    EXPECT_NE(resettled.run.err.find("16 meshes, 0 skipped"), std::string::npos) << resettled.run.err;
    EXPECT_EQ(rowEndingIn(readResults(out + "/results.csv"), "torus.off").at("views"), "8");
}

// Three small meshes in sorted order: cube.off, icosphere.off, torus.off.
std::string threeMeshes(const ScratchDirectory& scratch) {
    for (const char* name : {"cube.off", "icosphere.off", "torus.off"})
        fs::copy_file(dataset(name), scratch.path() / "library" / name, fs::copy_options::overwrite_existing);
    return scratch.file("library");
}

ScratchDirectory& withLibraryFolder(ScratchDirectory& scratch) {
    fs::create_directories(scratch.path() / "library");
    return scratch;
}

// One worker, so the ones after the faulty mesh need a new worker.
std::vector<Row> batchWithFault(const std::string& fault, const std::vector<std::string>& extra, std::string* err = nullptr) {
    ScratchDirectory scratch;
    const std::string library = threeMeshes(withLibraryFolder(scratch)), out = scratch.file("out");
    std::vector<std::string> arguments = {library, "-o", out, "--views", "8", "--jobs", "1"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    const TimedRun batch = runBatch(arguments, {"CONESCOPE_BATCH_TEST_FAULT=" + fault});
    EXPECT_EQ(batch.run.exitCode, 3) << batch.run.err;
    if (err) *err = batch.run.err;
    std::vector<Row> rows = readResults(out + "/results.csv");
    EXPECT_EQ(rows.size(), 3u);
    for (const Row& row : rows)
        if (row.at("file").find("cube.off") == std::string::npos) {
            EXPECT_EQ(row.at("status"), "ok") << row.at("error");
        }
    return rows;
}

TEST(CliBatch, AWorkerThatCrashesIsAnErrorRowAndANewWorkerTakesOver) {
    const Row crashed = rowEndingIn(batchWithFault("crash:cube.off", {}), "cube.off");
    EXPECT_EQ(crashed.at("status"), "error");
    EXPECT_EQ(crashed.at("error_kind"), "crash");
    // AddressSanitizer reports the segmentation fault and aborts instead.
    const std::string signal = kAddressSanitizer ? "ended with signal" : "ended with signal 11 (Segmentation fault)";
    EXPECT_NE(crashed.at("error").find(signal), std::string::npos) << crashed.at("error");
}

TEST(CliBatch, AMeshThatAllocatesWithoutBoundIsAMemoryErrorRow) {
    if (kAddressSanitizer)
        GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no data limit can hold it (the Release run checks this)";
    const Row exhausted = rowEndingIn(batchWithFault("allocate:cube.off", {"--memory-limit", "300"}), "cube.off");
    EXPECT_EQ(exhausted.at("status"), "error");
    EXPECT_EQ(exhausted.at("error_kind"), "memory");
    EXPECT_NE(exhausted.at("error").find("out of memory (the worker's memory limit is 300 MiB"), std::string::npos)
        << exhausted.at("error");
}

TEST(CliBatch, AMeshThatHangsIsStoppedAfterItsTimeout) {
    const Row hung = rowEndingIn(batchWithFault("hang:cube.off", {"--timeout", "1"}), "cube.off");
    EXPECT_EQ(hung.at("error_kind"), "timeout");
    EXPECT_NE(hung.at("error").find("took longer than 1 s"), std::string::npos) << hung.at("error");
}

// Starts a batch whose second mesh hangs, waits for the first row, then sends `signal`.
int stopMidway(const std::string& library, const std::string& out, const ScratchDirectory& scratch, int signal) {
    const pid_t pid = clitest::startCli({"batch", library, "-o", out, "--views", "8", "--jobs", "1"},
                                        {"CONESCOPE_BATCH_TEST_FAULT=hang:icosphere.off"}, scratch.file("stdout"),
                                        scratch.file("stderr"));
    for (int wait = 0; wait < 600; ++wait) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (fs::exists(out + "/results.csv") && readResults(out + "/results.csv").size() == 1) break;
    }
    // A second batch cannot write into the same folder meanwhile.
    const CliRun second = runCli({"batch", library, "-o", out});
    EXPECT_EQ(second.exitCode, 1);
    EXPECT_NE(second.err.find("is in use by another batch"), std::string::npos) << second.err;
    ::kill(pid, signal);
    return clitest::waitCli(pid);
}

void expectWholeRows(const std::string& out, size_t rows) {
    std::vector<std::string> lines;
    const std::string csv = readTextFile(out + "/results.csv");
    EXPECT_EQ(readResults(out + "/results.csv", &lines).size(), rows);
    EXPECT_EQ(csv.back(), '\n');
    for (const auto& entry : fs::directory_iterator(out + "/meshes")) {
        EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << entry.path();
        EXPECT_TRUE(nlohmann::json::accept(readTextFile(entry.path().string()))) << entry.path();
    }
}

TEST(CliBatch, CtrlCLeavesWholeRowsAndTheSameCommandResumes) {
    for (int signal : {SIGINT, SIGTERM, SIGKILL}) {
        ScratchDirectory scratch;
        const std::string library = threeMeshes(withLibraryFolder(scratch)), out = scratch.file("out");
        const int code = stopMidway(library, out, scratch, signal);
        EXPECT_EQ(code, signal == SIGKILL ? 128 + SIGKILL : 130) << readTextFile(scratch.file("stderr"));
        if (signal != SIGKILL) {
            EXPECT_NE(readTextFile(scratch.file("stderr")).find("the same command resumes"), std::string::npos);
            EXPECT_TRUE(fs::exists(out + "/report.html"));
        }
        expectWholeRows(out, 1);
        const TimedRun resumed = runBatch({library, "-o", out, "--views", "8"});
        EXPECT_EQ(resumed.run.exitCode, 0) << resumed.run.err;
        EXPECT_NE(resumed.run.err.find("3 meshes, 1 skipped"), std::string::npos) << resumed.run.err;
        expectWholeRows(out, 3);
    }
}

TEST(CliBatch, ShardsTakeEveryNthMeshOfTheSortedList) {
    ScratchDirectory scratch;
    clitest::copyBundledDatasets(scratch.path() / "library");
    const std::string library = scratch.file("library");
    runBatch({library, "-o", scratch.file("all"), "--views", "4", "--no-per-cluster"});
    std::vector<std::string> all;
    for (const Row& row : readResults(scratch.file("all") + "/results.csv")) all.push_back(row.at("file"));
    ASSERT_EQ(all.size(), 8u);
    for (size_t shard = 1; shard <= 3; ++shard) {
        const std::string out = scratch.file("shard" + std::to_string(shard));
        const TimedRun run = runBatch({library, "-o", out, "--views", "4", "--no-per-cluster", "--shard",
                                       std::to_string(shard) + "/3"});
        EXPECT_EQ(run.run.exitCode, 0) << run.run.err;
        std::vector<std::string> expected, taken;
        for (size_t k = shard - 1; k < all.size(); k += 3) expected.push_back(all[k]);
        for (const Row& row : readResults(out + "/results.csv")) taken.push_back(row.at("file"));
        EXPECT_EQ(taken, expected);
    }
}

TEST(CliBatch, ComparisonColumnsAreCompareTotals) {
    ScratchDirectory scratch;
    const std::string out = scratch.file("out");
    const TimedRun run = runBatch({dataset("elephant.off"), dataset("icosphere.off"), "-o", out, "--views", "8", "--compare-meshopt"});
    ASSERT_EQ(run.run.exitCode, 0) << run.run.err;
    for (const Row& row : readResults(out + "/results.csv")) {
        const CliRun compare = runCli({"compare", "--quiet", "--format", "json", row.at("file"), "--views", "8", "--a",
                                       "builder=meshopt,cone=meshopt,test=apex"});
        const nlohmann::json json = nlohmann::json::parse(compare.out);
        expectSameDocument(nlohmann::json::parse(readTextFile(out + "/" + row.at("compare_json"))), json);
        expectSameDocument(nlohmann::json::parse(readTextFile(out + "/" + row.at("json"))), json["b"]);
        expectRowEqualsDocument(row, json["b"]);
        EXPECT_EQ(row.at("a_options"), "builder=meshopt,cone=meshopt,test=apex");
        EXPECT_EQ(row.at("a_cone"), "meshopt");
        EXPECT_EQ(row.at("a_test"), "apex");
        EXPECT_EQ(std::stod(row.at("a_efficiency")), json["a"]["results"][0]["efficiency"].get<double>());
        EXPECT_EQ(row.at("a_clusters"), json["a"]["clusters"].dump());
        for (const char* key : {"triangles_culled_only_a", "triangles_culled_only_b", "triangles_culled_both"})
            EXPECT_EQ(row.at(key), json["diff"][key].dump()) << key;
    }
}

TEST(CliBatch, BadArgumentsStopTheBatchBeforeAnyMeshRuns) {
    ScratchDirectory scratch;
    const std::string out = scratch.file("out");
    EXPECT_EQ(runBatch({dataset("cube.off"), "-o", out, "--shard", "3/2"}).run.exitCode, 2);
    EXPECT_EQ(runBatch({dataset("cube.off"), "-o", out, "--compare", "colour=red"}).run.exitCode, 2);
}

// Whatever is wrong with a path, given or found, is that path's error row; the other meshes run.
TEST(CliBatch, EveryPathProblemIsAnErrorRowAndTheBatchGoesOn) {
    ScratchDirectory scratch;
    const fs::path library = scratch.path() / "library";
    fs::create_directories(library / "model.obj");
    fs::copy_file(dataset("cube.off"), library / "good.off");
    fs::copy_file(dataset("cube.off"), library / "model.obj" / "inside.off");
    fs::create_symlink("nowhere.obj", library / "gone.obj");
    ASSERT_EQ(::mkfifo((library / "pipe.ply").c_str(), 0644), 0);
    fs::create_symlink(scratch.file("nothing.stl"), scratch.path() / "given-link.stl");
    const std::string out = scratch.file("out");
    const TimedRun batch = runBatch({library.string(), scratch.file("missing.off"), scratch.file("given-link.stl"), "-o", out});
    EXPECT_EQ(batch.run.exitCode, 3) << batch.run.err;
    const std::vector<Row> rows = readResults(out + "/results.csv");
    ASSERT_EQ(rows.size(), 7u) << batch.run.err;
    for (const char* good : {"library/good.off", "model.obj/inside.off"}) EXPECT_EQ(rowEndingIn(rows, good).at("status"), "ok") << good;
    const std::map<std::string, std::string> problems = {
        {"library/gone.obj", "gone.obj: a link to nowhere.obj, which does not exist"},
        {"library/model.obj", "model.obj: a folder named like a mesh file, not a mesh (its meshes are looked for inside it)"},
        {"library/pipe.ply", "pipe.ply: not a regular file (a device, pipe or socket)"},
        {"missing.off", "missing.off: no such file or folder"},
        {"given-link.stl", "given-link.stl: a link to " + scratch.file("nothing.stl") + ", which does not exist"}};
    for (const auto& [file, message] : problems) {
        const Row& row = rowEndingIn(rows, file);
        EXPECT_EQ(row.at("status"), "error") << file;
        EXPECT_EQ(row.at("error_kind"), "read") << file;
        EXPECT_NE(row.at("error").find(message), std::string::npos) << row.at("error");
        EXPECT_NE(batch.run.err.find(message), std::string::npos) << batch.run.err;
    }
}

// A file or folder nobody may read (run as a user other than root; root reads everything).
TEST(CliBatch, UnreadableFilesAndFoldersAreErrorRows) {
    if (::geteuid() == 0) GTEST_SKIP() << "root reads every file: run the tests as another user to check unreadable paths";
    ScratchDirectory scratch;
    const fs::path library = scratch.path() / "library";
    fs::create_directories(library / "closed");
    fs::copy_file(dataset("cube.off"), library / "good.off");
    fs::copy_file(dataset("cube.off"), library / "secret.off");
    fs::copy_file(dataset("cube.off"), library / "closed" / "hidden-inside.off");
    fs::permissions(library / "secret.off", fs::perms::none);
    fs::permissions(library / "closed", fs::perms::none);
    const std::string out = scratch.file("out");
    const TimedRun batch = runBatch({library.string(), "-o", out});
    fs::permissions(library / "closed", fs::perms::owner_all);
    EXPECT_EQ(batch.run.exitCode, 3) << batch.run.err;
    const std::vector<Row> rows = readResults(out + "/results.csv");
    ASSERT_EQ(rows.size(), 3u) << batch.run.err;
    EXPECT_EQ(rowEndingIn(rows, "good.off").at("status"), "ok");
    EXPECT_NE(rowEndingIn(rows, "secret.off").at("error").find("secret.off: cannot open file for reading (Permission denied)"), std::string::npos);
    EXPECT_NE(rowEndingIn(rows, "library/closed").at("error").find("closed: cannot list the folder (Permission denied)"), std::string::npos);
}

// The output folder's problems in the batch's words, not std::filesystem's "filesystem error: ...".
TEST(CliBatch, OutputFolderErrorsSayWhatIsWrong) {
    ScratchDirectory scratch;
    const std::string file = scratch.writeFile("taken.txt", "a file\n");
    fs::create_symlink(scratch.file("nowhere"), scratch.path() / "dangling");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {file, file + ": cannot be the output folder: " + file + " is a file, not a folder"},
        {file + "/out", file + "/out: cannot be the output folder: " + file + " is a file, not a folder"},
        {scratch.file("dangling"), scratch.file("dangling") + ": cannot be the output folder: " + scratch.file("dangling") + " is a link to nothing"},
        {"/proc/conescope-out", "/proc/conescope-out: cannot make the output folder (No such file or directory)"}};
    for (const auto& [folder, message] : cases) {
        const TimedRun batch = runBatch({dataset("cube.off"), "-o", folder});
        EXPECT_EQ(batch.run.exitCode, 1) << folder;
        EXPECT_NE(batch.run.err.find("conescope-cli: error: " + message), std::string::npos) << batch.run.err;
        EXPECT_EQ(batch.run.err.find("filesystem error"), std::string::npos) << batch.run.err;
    }
}

}  // namespace
}  // namespace conescope
