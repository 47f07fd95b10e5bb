#include "geometry/scene/scratch_pages.h"

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace scratch = geometry::scene::scratch;
using geometry::scene::ScratchScope;

namespace {

constexpr size_t kMiB = size_t(1) << 20;

/// Pages of [p, p + bytes) that are resident (mincore): a kept page moved in is, a fresh one is not
/// until written.
size_t residentPages(const void* p, size_t bytes) {
    const size_t page = size_t(sysconf(_SC_PAGESIZE));
    std::vector<unsigned char> in((bytes + page - 1) / page);
    EXPECT_EQ(mincore(const_cast<void*>(p), bytes, in.data()), 0);
    return size_t(std::count_if(in.begin(), in.end(), [](unsigned char c) { return (c & 1) != 0; }));
}

size_t bytesEqualTo(const void* p, size_t bytes, unsigned char value) {
    const auto* b = static_cast<const unsigned char*>(p);
    return size_t(std::count(b, b + bytes, value));
}

/// A block of `bytes` from scratch::allocate with every byte written (only pages in memory are kept).
void* writtenBlock(size_t bytes, unsigned char value = 0x5a) {
    void* p = scratch::allocate(bytes);
    std::memset(p, value, bytes);
    return p;
}

} // namespace

TEST(ScratchPages, AFreedBlocksPagesMakeTheNextBlockWithTheirContents) {
    const ScratchScope scope;
    void* a = scratch::allocate(4 * kMiB);
    std::memset(a, 0xab, 4 * kMiB);
    scratch::release(a, 4 * kMiB);
    EXPECT_EQ(scratch::keptBytes(), 4 * kMiB);
    void* b = scratch::allocate(4 * kMiB);
    EXPECT_EQ(scratch::keptBytes(), 0u);
    // Moved, not copied into fresh pages: resident before any write, and still holding a's bytes.
    EXPECT_EQ(residentPages(b, 4 * kMiB), 4 * kMiB / size_t(sysconf(_SC_PAGESIZE)));
    EXPECT_EQ(bytesEqualTo(b, 4 * kMiB, 0xab), 4 * kMiB);
    scratch::release(b, 4 * kMiB);
}

TEST(ScratchPages, ALargerBlockTakesEveryKeptPageThenFreshOnes) {
    const ScratchScope scope;
    void* a = scratch::allocate(1 * kMiB);
    void* b = scratch::allocate(2 * kMiB);
    std::memset(a, 0xaa, 1 * kMiB);
    std::memset(b, 0xbb, 2 * kMiB);
    scratch::release(a, 1 * kMiB);
    scratch::release(b, 2 * kMiB);
    void* c = scratch::allocate(5 * kMiB);
    EXPECT_EQ(scratch::keptBytes(), 0u);
    EXPECT_EQ(bytesEqualTo(c, 5 * kMiB, 0xaa), 1 * kMiB);
    EXPECT_EQ(bytesEqualTo(c, 5 * kMiB, 0xbb), 2 * kMiB);
    EXPECT_EQ(bytesEqualTo(c, 5 * kMiB, 0x00), 2 * kMiB); // fresh pages read as zero
    scratch::release(c, 5 * kMiB);
}

TEST(ScratchPages, ASmallerBlockLeavesTheRestKept) {
    const ScratchScope scope;
    scratch::release(writtenBlock(4 * kMiB), 4 * kMiB);
    void* b = scratch::allocate(1 * kMiB + 1); // whole pages: 1 MiB and one page
    const size_t page = size_t(sysconf(_SC_PAGESIZE));
    EXPECT_EQ(scratch::keptBytes(), 3 * kMiB - page);
    scratch::release(b, 1 * kMiB + 1);
    EXPECT_EQ(scratch::keptBytes(), 4 * kMiB);
}

TEST(ScratchPages, PagesAreKeptOnlyWhileAScopeIsOpen) {
    scratch::release(writtenBlock(2 * kMiB), 2 * kMiB);
    EXPECT_EQ(scratch::keptBytes(), 0u); // no scope: unmapped at once
    {
        const ScratchScope outer;
        {
            const ScratchScope inner;
            scratch::release(writtenBlock(2 * kMiB), 2 * kMiB);
        }
        EXPECT_EQ(scratch::keptBytes(), 2 * kMiB); // the outer scope still holds them
        scratch::releaseKept();
        EXPECT_EQ(scratch::keptBytes(), 0u);
        scratch::release(writtenBlock(2 * kMiB), 2 * kMiB);
    }
    EXPECT_EQ(scratch::keptBytes(), 0u); // the last scope gave them back
}

TEST(ScratchPages, LargeVectorsUseThemAndSmallOnesTheHeap) {
    if (!geometry::scene::kScratchPages) GTEST_SKIP() << "the address sanitizer's build keeps the heap's blocks";
    const ScratchScope scope;
    { geometry::scene::ScratchVector<uint32_t> small(1000, 7u); }
    EXPECT_EQ(scratch::keptBytes(), 0u);
    {
        geometry::scene::ScratchVector<uint32_t> large(kMiB, 7u); // 4 MiB
        EXPECT_EQ(std::count(large.begin(), large.end(), 7u), std::ptrdiff_t(kMiB));
    }
    EXPECT_EQ(scratch::keptBytes(), 4 * kMiB);
    geometry::scene::ScratchVector<uint32_t> again(kMiB, 1u); // the kept pages, written anew
    EXPECT_EQ(scratch::keptBytes(), 0u);
    EXPECT_EQ(std::count(again.begin(), again.end(), 1u), std::ptrdiff_t(kMiB));
}

