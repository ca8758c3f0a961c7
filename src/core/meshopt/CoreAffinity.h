// Keeping two threads that must run at once on different cores. Linux starts a new thread on its
// creator's core and wakes a waiting thread on the core of the thread that woke it; on a machine of
// two cores the meshlet builder and the optimizer consuming its parts then took turns on one core
// while the other idled, in most fresh processes for part of the run and in about one run in six
// for all of it. Holding each on a core of its own while both have work avoids that; a held
// thread gets back the cores it had when the hold is released. Where thread affinity is not
// available (not Linux, or one core allowed) nothing is held.
#pragma once

#include <bitset>
#include <system_error>
#include <thread>
#include <utility>

namespace conescope {

// A set of cores by number.
using Cores = std::bitset<1024>;

// The calling thread's cores cut in two: the one it runs on now, and the others. Both empty when
// it may use only one core or its cores cannot be read.
struct CoreSplit {
    Cores current, others;
};
CoreSplit splitCores();

// Restricts a thread to `cores` until released (or destroyed); empty cores hold nothing.
class CoreHold {
public:
    CoreHold() = default;
    CoreHold(std::thread::native_handle_type thread, const Cores& cores);
    CoreHold(CoreHold&& other) noexcept;
    CoreHold& operator=(CoreHold&& other) noexcept;
    CoreHold(const CoreHold&) = delete;
    CoreHold& operator=(const CoreHold&) = delete;
    ~CoreHold() { release(); }

    bool held() const { return held_; }
    // Gives the thread back the cores it had; callable from any thread, once or more.
    void release();

private:
    std::thread::native_handle_type thread_{};
    Cores previous_;
    bool held_ = false;
};

// The cores a thread may run on (empty where that cannot be read).
Cores coresOf(std::thread::native_handle_type thread);
// The calling thread's handle, for a hold.
std::thread::native_handle_type thisThread();

// A thread running `work`, held on `cores` (nothing held when empty). Not joinable when the system
// makes no thread: the caller then does the work itself.
template <typename Work>
std::thread threadOnCores(const Cores& cores, Work work) {
    try {
        return std::thread([cores, work = std::move(work)]() mutable {
            const CoreHold hold(thisThread(), cores);
            work();
        });
    } catch (const std::system_error&) {
        return std::thread();
    }
}

}  // namespace conescope
