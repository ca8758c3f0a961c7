#include "CliTestSupport.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace conescope::clitest {

std::filesystem::path datasetsDir() { return CONESCOPE_DATASETS_DIR; }

std::string dataset(const std::string& name) { return (datasetsDir() / name).string(); }

std::string readTextFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// fork + exec rather than system(): the arguments reach the program exactly as given.
pid_t startCli(const std::vector<std::string>& arguments, const std::vector<std::string>& environment,
               const std::string& outPath, const std::string& errPath) {
    return startProgram(CONESCOPE_CLI_PATH, arguments, environment, outPath, errPath);
}

pid_t startProgram(const std::string& path, const std::vector<std::string>& arguments, const std::vector<std::string>& environment,
                   const std::string& outPath, const std::string& errPath) {
    const pid_t child = ::fork();
    if (child < 0) throw std::runtime_error("fork failed");
    if (child == 0) {
        const int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out < 0 || err < 0) ::_exit(126);
        ::dup2(out, STDOUT_FILENO);
        ::dup2(err, STDERR_FILENO);
        for (const std::string& variable : environment) {
            const size_t equals = variable.find('=');
            ::setenv(variable.substr(0, equals).c_str(), variable.substr(equals + 1).c_str(), 1);
        }
        std::vector<char*> argv;
        std::string program = path;
        argv.push_back(program.data());
        std::vector<std::string> copies = arguments;
        for (std::string& argument : copies) argv.push_back(argument.data());
        argv.push_back(nullptr);
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
    return child;
}

int waitCli(pid_t pid) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

CliRun runCli(const std::vector<std::string>& arguments, const std::vector<std::string>& environment) {
    return runProgram(CONESCOPE_CLI_PATH, arguments, environment);
}

CliRun runProgram(const std::string& path, const std::vector<std::string>& arguments, const std::vector<std::string>& environment) {
    ScratchDirectory capture;
    const std::string outPath = capture.file("stdout"), errPath = capture.file("stderr");
    CliRun run;
    run.exitCode = waitCli(startProgram(path, arguments, environment, outPath, errPath));
    run.out = readTextFile(outPath);
    run.err = readTextFile(errPath);
    return run;
}

nlohmann::json runStatsJson(const std::vector<std::string>& arguments) { return runJsonCommand("stats", arguments); }

nlohmann::json runJsonFormat(const std::string& command, const std::vector<std::string>& arguments) {
    return runJsonCommand(command, withArguments({"--format", "json"}, arguments));
}

const nlohmann::json* granularityRow(const nlohmann::json& report, const std::string& record) {
    const nlohmann::json* found = nullptr;
    for (const nlohmann::json& row : report["rows"])
        if (row["record"] == record) found = &row;
    return found;
}

std::vector<std::string> withArguments(std::vector<std::string> first, const std::vector<std::string>& then) {
    first.insert(first.end(), then.begin(), then.end());
    return first;
}

nlohmann::json runJsonCommand(const std::string& name, const std::vector<std::string>& arguments) {
    std::vector<std::string> command = {name, "--quiet"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    const CliRun run = runCli(command);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    try {
        return nlohmann::json::parse(run.out);
    } catch (const nlohmann::json::parse_error& error) {
        ADD_FAILURE() << "stdout is not JSON: " << error.what() << "\n" << run.out.substr(0, 500);
        return {};
    }
}

// Timings differ between any two runs; everything else is deterministic.
void removeTimings(nlohmann::json& json) {
    if (json.is_object()) {
        json.erase("ns_per_cluster");
        for (auto& [key, value] : json.items()) removeTimings(value);
    } else if (json.is_array()) {
        for (nlohmann::json& value : json) removeTimings(value);
    }
}

}  // namespace conescope::clitest
