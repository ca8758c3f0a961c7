// Progress reports and cancellation for long work.
#pragma once

#include <exception>
#include <functional>
#include <string>

namespace conescope {

// Progress in [0, 1]; returning false cancels (the function then throws OperationCancelled).
using ProgressCallback = std::function<bool(double fraction, const std::string& stage)>;
struct OperationCancelled : std::exception {
    const char* what() const noexcept override { return "operation cancelled"; }
};

// Reports progress; false from the callback cancels (throws OperationCancelled).
inline void reportProgress(const ProgressCallback& progress, double fraction, const std::string& stage) {
    if (progress && !progress(fraction, stage)) throw OperationCancelled();
}

// Reports `fraction` of [0, 1] as the same point of [begin, end] of the caller's progress, so a
// step can report within its share of a longer run; under the caller's `stage` name when one is
// given, else the step's own. Empty when `progress` is.
inline ProgressCallback progressWithin(const ProgressCallback& progress, double begin, double end,
                                       const std::string& stage = {}) {
    if (!progress) return {};
    return [progress, begin, end, stage](double fraction, const std::string& stepStage) {
        return progress(begin + (end - begin) * fraction, stage.empty() ? stepStage : stage);
    };
}

}  // namespace conescope
