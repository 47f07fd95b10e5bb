#include "geometry/analysis/metrics.h"
#include "geometry/analysis/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace geometry::analysis;

namespace {
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

std::vector<uint8_t> allReceivers(size_t n) { return std::vector<uint8_t>(n, 1); }
} // namespace

// ---- aliasingStats --------------------------------------------------------------------------

TEST(AliasingStats, HandComputedSmallCase) {
    // Receivers hold m = {0.5, 1, 2, 4} (the 100 and the NaN are on non-receivers).
    const std::vector<float> m{2.f, 100.f, 0.5f, 4.f, kNaN, 1.f};
    const std::vector<uint8_t> r{1, 0, 1, 1, 0, 1};
    const auto st = aliasingStats(m, r);
    EXPECT_EQ(st.count, 4u);
    EXPECT_EQ(st.skipped, 0u);
    EXPECT_DOUBLE_EQ(st.mean, 7.5 / 4);
    EXPECT_DOUBLE_EQ(st.p50, 1.0); // nearest rank ⌈0.5·4⌉ = 2nd smallest
    EXPECT_DOUBLE_EQ(st.p95, 4.0); // ⌈0.95·4⌉ = 4th
    EXPECT_DOUBLE_EQ(st.max, 4.0);
    EXPECT_DOUBLE_EQ(st.undersampled, 0.5); // 2 and 4; m = 1 exactly is not undersampled
}

TEST(AliasingStats, NearestRankPercentilesOnOneToHundred) {
    std::vector<float> m;
    for (int i = 100; i >= 1; --i) m.push_back(float(i)); // order must not matter
    const auto st = aliasingStats(m, allReceivers(m.size()));
    EXPECT_DOUBLE_EQ(st.p50, 50.0);
    EXPECT_DOUBLE_EQ(st.p95, 95.0);
    EXPECT_DOUBLE_EQ(st.max, 100.0);
    EXPECT_DOUBLE_EQ(st.mean, 50.5);
    EXPECT_DOUBLE_EQ(st.undersampled, 0.99);
}

TEST(AliasingStats, TwentyValuesP95IsTheNineteenth) {
    // 0.95·20 is 19 exactly in reals but not in binary floating point; the rank must be 19.
    std::vector<float> m;
    for (int i = 1; i <= 20; ++i) m.push_back(float(i));
    EXPECT_DOUBLE_EQ(aliasingStats(m, allReceivers(20)).p95, 19.0);
}

TEST(AliasingStats, SingleValue) {
    const std::vector<float> m{3.f};
    const auto st = aliasingStats(m, allReceivers(1));
    EXPECT_EQ(st.count, 1u);
    EXPECT_DOUBLE_EQ(st.p50, 3.0);
    EXPECT_DOUBLE_EQ(st.p95, 3.0);
    EXPECT_DOUBLE_EQ(st.undersampled, 1.0);
}

TEST(AliasingStats, NonFiniteReceiverValuesAreSkippedAndCounted) {
    const std::vector<float> m{kNaN, 2.f, kInf, -kInf, 0.5f};
    const auto st = aliasingStats(m, allReceivers(m.size()));
    EXPECT_EQ(st.count, 2u);
    EXPECT_EQ(st.skipped, 3u);
    EXPECT_DOUBLE_EQ(st.mean, 1.25);
    EXPECT_DOUBLE_EQ(st.max, 2.0);
    EXPECT_DOUBLE_EQ(st.undersampled, 0.5);
    EXPECT_TRUE(std::isfinite(st.p50) && std::isfinite(st.p95));
}

TEST(AliasingStats, EmptyOrNoReceiversGiveAllZero) {
    for (const auto& st :
         {aliasingStats({}, {}), aliasingStats(std::vector<float>{5.f, 6.f}, std::vector<uint8_t>{0, 0}),
          aliasingStats(std::vector<float>{kNaN}, std::vector<uint8_t>{1})}) {
        EXPECT_EQ(st.count, 0u);
        EXPECT_EQ(st.mean, 0.0);
        EXPECT_EQ(st.p50, 0.0);
        EXPECT_EQ(st.p95, 0.0);
        EXPECT_EQ(st.max, 0.0);
        EXPECT_EQ(st.undersampled, 0.0);
    }
    EXPECT_EQ(aliasingStats(std::vector<float>{kNaN}, std::vector<uint8_t>{1}).skipped, 1u);
}

TEST(AliasingStats, SizeMismatchThrows) {
    EXPECT_THROW((void)aliasingStats(std::vector<float>{1.f, 2.f}, std::vector<uint8_t>{1}), std::invalid_argument);
}

