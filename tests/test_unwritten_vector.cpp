#include "geometry/scene/unwritten_vector.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

using geometry::scene::UnwrittenVector;

TEST(UnwrittenVector, ValuesGivenAreKeptAsWithStdVector) {
    // Only elements made without a value start unwritten: every other way of filling keeps its value.
    UnwrittenVector<uint32_t> v(4, 7u);
    EXPECT_EQ(v, (UnwrittenVector<uint32_t>{7, 7, 7, 7}));
    v.push_back(9);
    v.resize(7, 3u);
    EXPECT_EQ(v, (UnwrittenVector<uint32_t>{7, 7, 7, 7, 9, 3, 3}));
    v.assign(2, 1u);
    EXPECT_EQ(v, (UnwrittenVector<uint32_t>{1, 1}));
    UnwrittenVector<std::array<uint32_t, 3>> tris;
    tris.emplace_back(std::array<uint32_t, 3>{1, 2, 3});
    EXPECT_EQ(tris[0][2], 3u);
}

TEST(UnwrittenVector, SizedVectorsHaveTheirSizeAndTakeWrites) {
    UnwrittenVector<float> v(1000);
    ASSERT_EQ(v.size(), 1000u);
    for (size_t i = 0; i < v.size(); ++i) v[i] = float(i);
    v.resize(2000);
    ASSERT_EQ(v.size(), 2000u);
    EXPECT_EQ(v[999], 999.f); // kept across the growth
    UnwrittenVector<float>().swap(v);
    EXPECT_EQ(v.capacity(), 0u);
}
