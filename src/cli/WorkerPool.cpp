#include "cli/WorkerPool.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace conescope::cli {

namespace {

constexpr size_t kErrorTailBytes = 4096;
constexpr int kExecFailed = 127;

void closeQuietly(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
}

// In the child between fork and exec: only async-signal-safe calls.
[[noreturn]] void becomeWorker(const std::vector<char*>& argv, pid_t supervisor, int input, int output, int errors,
                               size_t memoryBytes) {
    ::dup2(input, STDIN_FILENO);
    ::dup2(output, STDOUT_FILENO);
    ::dup2(errors, STDERR_FILENO);
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != supervisor) ::_exit(1);  // the supervisor died before prctl
    const rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);
    if (memoryBytes > 0) {
        const rlimit data{memoryBytes, memoryBytes};
        ::setrlimit(RLIMIT_DATA, &data);
    }
    ::signal(SIGPIPE, SIG_DFL);
    ::execv(argv[0], argv.data());
    ::_exit(kExecFailed);
}

// The last line the worker wrote on stderr: what a crashing library said, if anything.
std::string lastLine(const std::string& text) {
    size_t end = text.find_last_not_of("\n\r ");
    if (end == std::string::npos) return {};
    const size_t start = text.rfind('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1, end + 1 - (start == std::string::npos ? 0 : start + 1));
}

}  // namespace

std::string describeExit(int status) {
    if (WIFSIGNALED(status))
        return "signal " + std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    return "exit code " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

WorkerPool::WorkerPool(std::vector<std::string> command, size_t workers, Limits limits)
    : command_(std::move(command)), capacity_(std::max<size_t>(1, workers)), limits_(limits) {
    // A worker that dies while a job is written to it must not kill the supervisor.
    ::signal(SIGPIPE, SIG_IGN);
}

WorkerPool::~WorkerPool() {
    for (Worker& worker : workers_) reap(worker, SIGKILL);
}

bool WorkerPool::canTake() const { return running() < capacity_; }

size_t WorkerPool::running() const {
    return size_t(std::count_if(workers_.begin(), workers_.end(), [](const Worker& worker) { return worker.busy; }));
}

WorkerPool::Worker WorkerPool::start() {
    int input[2], output[2], errors[2];
    if (::pipe2(input, O_CLOEXEC) != 0 || ::pipe2(output, O_CLOEXEC) != 0 || ::pipe2(errors, O_CLOEXEC) != 0)
        throw std::runtime_error(std::string("cannot start a batch worker: ") + std::strerror(errno));
    std::vector<char*> argv;
    for (const std::string& word : command_) argv.push_back(const_cast<char*>(word.c_str()));
    argv.push_back(nullptr);
    const pid_t supervisor = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("cannot start a batch worker: ") + std::strerror(errno));
    if (pid == 0) becomeWorker(argv, supervisor, input[0], output[1], errors[1], limits_.memoryBytes);
    ::close(input[0]);
    ::close(output[1]);
    ::close(errors[1]);
    ::fcntl(output[0], F_SETFL, O_NONBLOCK);
    ::fcntl(errors[0], F_SETFL, O_NONBLOCK);
    Worker worker;
    worker.pid = pid;
    worker.input = input[1];
    worker.output = output[0];
    worker.errors = errors[0];
    return worker;
}

void WorkerPool::submit(size_t job, const std::string& request) {
    auto idle = std::find_if(workers_.begin(), workers_.end(), [](const Worker& worker) { return !worker.busy; });
    if (idle == workers_.end()) {
        workers_.push_back(start());
        idle = workers_.end() - 1;
    }
    idle->busy = true;
    idle->job = job;
    idle->started = std::chrono::steady_clock::now();
    // A write to a worker that died fails (EPIPE); its end is then seen by wait() as for any death.
    for (size_t written = 0; written < request.size();) {
        const ssize_t count = ::write(idle->input, request.data() + written, request.size() - written);
        if (count < 0 && errno == EINTR) continue;
        if (count <= 0) break;
        written += size_t(count);
    }
}

