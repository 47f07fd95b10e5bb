// Pages for the loader's large temporaries (docs/design.md §2.1 "Scratch pages"). While a load runs
// (a ScratchScope is open), a freed block's pages are kept, and the next block asked for is made of
// them, moved into place by the kernel (mremap: no copy, no fault, no clearing) before any fresh page
// is taken. A load's passes each make and free arrays of about the model's size; without this every
// pass faulted in and cleared its pages anew, about a fifth of the load's CPU time.
//
// Kept pages are taken before fresh ones, so the resident size rises only when no kept page is left:
// the peak is the largest sum of live blocks, as without keeping, as long as the load's other large
// arrays (the model's own, from the heap) take kept pages too (scratch::backWithKept) or are made
// after scratch::releaseKept(). When the last scope closes, the kept pages go back to the system.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace geometry::scene {

/// Blocks this large and above are scratch pages; smaller ones come from the heap.
inline constexpr size_t kScratchMinBytes = size_t(1) << 20;

/// Without the sanitizers' allocator the address sanitizer would not see these blocks' bounds.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kScratchPages = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kScratchPages = false;
#else
inline constexpr bool kScratchPages = true;
#endif
#else
inline constexpr bool kScratchPages = true;
#endif

namespace scratch {
/// The whole pages inside [p, p + bytes), as addresses [lo, hi) (lo == hi: none). The rest of a
/// partly covered page may be someone else's (a heap chunk's header, a mapped file's other bytes).
[[nodiscard]] std::pair<uintptr_t, uintptr_t> pagesWithin(const void* p, size_t bytes) noexcept;
/// A page-aligned block of at least `bytes`, mapped on its own: kept pages first (their old contents
/// stay), then fresh zero pages. Throws std::bad_alloc when the system has no room.
[[nodiscard]] void* allocate(size_t bytes);
/// Gives back a block from allocate() of that size: kept while a scope is open, else unmapped.
void release(void* block, size_t bytes) noexcept;
/// Moves kept pages in place of the whole pages inside [p, p + bytes), memory the caller owns and
/// has not written yet (a heap array's reserved capacity), so that writing it faults in nothing;
/// those pages' contents become the kept pages' old ones. Returns the bytes moved in (0 when none is
/// kept). A load's own arrays take kept pages this way instead of fresh ones: on this project's
/// 2-core machine a fresh page costs about 2.5 µs to fault in and clear.
size_t backWithKept(void* p, size_t bytes) noexcept;
/// Faults in the whole pages inside [p, p + bytes), memory the caller owns (a heap array's reserved
/// capacity), on every core: the resize that first writes such an array faults its pages one by one
/// on one thread (48 MB: 35 ms; on two cores at once: 14 ms). Without the kernel's support (Linux
/// 5.14, MADV_POPULATE_WRITE) nothing happens and the writes fault as before.
void faultIn(void* p, size_t bytes) noexcept;
/// Gives the whole pages inside [p, p + bytes) back to the system, memory the caller owns and no
/// longer needs the contents of: a heap array's capacity past its size (they read as zeros when next
/// touched; a shrunken array's tail would otherwise stay resident), or a read file mapping's pages
/// already read (read from the file again if touched).
void dropPages(const void* p, size_t bytes) noexcept;
/// backWithKept, then faultIn for what kept pages did not cover: a load's own array of `bytes`,
/// about to be written in full.
void prepare(void* p, size_t bytes) noexcept;
/// prepare for the whole reserved capacity of `v` (reserve first; nothing written yet).
template <class T, class A> void prepareCapacity(std::vector<T, A>& v) noexcept {
    prepare(v.data(), v.capacity() * sizeof(T));
}
/// An empty `v` made `n` elements long (value-initialised) on pages that are in memory first, with
/// `spare` elements of capacity beyond: the resize's writes fault nothing in on one thread.
template <class T, class A> void resizePrepared(std::vector<T, A>& v, size_t n, size_t spare = 0) {
    v.reserve(n + spare);
    prepareCapacity(v);
    v.resize(n);
}
/// Gives every kept page back to the system: before a load makes arrays of its own that are not
/// scratch and not backed (they would add to the kept pages, not take them).
void releaseKept() noexcept;
/// Bytes of pages kept for the next block (tests, reports).
[[nodiscard]] size_t keptBytes() noexcept;
} // namespace scratch

/// Keeps freed scratch pages until the last open scope closes (loadModel holds one). Scopes may
/// nest and be open on several threads; the pages are shared by all of them.
class ScratchScope {
public:
    ScratchScope() noexcept;
    ~ScratchScope();
    ScratchScope(const ScratchScope&) = delete;
    ScratchScope& operator=(const ScratchScope&) = delete;
};

/// std::allocator, with blocks of kScratchMinBytes and above from scratch pages.
template <class T> struct ScratchAllocator {
    using value_type = T;
    ScratchAllocator() noexcept = default;
    template <class U> ScratchAllocator(const ScratchAllocator<U>&) noexcept {}
    [[nodiscard]] T* allocate(size_t n) {
        if (kScratchPages && n >= kScratchMinBytes / sizeof(T)) {
            if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
            return static_cast<T*>(scratch::allocate(n * sizeof(T)));
        }
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T* p, size_t n) noexcept {
        if (kScratchPages && n >= kScratchMinBytes / sizeof(T)) scratch::release(p, n * sizeof(T));
        else std::allocator<T>().deallocate(p, n);
    }
    template <class U> bool operator==(const ScratchAllocator<U>&) const noexcept { return true; }
};

/// A loader temporary that starts with its elements' values, as std::vector.
template <class T> using ScratchVector = std::vector<T, ScratchAllocator<T>>;

} // namespace geometry::scene
