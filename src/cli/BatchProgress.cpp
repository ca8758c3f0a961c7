#include "cli/BatchProgress.h"

#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace conescope::cli {

std::string durationText(double seconds) {
    const long total = long(seconds + 0.5);
    char text[32];
    if (total < 60)
        std::snprintf(text, sizeof text, "%ld s", total);
    else if (total < 3600)
        std::snprintf(text, sizeof text, "%ld min %02ld s", total / 60, total % 60);
    else
        std::snprintf(text, sizeof text, "%ld h %02ld min", total / 3600, total % 3600 / 60);
    return text;
}

BatchProgress::BatchProgress(size_t meshes, size_t skipped, uintmax_t bytes, bool quiet)
    : shown_(!quiet && ::isatty(STDERR_FILENO)), meshes_(meshes), skipped_(skipped), bytes_(bytes),
      start_(std::chrono::steady_clock::now()), drawn_(start_) {}

BatchProgress::~BatchProgress() { clear(); }

void BatchProgress::finished(uintmax_t bytes, bool ok, const std::string& name) {
    ++done_;
    errors_ += ok ? 0 : 1;
    bytesDone_ += bytes;
    last_ = name;
}

void BatchProgress::draw(bool force) {
    if (!shown_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && drawnOnce_ && now - drawn_ < std::chrono::milliseconds(200)) return;
    drawn_ = now;
    drawnOnce_ = true;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::string eta = "ETA --";
    if (bytesDone_ > 0 && bytes_ > bytesDone_)
        eta = "ETA " + durationText(elapsed * double(bytes_ - bytesDone_) / double(bytesDone_));
    else if (done_ == meshes_)
        eta = "done";
    std::string line = std::to_string(done_) + "/" + std::to_string(meshes_) + " meshes (" +
                       std::to_string(meshes_ ? done_ * 100 / meshes_ : 100) + "%), " + std::to_string(errors_) + " errors, " +
                       std::to_string(skipped_) + " skipped, " + durationText(elapsed) + ", " + eta;
    if (!last_.empty()) line += " | " + last_;
    if (line.size() > 118) line = line.substr(0, 115) + "...";
    std::cerr << "\r\033[K" << line << std::flush;
}

void BatchProgress::clear() {
    if (shown_ && drawnOnce_) std::cerr << "\r\033[K" << std::flush;
    drawnOnce_ = false;
}

}  // namespace conescope::cli
