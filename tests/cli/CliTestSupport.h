// Running the built conescope-cli from tests: its path comes from the build, and every run's
// exit code, stdout and stderr are captured through files in a scratch directory.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ScratchDirectory.h"

namespace conescope::clitest {

std::filesystem::path datasetsDir();
std::string dataset(const std::string& name);  // full path of datasets/<name>

using testing::ScratchDirectory;  // ScratchDirectory.h

struct CliRun {
    int exitCode = -1;
    std::string out;
    std::string err;
};

// Runs conescope-cli with these arguments (each passed as one word, no shell expansion), and these
// environment variables ("NAME=value") set besides the test's own.
CliRun runCli(const std::vector<std::string>& arguments, const std::vector<std::string>& environment = {});
// The same for another program of the build.
CliRun runProgram(const std::string& path, const std::vector<std::string>& arguments, const std::vector<std::string>& environment = {});

// conescope-cli started as runCli starts it, its stdout and stderr going to the files `out` and `err`;
// returns its pid, so a test can signal it midway. waitCli: its exit code, or 128 + the signal.
pid_t startCli(const std::vector<std::string>& arguments, const std::vector<std::string>& environment,
               const std::string& out, const std::string& err);
pid_t startProgram(const std::string& path, const std::vector<std::string>& arguments, const std::vector<std::string>& environment,
                   const std::string& out, const std::string& err);
int waitCli(pid_t pid);

std::string readTextFile(const std::string& path);

// `conescope-cli COMMAND --quiet ARGUMENTS` parsed as JSON (a test failure when it is not, or when
// it exits with an error or writes to stderr).
nlohmann::json runJsonCommand(const std::string& command, const std::vector<std::string>& arguments);
// runJsonCommand("stats", ARGUMENTS).
nlohmann::json runStatsJson(const std::vector<std::string>& arguments);
// runJsonCommand(COMMAND, "--format json" ARGUMENTS): for the commands whose default format is text.
nlohmann::json runJsonFormat(const std::string& command, const std::vector<std::string>& arguments);
// The row of this record in a `granularity` report, or null when it has none.
const nlohmann::json* granularityRow(const nlohmann::json& report, const std::string& record);

// The arguments `first` with `then` after them.
std::vector<std::string> withArguments(std::vector<std::string> first, const std::vector<std::string>& then);

// Timings differ between any two runs; everything else is deterministic: drops every ns_per_cluster.
void removeTimings(nlohmann::json& json);

// Lines of a text, without the newlines.
std::vector<std::string> splitLines(const std::string& text);

}  // namespace conescope::clitest