TEST(ScratchPages, PagesNeverWrittenAreNotKept) {
    const ScratchScope scope;
    void* a = scratch::allocate(4 * kMiB);
    std::memset(a, 0x11, 1 * kMiB); // the rest was never written: not in memory
    scratch::release(a, 4 * kMiB);
    EXPECT_EQ(scratch::keptBytes(), 1 * kMiB);
    void* b = scratch::allocate(1 * kMiB);
    EXPECT_EQ(bytesEqualTo(b, 1 * kMiB, 0x11), 1 * kMiB);
    scratch::release(b, 1 * kMiB);
}

TEST(ScratchPages, AHeapArrayTakesKeptPagesInPlaceOfItsOwn) {
    const ScratchScope scope;
    const size_t page = size_t(sysconf(_SC_PAGESIZE));
    EXPECT_EQ(scratch::backWithKept(nullptr, 4 * kMiB), 0u);
    scratch::release(writtenBlock(4 * kMiB, 0xab), 4 * kMiB);
    // 8 MiB of heap, not written yet; one byte past its start leaves its first page partly covered.
    auto* heap = static_cast<unsigned char*>(std::malloc(8 * kMiB + page));
    ASSERT_NE(heap, nullptr);
    unsigned char* const array = heap + (page - reinterpret_cast<uintptr_t>(heap) % page) + 1;
    EXPECT_EQ(scratch::backWithKept(array, 8 * kMiB - 1), 4 * kMiB); // whole pages from array + page - 1 on
    EXPECT_EQ(scratch::keptBytes(), 0u);
    EXPECT_EQ(scratch::backWithKept(array, 8 * kMiB - 1), 0u); // nothing left to take
    // Moved, not faulted in: in memory before any write, with the kept pages' bytes, from the first
    // whole page on.
    unsigned char* const firstWhole = array + page - 1;
    EXPECT_EQ(residentPages(firstWhole, 4 * kMiB), 4 * kMiB / page);
    EXPECT_EQ(bytesEqualTo(firstWhole, 4 * kMiB, 0xab), 4 * kMiB);
    std::memset(array, 0x77, 8 * kMiB - 1); // all of it still the heap's to use and free
    EXPECT_EQ(bytesEqualTo(array, 8 * kMiB - 1, 0x77), 8 * kMiB - 1);
    std::free(heap);
}

TEST(ScratchPages, PrepareBacksWithKeptPagesThenFaultsInTheRest) {
    const size_t page = size_t(sysconf(_SC_PAGESIZE));
#if defined(MADV_POPULATE_WRITE)
    void* probe = mmap(nullptr, page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(probe, MAP_FAILED);
    const bool populates = madvise(probe, page, MADV_POPULATE_WRITE) == 0;
    munmap(probe, page);
    if (!populates) GTEST_SKIP() << "the kernel cannot populate pages (MADV_POPULATE_WRITE: Linux 5.14)";
#else
    GTEST_SKIP() << "MADV_POPULATE_WRITE unknown here";
#endif
    const ScratchScope scope;
    scratch::release(writtenBlock(2 * kMiB, 0xab), 2 * kMiB);
    // 8 MiB of heap, not written yet, page-aligned: 2 MiB of kept pages, then 6 MiB faulted in on every core.
    auto* heap = static_cast<unsigned char*>(std::malloc(8 * kMiB + page));
    ASSERT_NE(heap, nullptr);
    unsigned char* const array = heap + (page - reinterpret_cast<uintptr_t>(heap) % page);
    scratch::prepare(array, 8 * kMiB);
    EXPECT_EQ(scratch::keptBytes(), 0u);
    EXPECT_EQ(residentPages(array, 8 * kMiB), 8 * kMiB / page); // all in memory before any write
    EXPECT_EQ(bytesEqualTo(array, 2 * kMiB, 0xab), 2 * kMiB);
    EXPECT_EQ(bytesEqualTo(array + 2 * kMiB, 6 * kMiB, 0), 6 * kMiB); // fresh pages read as zero
    std::free(heap);
}

TEST(ScratchPages, DroppedPagesLeaveMemoryAndTheRestAsItWas) {
    const size_t page = size_t(sysconf(_SC_PAGESIZE));
    // 8 MiB of heap, written; one byte past a page's start, so the first page is only partly covered.
    auto* heap = static_cast<unsigned char*>(std::malloc(8 * kMiB + 2 * page));
    ASSERT_NE(heap, nullptr);
    unsigned char* const array = heap + (page - reinterpret_cast<uintptr_t>(heap) % page);
    std::memset(array, 0x5a, 8 * kMiB);
    scratch::dropPages(nullptr, 4 * kMiB); // nothing to drop
    scratch::dropPages(array + 4 * kMiB + 1, 4 * kMiB - 1);
    // The page holding array + 4 MiB + 1 is only partly inside: it stays, with every byte.
    EXPECT_EQ(residentPages(array, 4 * kMiB + page), 4 * kMiB / page + 1);
    EXPECT_EQ(bytesEqualTo(array, 4 * kMiB + page, 0x5a), 4 * kMiB + page);
    EXPECT_EQ(residentPages(array + 4 * kMiB + page, 4 * kMiB - page), 0u);
    // Still the heap's to use: the dropped pages read as zeros, take writes, and free.
    EXPECT_EQ(bytesEqualTo(array + 4 * kMiB + page, 4 * kMiB - page, 0), 4 * kMiB - page);
    std::memset(array, 0x77, 8 * kMiB);
    EXPECT_EQ(bytesEqualTo(array, 8 * kMiB, 0x77), 8 * kMiB);
    std::free(heap);
}
