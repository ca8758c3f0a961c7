#include "CoreAffinity.h"

#include <utility>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace conescope {

#if defined(__linux__)

namespace {

Cores toCores(const cpu_set_t& set) {
    Cores cores;
    for (size_t c = 0; c < cores.size() && c < CPU_SETSIZE; ++c)
        if (CPU_ISSET(c, &set)) cores.set(c);
    return cores;
}

cpu_set_t toSet(const Cores& cores) {
    cpu_set_t set;
    CPU_ZERO(&set);
    for (size_t c = 0; c < cores.size() && c < CPU_SETSIZE; ++c)
        if (cores.test(c)) CPU_SET(c, &set);
    return set;
}

bool setCores(std::thread::native_handle_type thread, const Cores& cores) {
    const cpu_set_t set = toSet(cores);
    return pthread_setaffinity_np(thread, sizeof set, &set) == 0;
}

}  // namespace

Cores coresOf(std::thread::native_handle_type thread) {
    cpu_set_t set;
    if (pthread_getaffinity_np(thread, sizeof set, &set) != 0) return {};
    return toCores(set);
}

std::thread::native_handle_type thisThread() { return pthread_self(); }

CoreSplit splitCores() {
    const Cores allowed = coresOf(thisThread());
    const int current = sched_getcpu();
    if (allowed.count() < 2 || current < 0 || size_t(current) >= allowed.size() || !allowed.test(size_t(current))) return {};
    CoreSplit split;
    split.current.set(size_t(current));
    split.others = allowed;
    split.others.reset(size_t(current));
    return split;
}

CoreHold::CoreHold(std::thread::native_handle_type thread, const Cores& cores) : thread_(thread) {
    if (cores.none()) return;
    previous_ = coresOf(thread);
    held_ = previous_.any() && setCores(thread, cores);
}

void CoreHold::release() {
    if (held_) setCores(thread_, previous_);  // a refusal leaves the thread where it is: still correct
    held_ = false;
}

#else

Cores coresOf(std::thread::native_handle_type) { return {}; }
std::thread::native_handle_type thisThread() { return {}; }
CoreSplit splitCores() { return {}; }
CoreHold::CoreHold(std::thread::native_handle_type thread, const Cores&) : thread_(thread) {}
void CoreHold::release() { held_ = false; }

#endif

CoreHold::CoreHold(CoreHold&& other) noexcept
    : thread_(other.thread_), previous_(other.previous_), held_(std::exchange(other.held_, false)) {}

CoreHold& CoreHold::operator=(CoreHold&& other) noexcept {
    if (this != &other) {
        release();
        thread_ = other.thread_;
        previous_ = other.previous_;
        held_ = std::exchange(other.held_, false);
    }
    return *this;
}

}  // namespace conescope
