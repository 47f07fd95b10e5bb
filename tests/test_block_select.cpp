// blockSelect (geometry/scene/block_select.h) keeps std::nth_element's promise on every kind of order
// chunking meets (random, sorted, few distinct keys, all equal), also when its sampled pivots miss
// the rank they should bracket, and moves elements, never loses them.
#include "geometry/scene/block_select.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using geometry::scene::blockSelect;

namespace {

struct Item {
    float key;
    uint32_t id;
};

float keyOf(const Item& i) { return i.key; }

/// Selects position nth of `items` and checks the promise and that the ids are a permutation.
void expectSelected(std::vector<Item> items, size_t nth, const char* what) {
    const std::vector<Item> before = items;
    blockSelect(items.data(), items.data() + nth, items.data() + items.size(), keyOf);
    if (nth < items.size()) {
        std::vector<float> sorted;
        for (const Item& i : before) sorted.push_back(i.key);
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(items[nth].key, sorted[nth]) << what << " n " << items.size() << " nth " << nth;
        for (size_t i = 0; i < nth; ++i) ASSERT_LE(items[i].key, items[nth].key) << what << " at " << i;
        for (size_t i = nth + 1; i < items.size(); ++i) ASSERT_GE(items[i].key, items[nth].key) << what << " at " << i;
    }
    std::vector<uint32_t> ids;
    for (const Item& i : items) ids.push_back(i.id);
    std::sort(ids.begin(), ids.end());
    for (size_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i) << what;
    // Each id keeps its key: elements move whole.
    for (const Item& i : items) ASSERT_EQ(i.key, before[i.id].key) << what;
}

std::vector<Item> itemsOf(const std::vector<float>& keys) {
    std::vector<Item> items;
    for (size_t i = 0; i < keys.size(); ++i) items.push_back({keys[i], uint32_t(i)});
    return items;
}

} // namespace

TEST(BlockSelect, KeepsNthElementsPromiseOnEveryOrder) {
    std::mt19937 rng(7);
    for (const size_t n :
         {size_t(1), size_t(2), size_t(63), size_t(65), size_t(200), size_t(1025), size_t(20000), size_t(100003)}) {
        std::vector<float> random(n), few(n), sorted(n), reversed(n), equal(n, 2.5f), organ(n);
        for (size_t i = 0; i < n; ++i) {
            random[i] = std::uniform_real_distribution<float>(-1.f, 1.f)(rng);
            few[i] = float(rng() % 3); // three distinct keys: most comparisons tie
            sorted[i] = float(i);
            reversed[i] = float(n - i);
            organ[i] = float(std::min(i, n - i));
        }
        for (const size_t nth : {size_t(0), n / 2, n - 1}) {
            expectSelected(itemsOf(random), nth, "random");
            expectSelected(itemsOf(few), nth, "few");
            expectSelected(itemsOf(sorted), nth, "sorted");
            expectSelected(itemsOf(reversed), nth, "reversed");
            expectSelected(itemsOf(equal), nth, "equal");
            expectSelected(itemsOf(organ), nth, "organ pipe");
        }
    }
}

// The evenly spaced sample (every 32nd of 2^16 keys) holds only keys above all the others, or only
// keys below: both pivots fall on one side of the rank, and the round must cut the range from that
// side instead.
TEST(BlockSelect, SampledPivotsOnOneSideStillSelect) {
    const size_t n = size_t(1) << 16;
    for (const float sign : {1.f, -1.f}) {
        std::vector<float> keys(n);
        for (size_t i = 0; i < n; ++i) keys[i] = i % 16 == 0 ? sign * float(1e6 + i) : float(i % 1000);
        for (const size_t nth : {size_t(0), n / 2, n / 3, n - 1}) expectSelected(itemsOf(keys), nth, "biased sample");
    }
}

TEST(BlockSelect, IsDeterministicAndLeavesRangesWithoutNth) {
    std::mt19937 rng(3);
    std::vector<float> keys(5000);
    for (float& k : keys) k = float(rng() % 100);
    std::vector<Item> a = itemsOf(keys), b = itemsOf(keys);
    blockSelect(a.data(), a.data() + 2500, a.data() + a.size(), keyOf);
    blockSelect(b.data(), b.data() + 2500, b.data() + b.size(), keyOf);
    for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i].id, b[i].id);
    std::vector<Item> c = itemsOf(keys);
    blockSelect(c.data(), c.data() + c.size(), c.data() + c.size(), keyOf); // nth == last: nothing to do
    for (size_t i = 0; i < c.size(); ++i) ASSERT_EQ(c[i].id, i);
    blockSelect(c.data(), c.data(), c.data(), keyOf); // empty
}

// 2^15 keys are sampled every 32nd: NaN at every third key is in the sample as well (the sampled
// round is skipped); NaN at every fourth from the second is not, and the sampled partitions meet it.
TEST(BlockSelect, NaNKeysEndItWithoutLosingElements) {
    for (const size_t n : {size_t(3000), size_t(1) << 15})
        for (const size_t nanEvery : {size_t(3), size_t(4)}) {
            std::vector<float> keys(n, 1.f);
            for (size_t i = 1; i < keys.size(); i += nanEvery) keys[i] = std::numeric_limits<float>::quiet_NaN();
            for (size_t i = 2; i < keys.size(); i += 7) keys[i] = float(i);
            std::vector<Item> items = itemsOf(keys);
            blockSelect(items.data(), items.data() + n / 2, items.data() + items.size(), keyOf);
            std::vector<uint32_t> ids;
            for (const Item& i : items) ids.push_back(i.id);
            std::sort(ids.begin(), ids.end());
            for (size_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], i) << n << " " << nanEvery;
        }
}
