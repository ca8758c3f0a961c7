// conescope-cli batch-worker: the process a batch runs its meshes in (WorkerPool.h). A job is three
// fields, each ending in a NUL byte: the mesh's path, where its statistics JSON goes and where its
// comparison JSON goes (empty: none). The reply is one line: the row's cells as a JSON object.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/Batch.h"
#include "batch/BatchJob.h"

namespace conescope::cli {

namespace {

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
    BatchJob job;
    while (readField(job.path) && readField(job.json) && readField(job.compareJson)) {
        BatchRow row = runBatchJob(config, job, testFaultFor(job.path));
        if (row["error_kind"] == "memory" && options.memoryLimitMiB > 0)
            row["error"] += " (the worker's memory limit is " + std::to_string(options.memoryLimitMiB) + " MiB: --memory-limit)";
        writeAll(replies, nlohmann::json(row).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    return 0;
}

}  // namespace conescope::cli
