// conescope-cli batch-worker: the process a batch runs its meshes in (WorkerPool.h). A job is three
// fields, each ending in a NUL byte: the mesh's path, where its statistics JSON goes and where its
// comparison JSON goes (empty: none). The reply is one line: the row's cells as a JSON object.
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/Batch.h"
#include "cli/BatchJob.h"

namespace conescope::cli {

namespace {

// For tests only: CONESCOPE_BATCH_TEST_FAULT=KIND:NAME makes a worker misbehave on the mesh whose file
// is named NAME, after reading it, where its run would be: `crash` (SIGSEGV), `allocate` (64 MiB
// blocks, each written, until the allocator refuses), `hang` (sleeps until stopped). Read in the
// worker command only, so no other command changes with it.
struct TestFault {
    std::string kind, name;
};

TestFault testFaultFromEnvironment() {
    const char* text = std::getenv("CONESCOPE_BATCH_TEST_FAULT");
    if (!text) return {};
    const std::string value = text;
    const size_t colon = value.find(':');
    if (colon == std::string::npos) return {};
    return {value.substr(0, colon), value.substr(colon + 1)};
}

void misbehave(const std::string& kind) {
    if (kind == "crash") std::raise(SIGSEGV);
    if (kind == "hang")
        for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
    if (kind == "allocate") {
        constexpr size_t block = size_t(64) << 20;
        std::vector<std::unique_ptr<char[]>> blocks;
        for (;;) {
            blocks.emplace_back(new char[block]);
            std::memset(blocks.back().get(), 1, block);
        }
    }
}

// One NUL-terminated field; false at the end of the input.
bool readField(std::string& field) { return bool(std::getline(std::cin, field, '\0')); }

void writeAll(int fd, const std::string& text) {
    for (size_t written = 0; written < text.size();) {
        const ssize_t count = ::write(fd, text.data() + written, text.size() - written);
        if (count < 0 && errno == EINTR) continue;
        if (count <= 0) std::exit(1);  // the supervisor is gone
        written += size_t(count);
    }
}

}  // namespace

int runBatchWorker(const BatchWorkerOptions& options) {
    const BatchConfig config = batchConfig(options.run.toSettings(), options.compare, options.detail, options.granularity, options.lod);
    // Replies have a descriptor of their own; whatever a library prints to stdout goes to stderr.
    const int replies = ::dup(STDOUT_FILENO);
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    const TestFault fault = testFaultFromEnvironment();
    BatchJob job;
    while (readField(job.path) && readField(job.json) && readField(job.compareJson)) {
        const bool faulty = !fault.kind.empty() && std::filesystem::path(job.path).filename() == fault.name;
        const std::function<void()> testFault = [&] { misbehave(fault.kind); };
        BatchRow row = runBatchJob(config, job, faulty ? testFault : std::function<void()>());
        if (row["error_kind"] == "memory" && options.memoryLimitMiB > 0)
            row["error"] += " (the worker's memory limit is " + std::to_string(options.memoryLimitMiB) + " MiB: --memory-limit)";
        writeAll(replies, nlohmann::json(row).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    return 0;
}

}  // namespace conescope::cli
