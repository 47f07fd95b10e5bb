#include "geometry/scene/scratch_pages.h"

#include "geometry/scene/parallel_ranges.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <utility>

namespace geometry::scene {

namespace {

struct Block {
    std::byte* p;
    size_t bytes;
};

std::mutex mutex;
std::vector<Block> kept; // freed blocks' pages, taken from the back (the most recently used)
size_t keptTotal = 0;
int scopes = 0;

/// Pages per thread below which faultIn stays on one thread (1 MiB).
constexpr size_t kFaultInPagesPerThreadMin = 256;

size_t pageSize() noexcept {
    static const size_t page = size_t(std::max(4096l, sysconf(_SC_PAGESIZE)));
    return page;
}

/// `bytes` rounded up to whole pages; 0 where that does not fit in size_t.
size_t wholePages(size_t bytes) noexcept {
    const size_t page = pageSize();
    return bytes > SIZE_MAX - page ? 0 : (bytes + page - 1) / page * page;
}

/// Moves kept pages over the front of the page-aligned [to, to + size), the most recently kept first;
/// returns the bytes moved. Moving a page table entry costs far less than a fault and a clear. A
/// piece that cannot move leaves the rest as it was. Holds the lock: two callers never take the same
/// pages.
size_t moveKeptTo(std::byte* to, size_t size) noexcept {
    const std::lock_guard lock(mutex);
    size_t filled = 0;
    while (filled < size && !kept.empty()) {
        Block& from = kept.back();
        const size_t take = std::min(from.bytes, size - filled);
        if (mremap(from.p, take, take, MREMAP_MAYMOVE | MREMAP_FIXED, to + filled) == MAP_FAILED) break;
        filled += take;
        keptTotal -= take;
        from.p += take;
        from.bytes -= take;
        if (from.bytes == 0) kept.pop_back();
    }
    return filled;
}

} // namespace

namespace scratch {

std::pair<uintptr_t, uintptr_t> pagesWithin(const void* p, size_t bytes) noexcept {
    const uintptr_t page = pageSize(), from = uintptr_t(p), to = from + bytes;
    if (p == nullptr || to < from) return {0, 0};
    const uintptr_t lo = (from + page - 1) / page * page, hi = to / page * page;
    return hi > lo ? std::pair(lo, hi) : std::pair(lo, lo);
}

void* allocate(size_t bytes) {
    const size_t size = wholePages(std::max<size_t>(bytes, 1));
    if (size == 0) throw std::bad_alloc();
    void* mapped = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    auto* const block = static_cast<std::byte*>(mapped);
    moveKeptTo(block, size); // the rest stays fresh
    return block;
}

size_t backWithKept(void* p, size_t bytes) noexcept {
    const auto [lo, hi] = pagesWithin(p, bytes);
    return hi > lo ? moveKeptTo(reinterpret_cast<std::byte*>(lo), hi - lo) : 0;
}

void faultIn(void* p, size_t bytes) noexcept {
#if defined(MADV_POPULATE_WRITE)
    const std::pair<uintptr_t, uintptr_t> whole = pagesWithin(p, bytes);
    const uintptr_t lo = whole.first, page = pageSize();
    const size_t pages = (whole.second - lo) / page;
    if (pages == 0) return;
    try {
        forEachRange(pages, rangeThreads(pages, kFaultInPagesPerThreadMin), [&](unsigned, size_t b, size_t e) {
            ::madvise(reinterpret_cast<void*>(lo + b * page), (e - b) * page, MADV_POPULATE_WRITE);
        });
    } catch (...) { // no thread to be had: the writes fault the pages in instead
    }
#else
    (void)p;
    (void)bytes;
#endif
}

void dropPages(const void* p, size_t bytes) noexcept {
    const auto [lo, hi] = pagesWithin(p, bytes);
    if (hi > lo) ::madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_DONTNEED);
}

void prepare(void* p, size_t bytes) noexcept {
    // Kept pages fill the whole pages' front; the rest is faulted in.
    const auto [lo, hi] = pagesWithin(p, bytes);
    const uintptr_t done = lo + backWithKept(p, bytes);
    if (hi > done) faultIn(reinterpret_cast<void*>(done), hi - done);
}

void release(void* block, size_t bytes) noexcept {
    const size_t size = wholePages(std::max<size_t>(bytes, 1));
    if (block == nullptr || size == 0) return;
    auto* const b = static_cast<std::byte*>(block);
    const size_t page = pageSize();
    const std::lock_guard lock(mutex);
    // Only pages in memory are kept: a page never written would come back as a fresh one, and a block
    // taking it before a resident kept page would fault it in while the resident one stayed kept,
    // above the peak (4 M piperack STL, loadModel alone: 257 -> 292 MiB before this).
    std::vector<unsigned char> resident;
    try {
        if (scopes > 0) resident.resize(size / page);
    } catch (...) { // no room to look: give it back instead
    }
    if (resident.empty() || mincore(b, size, resident.data()) != 0) {
        munmap(b, size);
        return;
    }
    for (size_t first = 0; first < resident.size();) {
        const bool in = (resident[first] & 1) != 0;
        size_t end = first + 1;
        while (end < resident.size() && ((resident[end] & 1) != 0) == in) ++end;
        const Block run{b + first * page, (end - first) * page};
        bool keep = in;
        try {
            if (keep) kept.push_back(run);
        } catch (...) {
            keep = false;
        }
        if (keep) keptTotal += run.bytes;
        else munmap(run.p, run.bytes);
        first = end;
    }
}

void releaseKept() noexcept {
    std::vector<Block> gone;
    {
        const std::lock_guard lock(mutex);
        gone.swap(kept);
        keptTotal = 0;
    }
    for (const Block& b : gone) munmap(b.p, b.bytes);
}

size_t keptBytes() noexcept {
    const std::lock_guard lock(mutex);
    return keptTotal;
}

} // namespace scratch

ScratchScope::ScratchScope() noexcept {
    const std::lock_guard lock(mutex);
    ++scopes;
}

ScratchScope::~ScratchScope() {
    {
        const std::lock_guard lock(mutex);
        if (--scopes > 0) return;
    }
    scratch::releaseKept();
}

} // namespace geometry::scene