// ---- truthStats -----------------------------------------------------------------------------

TEST(TruthStats, HandComputedRates) {
    // pixel:     0    1    2    3    4    5     6 (non-receiver)
    // truth:     lit  lit  shad shad lit  shad  lit
    // s:         1    0.2  0    0.7  0.5  0.49  0
    // verdict:   ok   FS   ok   FL   ok   ok    —
    const std::vector<float> s{1.f, 0.2f, 0.f, 0.7f, 0.5f, 0.49f, 0.f};
    const std::vector<uint8_t> occ{0, 0, 1, 1, 0, 1, 0};
    const std::vector<uint8_t> r{1, 1, 1, 1, 1, 1, 0};
    const auto st = truthStats(s, occ, r);
    EXPECT_EQ(st.count, 6u);
    EXPECT_EQ(st.skipped, 0u);
    EXPECT_DOUBLE_EQ(st.falseShadow, 1.0 / 6); // s = 0.5 on a lit pixel counts as lit
    EXPECT_DOUBLE_EQ(st.falseLit, 1.0 / 6);    // s = 0.49 on a shadowed pixel is correct
    // |s − truth|: 0, 0.8, 0, 0.7, 0.5, 0.49
    const double expected = (0.0 + (1.0 - double(0.2f)) + 0.0 + double(0.7f) + 0.5 + double(0.49f)) / 6;
    EXPECT_NEAR(st.meanAbs, expected, 1e-12);
}

TEST(TruthStats, PerfectAgreement) {
    const std::vector<float> s{1.f, 0.f, 1.f};
    const std::vector<uint8_t> occ{0, 1, 0};
    const auto st = truthStats(s, occ, allReceivers(3));
    EXPECT_EQ(st.falseShadow, 0.0);
    EXPECT_EQ(st.falseLit, 0.0);
    EXPECT_EQ(st.meanAbs, 0.0);
}

TEST(TruthStats, NonFiniteSkippedAndCounted) {
    const std::vector<float> s{kNaN, 0.f, kInf};
    const std::vector<uint8_t> occ{0, 0, 1};
    const auto st = truthStats(s, occ, allReceivers(3));
    EXPECT_EQ(st.count, 1u);
    EXPECT_EQ(st.skipped, 2u);
    EXPECT_DOUBLE_EQ(st.falseShadow, 1.0);
    EXPECT_DOUBLE_EQ(st.meanAbs, 1.0);
}

TEST(TruthStats, EmptyGivesAllZero) {
    const auto st = truthStats({}, {}, {});
    EXPECT_EQ(st.count, 0u);
    EXPECT_EQ(st.falseShadow, 0.0);
    EXPECT_EQ(st.falseLit, 0.0);
    EXPECT_EQ(st.meanAbs, 0.0);
}

TEST(TruthStats, SizeMismatchThrows) {
    const std::vector<float> s{1.f, 0.f};
    EXPECT_THROW((void)truthStats(s, std::vector<uint8_t>{0}, allReceivers(2)), std::invalid_argument);
    EXPECT_THROW((void)truthStats(s, std::vector<uint8_t>{0, 1}, allReceivers(3)), std::invalid_argument);
}

// ---- texel utilization ----------------------------------------------------------------------

TEST(TexelUtilization, FourByFourMapFromAFewPixels) {
    const std::vector<glm::vec4> aux{
        {0.2f, 0.7f, 0.f, 0.5f},   // texel (0,0)
        {0.9f, 0.1f, 0.f, 0.5f},   // texel (0,0) again: counted once
        {3.5f, 3.99f, 0.f, 0.5f},  // texel (3,3)
        {1.0f, 2.0f, 0.f, 0.5f},   // texel (1,2): floor of an exact integer
        {2.5f, 2.5f, 1.f, 0.5f},   // other split
        {2.5f, 0.5f, 0.f, 0.5f},   // non-receiver
        {4.0f, 1.0f, 0.f, 0.5f},   // u = resolution: off the map
        {-0.1f, 1.0f, 0.f, 0.5f},  // off the map
        {kNaN, 1.0f, 0.f, 0.5f},   // not finite
        {1.5f, 1.5f, 0.02f, 0.5f}, // split index read back slightly off 0: texel (1,1)
    };
    const std::vector<uint8_t> r{1, 1, 1, 1, 1, 0, 1, 1, 1, 1};
    EXPECT_DOUBLE_EQ(texelUtilization(aux, r, 0, 4), 4.0 / 16);
    EXPECT_DOUBLE_EQ(texelUtilization(aux, r, 1, 4), 1.0 / 16);
    EXPECT_DOUBLE_EQ(texelUtilization(aux, r, 2, 4), 0.0);

    const auto mask = texelUsageMask(aux, r, 0, 4);
    ASSERT_EQ(mask.size(), 16u);
    std::vector<uint8_t> expected(16, 0);
    for (auto [u, v] : {std::pair{0, 0}, {3, 3}, {1, 2}, {1, 1}}) expected[size_t(v * 4 + u)] = 1;
    EXPECT_EQ(mask, expected);
}

