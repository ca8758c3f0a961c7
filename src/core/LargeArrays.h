#pragma once

// Large arrays filled right after they are sized. Touching fresh memory costs a page fault per
// 4 KiB page, and on virtual machines a fault costs about 10 us: sizing the face geometry of a
// million triangles took longer than computing it. On Linux such arrays ask for transparent huge
// pages (2 MiB, one fault each) where the system allows them; elsewhere this is a plain resize.

#include <cstddef>
#include <vector>

namespace conescope {

// Arrays smaller than this gain nothing worth a system call.
constexpr size_t kLargeArrayBytes = size_t(4) << 20;

// Hint that [data, data + bytes) will be used whole: the 2 MiB-aligned pages inside it may be
// backed by huge pages. A hint only: nothing changes when the system ignores it.
void adviseHugePages(void* data, size_t bytes);

// For a process whose work ends with it (the CLI): memory freed is kept for the next
// allocation instead of given back to the system, so that reusing it faults no page again
// (glibc returns blocks of 128 KiB and more at once). A fifth of a prop's page faults.
void keepFreedMemory();

// reserve(count), with the hint when the new storage is large.
template <typename T>
void reserveLarge(std::vector<T>& values, size_t count) {
    if (count * sizeof(T) >= kLargeArrayBytes && values.capacity() < count) {
        values.reserve(count);
        adviseHugePages(values.data(), count * sizeof(T));
    }
}

template <typename T>
void resizeLarge(std::vector<T>& values, size_t count) {
    reserveLarge(values, count);
    values.resize(count);
}

}  // namespace conescope
