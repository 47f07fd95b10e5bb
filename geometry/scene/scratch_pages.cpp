#include "geometry/scene/scratch_pages.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <mutex>

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

size_t pageSize() noexcept {
    static const size_t page = size_t(std::max(4096l, sysconf(_SC_PAGESIZE)));
    return page;
}

/// `bytes` rounded up to whole pages; 0 where that does not fit in size_t.
size_t wholePages(size_t bytes) noexcept {
    const size_t page = pageSize();
    return bytes > SIZE_MAX - page ? 0 : (bytes + page - 1) / page * page;
}

} // namespace

namespace scratch {

void* allocate(size_t bytes) {
    const size_t size = wholePages(std::max<size_t>(bytes, 1));
    if (size == 0) throw std::bad_alloc();
    void* mapped = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    auto* const block = static_cast<std::byte*>(mapped);
    const std::lock_guard lock(mutex);
    // Kept pages replace the block's front: moving a page table entry costs far less than a fault
    // and a clear. A piece that cannot move leaves the rest of the block fresh.
    for (size_t filled = 0; filled < size && !kept.empty();) {
        Block& from = kept.back();
        const size_t take = std::min(from.bytes, size - filled);
        if (mremap(from.p, take, take, MREMAP_MAYMOVE | MREMAP_FIXED, block + filled) == MAP_FAILED) break;
        filled += take;
        keptTotal -= take;
        from.p += take;
        from.bytes -= take;
        if (from.bytes == 0) kept.pop_back();
    }
    return block;
}

void release(void* block, size_t bytes) noexcept {
    const size_t size = wholePages(std::max<size_t>(bytes, 1));
    if (block == nullptr || size == 0) return;
    {
        const std::lock_guard lock(mutex);
        if (scopes > 0) {
            try {
                kept.push_back({static_cast<std::byte*>(block), size});
                keptTotal += size;
                return;
            } catch (...) { // no room to note it: give it back instead
            }
        }
    }
    munmap(block, size);
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
