// forEachRange and forEachBlock (geometry/scene/parallel_ranges.h): the ranges and blocks they cut,
// each run once whatever the threads, and the first exception passed on.
#include "geometry/scene/parallel_ranges.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <stdexcept>
#include <vector>

using namespace geometry::scene;

TEST(ParallelRanges, CutsSplitTheCountOrTheCostEvenly) {
    EXPECT_EQ(rangeCuts(10, 3, {}), (std::vector<size_t>{0, 3, 6, 10}));
    // Cost prefix of items costing 1, 1, 1, 1, 8, 1, 1, 1: half the cost (7.5) lies before item 4.
    const std::vector<uint32_t> bounds{0, 1, 2, 3, 4, 12, 13, 14, 15};
    EXPECT_EQ(rangeCuts(8, 2, bounds), (std::vector<size_t>{0, 5, 8}));
    // More ranges than items: empty ranges, never past the end.
    EXPECT_EQ(rangeCuts(2, 4, {}), (std::vector<size_t>{0, 0, 1, 1, 2}));
}

TEST(ParallelRanges, EveryBlockRunsOnceOnAnyNumberOfThreads) {
    constexpr size_t n = 100'000, blocks = 37;
    const std::vector<size_t> cut = rangeCuts(n, blocks, {});
    for (const unsigned threads : {1u, 2u, 3u, 8u}) {
        std::vector<std::atomic<int>> runs(blocks);
        std::vector<int> seen(n, 0);
        forEachBlock(n, blocks, threads, [&](size_t k, size_t b, size_t e) {
            ++runs[k];
            EXPECT_EQ(b, cut[k]);
            EXPECT_EQ(e, cut[k + 1]);
            for (size_t i = b; i < e; ++i) ++seen[i]; // blocks do not overlap: no race
        });
        for (size_t k = 0; k < blocks; ++k)
            EXPECT_EQ(runs[k].load(), 1) << "block " << k << ", " << threads << " threads";
        EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(n)) << threads << " threads";
    }
}

TEST(ParallelRanges, ABlocksExceptionReachesTheCaller) {
    std::atomic<int> ran{0};
    EXPECT_THROW(forEachBlock(1000, 10, 2,
                              [&](size_t k, size_t, size_t) {
                                  ++ran;
                                  if (k == 3) throw std::runtime_error("block 3");
                              }),
                 std::runtime_error);
    // Blocks 0 to 3 were taken before the throw; the thread that threw takes no more.
    EXPECT_GE(ran.load(), 4);
}
