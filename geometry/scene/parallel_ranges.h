// Splitting a loop over [0, n) into contiguous ranges, one thread each. The loader's linear passes use it:
// every range writes only its own outputs, so the result never depends on how many threads ran.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>
#include <thread>
#include <vector>

namespace geometry::scene {

/// Alignment of the state each range's thread updates in its loop (counters, the ends of the vectors
/// it appends to), for state kept side by side in one array: two ranges' state in one cache line
/// makes every update take the line from the other core. The crease normals' output vectors shared
/// a line until 2026-12: the two threads' split of the 4 M piperack took 0.26 s instead of 0.20 s.
inline constexpr size_t kRangeStateAlign = 64;

/// The most threads rangeThreads() hands out: the cores (at most 16) unless set lower (tests compare
/// one thread with several; benchmarks time them against each other).
inline std::atomic<unsigned>& rangeThreadCap() noexcept {
    static std::atomic<unsigned> cap{std::clamp(std::thread::hardware_concurrency(), 1u, 16u)};
    return cap;
}

/// Threads worth starting for `n` items when each should have at least `minPerThread`: at most
/// rangeThreadCap(), at least 1.
[[nodiscard]] inline unsigned rangeThreads(size_t n, size_t minPerThread) noexcept {
    const size_t cores = std::max(rangeThreadCap().load(std::memory_order_relaxed), 1u);
    return unsigned(std::clamp<size_t>(n / std::max<size_t>(minPerThread, 1), 1, cores));
}

/// The `ranges` + 1 ends of contiguous ranges of [0, n), even in count or, with `bounds` (a
/// non-decreasing cost prefix over [0, n]), in cost.
[[nodiscard]] inline std::vector<size_t> rangeCuts(size_t n, size_t ranges, std::span<const uint32_t> bounds) {
    ranges = std::max<size_t>(ranges, 1);
    std::vector<size_t> cut(ranges + 1, n);
    cut[0] = 0;
    for (size_t t = 1; t < ranges; ++t) {
        if (bounds.empty()) {
            cut[t] = size_t(uint64_t(n) * t / ranges);
            continue;
        }
        const uint64_t goal = uint64_t(bounds.back()) * t / ranges; // the cost before range t
        cut[t] = size_t(std::lower_bound(bounds.begin(), bounds.end(), goal) - bounds.begin());
        cut[t] = std::clamp(cut[t], cut[t - 1], n);
    }
    return cut;
}

/// Calls `body(range, begin, end)` for `threads` contiguous ranges of [0, n) (range 0 on this thread,
/// the others on their own). `bounds`, when not empty, is a non-decreasing cost prefix over [0, n]
/// (size n + 1) that the ranges split evenly instead of the item count. The first exception thrown
/// by any range is rethrown here once all have finished.
template <class Body>
void forEachRange(size_t n, unsigned threads, Body&& body, std::span<const uint32_t> bounds = {}) {
    threads = std::max(threads, 1u);
    const std::vector<size_t> cut = rangeCuts(n, threads, bounds);
    std::vector<std::exception_ptr> failed(threads);
    {
        const auto run = [&](unsigned t) noexcept {
            try {
                body(t, cut[t], cut[t + 1]);
            } catch (...) {
                failed[t] = std::current_exception();
            }
        };
        std::vector<std::jthread> workers;
        unsigned started = 1;
        try {
            workers.reserve(threads - 1);
            for (; started < threads; ++started) workers.emplace_back(run, started);
        } catch (...) { // no thread to be had: the ranges left run here
        }
        run(0);
        for (unsigned t = started; t < threads; ++t) run(t);
    }
    for (const std::exception_ptr& e : failed)
        if (e) std::rethrow_exception(e);
}

/// Calls `body(block, begin, end)` for `blocks` contiguous blocks of [0, n) (cut as forEachRange cuts
/// ranges), on `threads` threads, each taking the next block not yet taken when it finishes one:
/// for passes whose cost per item differs along [0, n) more than `bounds` can say (the crease
/// normals' second half of the 4 M piperack cost 1.5 times its first), so that no thread waits for
/// another's slower range. Each block writes its own outputs, so the result is the same however
/// blocks fall to threads. The first exception is rethrown once all threads have finished.
template <class Body>
void forEachBlock(size_t n, size_t blocks, unsigned threads, Body&& body, std::span<const uint32_t> bounds = {}) {
    const std::vector<size_t> cut = rangeCuts(n, blocks, bounds);
    blocks = cut.size() - 1;
    std::atomic<size_t> next{0};
    forEachRange(std::min<size_t>(threads, blocks), unsigned(std::min<size_t>(threads, blocks)),
                 [&](unsigned, size_t, size_t) {
                     for (size_t k = next.fetch_add(1, std::memory_order_relaxed); k < blocks;
                          k = next.fetch_add(1, std::memory_order_relaxed))
                         body(k, cut[k], cut[k + 1]);
                 });
}

} // namespace geometry::scene