TEST(TexelUtilization, FullCoverage) {
    std::vector<glm::vec4> aux;
    for (int v = 0; v < 8; ++v)
        for (int u = 0; u < 8; ++u) aux.push_back({float(u) + 0.5f, float(v) + 0.5f, 3.f, 0.f});
    EXPECT_DOUBLE_EQ(texelUtilization(aux, allReceivers(aux.size()), 3, 8), 1.0);
    EXPECT_DOUBLE_EQ(texelUtilization(aux, allReceivers(aux.size()), 3, 16), 0.25);
}

TEST(TexelUtilization, EmptyInputIsZero) { EXPECT_EQ(texelUtilization({}, {}, 0, 16), 0.0); }

TEST(TexelUtilization, LargestResolutionWorks) {
    const std::vector<glm::vec4> aux{{16383.5f, 16383.5f, 0.f, 0.f}};
    EXPECT_DOUBLE_EQ(texelUtilization(aux, allReceivers(1), 0, 16384), 1.0 / (16384.0 * 16384.0));
}

TEST(TexelUtilization, BadInputThrows) {
    const std::vector<glm::vec4> aux{{0.f, 0.f, 0.f, 0.f}};
    EXPECT_THROW((void)texelUtilization(aux, allReceivers(2), 0, 4), std::invalid_argument);
    EXPECT_THROW((void)texelUsageMask(aux, allReceivers(2), 0, 4), std::invalid_argument);
    EXPECT_THROW((void)texelUtilization(aux, allReceivers(1), 0, 0), std::invalid_argument);
    EXPECT_THROW((void)texelUtilization(aux, allReceivers(1), 0, 16385), std::invalid_argument);
    EXPECT_THROW((void)texelUsageMask(aux, allReceivers(1), 0, -4), std::invalid_argument);
}

// The one percentile and median of the project (geometry/analysis/statistics.h).
TEST(Statistics, NearestRankPercentileAndMedian) {
    std::vector<double> twenty(20);
    for (int i = 0; i < 20; ++i) twenty[i] = 20 - i; // 20 … 1
    // 0.95·20 is 19.000000000000004 in doubles; the 19th smallest is still the nearest rank.
    EXPECT_EQ(percentile(std::span(twenty), 95), 19.0);
    EXPECT_EQ(percentile(std::span(twenty), 50), 10.0);
    EXPECT_EQ(percentile(std::span(twenty), 100), 20.0);
    EXPECT_EQ(percentile(std::span(twenty), 0), 1.0);
    std::vector<float> odd{3.f, 1.f, 2.f}, even{4.f, 1.f, 3.f, 2.f};
    EXPECT_EQ(median(std::span(odd)), 2.0);
    EXPECT_EQ(median(std::span(even)), 2.5);
    std::vector<double> none;
    EXPECT_TRUE(std::isnan(percentile(std::span(none), 50)));
    EXPECT_TRUE(std::isnan(median(std::span(none))));
}

// Pixels with a singular J carry the shader's cap, not a measurement: counted apart, left out of
// the mean, the percentiles and the maximum.
TEST(Metrics, SingularPixelsDoNotChangeTheFigures) {
    const std::vector<float> m{1.f, 2.f, 3.f, 4.f};
    const std::vector<uint8_t> all(4, 1);
    const AliasingStats plain = aliasingStats(m, all);
    std::vector<float> withCap = m;
    withCap.insert(withCap.end(), {1e10f, kSingularM});
    const AliasingStats capped = aliasingStats(withCap, std::vector<uint8_t>(6, 1));
    EXPECT_EQ(capped.mean, plain.mean);
    EXPECT_EQ(capped.p95, plain.p95);
    EXPECT_EQ(capped.max, 4.0);
    EXPECT_EQ(capped.count, 4u);
    EXPECT_DOUBLE_EQ(capped.singular, 2.0 / 6.0);
    EXPECT_EQ(plain.singular, 0.0);
}
