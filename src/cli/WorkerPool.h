// Worker processes that each run one job at a time, supervised so that a worker that crashes, runs
// out of memory or hangs costs only the job it had: its death or its timeout becomes that job's
// result, and the next job starts a new worker. Jobs and replies are single lines over pipes; each
// worker runs in its own process group (a terminal's Ctrl-C reaches only the supervisor), dies with
// its supervisor (PR_SET_PDEATHSIG), writes no core files and has its data segment limited
// (RLIMIT_DATA: the heap and private mappings), so runaway allocation fails inside it.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <sys/types.h>
#include <vector>

namespace conescope::cli {

class WorkerPool {
public:
    struct Limits {
        size_t memoryBytes = 0;      // each worker's RLIMIT_DATA; 0 = none
        double timeoutSeconds = 0;   // each job's; 0 = none
    };
    // What became of a job: a reply (one line), or the worker's end.
    struct Result {
        size_t job = 0;
        bool replied = false;
        std::string reply;
        std::string failureKind;     // "crash" or "timeout"
        std::string failure;         // a sentence for the job's error row
    };

    // `command` is run (execv) for every worker: its first word is the program.
    WorkerPool(std::vector<std::string> command, size_t workers, Limits limits);
    ~WorkerPool();                   // kills and reaps every worker
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    bool canTake() const;            // fewer jobs running than workers allowed
    size_t running() const;
    // Hands `request` (bytes, sent as they are) to an idle worker, starting one when none is idle.
    // Throws std::runtime_error when no worker can be started.
    void submit(size_t job, const std::string& request);
    // Results that came within `milliseconds` (fewer when a signal arrives: the caller checks its flags).
    std::vector<Result> wait(int milliseconds);

private:
    struct Worker {
        pid_t pid = -1;
        int input = -1, output = -1, errors = -1;
        std::string replyBuffer, errorTail;
        bool busy = false;
        size_t job = 0;
        std::chrono::steady_clock::time_point started;
    };
    Worker start();
    void readErrors(Worker& worker);
    Result ended(Worker& worker, int status, bool timedOut);
    void reap(Worker& worker, int signal);
    int pollTimeout(int milliseconds) const;

    std::vector<std::string> command_;
    size_t capacity_;
    Limits limits_;
    std::vector<Worker> workers_;
};

// "signal 11 (Segmentation fault)", "exit code 3": how a process ended, for people.
std::string describeExit(int status);

}  // namespace conescope::cli