void WorkerPool::readErrors(Worker& worker) {
    char buffer[4096];
    for (ssize_t count; (count = ::read(worker.errors, buffer, sizeof buffer)) > 0;) {
        worker.errorTail.append(buffer, size_t(count));
        if (worker.errorTail.size() > kErrorTailBytes) worker.errorTail.erase(0, worker.errorTail.size() - kErrorTailBytes);
    }
}

void WorkerPool::reap(Worker& worker, int signal) {
    closeQuietly(worker.input);
    if (worker.pid > 0) {  // never kill(-1): that would be every process of the user
        if (signal != 0) ::kill(worker.pid, signal);
        int status = 0;
        while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
    worker.pid = -1;
    closeQuietly(worker.output);
    closeQuietly(worker.errors);
}

WorkerPool::Result WorkerPool::ended(Worker& worker, int status, bool timedOut) {
    Result result;
    result.job = worker.job;
    if (timedOut) {
        result.failureKind = "timeout";
        result.failure = "took longer than " + std::to_string(int(limits_.timeoutSeconds + 0.5)) +
                         " s (--timeout); its worker was stopped";
        return result;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == kExecFailed)
        throw std::runtime_error("cannot start a batch worker (" + command_.front() + ")");
    result.failureKind = "crash";
    result.failure = "the worker running it ended with " + describeExit(status);
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        result.failure += ", sent by the system (its out-of-memory killer) or a user";
    const std::string said = lastLine(worker.errorTail);
    if (!said.empty()) result.failure += "; it said: " + said;
    return result;
}

int WorkerPool::pollTimeout(int milliseconds) const {
    if (limits_.timeoutSeconds <= 0) return milliseconds;
    const auto now = std::chrono::steady_clock::now();
    for (const Worker& worker : workers_) {
        if (!worker.busy) continue;
        const double left = limits_.timeoutSeconds - std::chrono::duration<double>(now - worker.started).count();
        milliseconds = std::min(milliseconds, std::max(0, int(left * 1000.0) + 1));
    }
    return milliseconds;
}

std::vector<WorkerPool::Result> WorkerPool::wait(int milliseconds) {
    std::vector<pollfd> fds;
    for (const Worker& worker : workers_) {
        fds.push_back({worker.output, POLLIN, 0});
        fds.push_back({worker.errors, POLLIN, 0});
    }
    std::vector<Result> results;
    if (::poll(fds.data(), fds.size(), pollTimeout(milliseconds)) < 0) return results;  // a signal
    std::vector<size_t> gone;
    const auto now = std::chrono::steady_clock::now();
    for (size_t k = 0; k < workers_.size(); ++k) {
        Worker& worker = workers_[k];
        readErrors(worker);
        char buffer[65536];
        ssize_t count = 0;
        while ((count = ::read(worker.output, buffer, sizeof buffer)) > 0) worker.replyBuffer.append(buffer, size_t(count));
        for (size_t end; worker.busy && (end = worker.replyBuffer.find('\n')) != std::string::npos;) {
            results.push_back({worker.job, true, worker.replyBuffer.substr(0, end), "", ""});
            worker.replyBuffer.erase(0, end + 1);
            worker.busy = false;
        }
        const bool closed = count == 0;  // the worker's end: it exited or was killed
        const bool late = worker.busy && limits_.timeoutSeconds > 0 &&
                          std::chrono::duration<double>(now - worker.started).count() > limits_.timeoutSeconds;
        if (!closed && !late) continue;
        if (late) ::kill(worker.pid, SIGKILL);
        int status = 0;
        while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
        }
        worker.pid = -1;
        readErrors(worker);
        gone.push_back(k);
        if (worker.busy) results.push_back(ended(worker, status, late));
        reap(worker, 0);
    }
    for (auto k = gone.rbegin(); k != gone.rend(); ++k) workers_.erase(workers_.begin() + long(*k));
    return results;
}

}  // namespace conescope::cli
