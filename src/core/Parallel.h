#pragma once

// Running independent pieces of work on all cores. Callers split work so that the result does not
// depend on the number of threads; these helpers only decide how many run at once.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <future>
#include <thread>
#include <vector>

namespace conescope {

// Threads worth starting for `tasks` independent tasks: one per core, at most one per task.
inline size_t threadsFor(size_t tasks) {
    return std::max<size_t>(1, std::min<size_t>(tasks, std::max(1u, std::thread::hardware_concurrency())));
}

// Calls task(i, worker) for every i in [0, count), on threadsFor(count) threads that each take
// the next unclaimed index, and waits for all of them; `worker` (below threadsFor(count)) names
// the thread, for scratch memory kept from task to task. Rethrows what a task threw.
template <typename Task>
void forEachInParallel(size_t count, Task task) {
    std::atomic<size_t> next{0};
    auto work = [&](size_t worker) {
        for (size_t i; (i = next++) < count;) task(i, worker);
    };
    std::vector<std::future<void>> helpers;
    for (size_t worker = 1; worker < threadsFor(count); ++worker) helpers.push_back(std::async(std::launch::async, work, worker));
    work(0);
    for (std::future<void>& helper : helpers) helper.get();
}

// [0, count) cut into `pieces` consecutive ranges of near-equal size: piece i is [begin, end).
inline size_t pieceBegin(size_t count, size_t pieces, size_t i) { return count * i / pieces; }

// Pieces for a loop of `count` cheap items: one per core, none smaller than `grain` items.
inline size_t piecesFor(size_t count, size_t grain) { return threadsFor(std::max<size_t>(1, count / std::max<size_t>(1, grain))); }

// Calls body(begin, end) on consecutive ranges covering [0, count), one per core when the loop
// is long enough to pay for the threads.
template <typename Body>
void forRangesInParallel(size_t count, size_t grain, Body body) {
    const size_t pieces = piecesFor(count, grain);
    forEachInParallel(pieces, [&](size_t i, size_t) { body(pieceBegin(count, pieces, i), pieceBegin(count, pieces, i + 1)); });
}

}  // namespace conescope
