// A batch's progress on a terminal: one line on stderr, rewritten at most a few times a second, with
// the meshes done, the errors, the meshes skipped and an ETA from the bytes done so far (a mesh's
// time grows with its size). Silent when stderr is no terminal or the batch is quiet.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace conescope::cli {

class BatchProgress {
public:
    BatchProgress(size_t meshes, size_t skipped, uintmax_t bytes, bool quiet);
    ~BatchProgress();
    // A mesh finished (ok or not) with this many bytes.
    void finished(uintmax_t bytes, bool ok, const std::string& name);
    // Redraws when due; `force` redraws now.
    void draw(bool force = false);
    // Clears the line, so what follows starts on a clean one.
    void clear();

private:
    bool shown_;
    size_t meshes_, skipped_, done_ = 0, errors_ = 0;
    uintmax_t bytes_, bytesDone_ = 0;
    std::string last_;
    std::chrono::steady_clock::time_point start_, drawn_;
    bool drawnOnce_ = false;
};

// "42 s", "3 min 05 s", "2 h 10 min": a duration for people.
std::string durationText(double seconds);

}  // namespace conescope::cli
