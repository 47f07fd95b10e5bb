#include "geometry/shadow/splits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace geometry::shadow;

namespace {
constexpr double n = 1, f = 100, half = std::numbers::pi / 2;
}

TEST(Splits, EverySchemeStartsAtNearEndsAtFarAndIncreases) {
    for (auto scheme :
         {SplitScheme::Uniform, SplitScheme::Log, SplitScheme::Practical, SplitScheme::Pssm, SplitScheme::Adaptive})
        for (int k = 1; k <= 8; ++k)
            for (double g : {0.0, 0.3, 0.8, half}) {
                SplitParams p{k, scheme};
                const auto c = splitDistances(p, n, f, g);
                ASSERT_EQ(c.size(), size_t(k) + 1);
                EXPECT_EQ(c.front(), n);
                EXPECT_EQ(c.back(), f);
                for (int i = 1; i <= k; ++i) {
                    if (scheme == SplitScheme::Adaptive && g == 0.0 && k > 5)
                        EXPECT_GE(c[i], c[i - 1]); // α^(k−1) > f/n: leading splits clamp at n
                    else EXPECT_GT(c[i], c[i - 1]) << splitSchemeName(scheme) << " k=" << k << " γ=" << g;
                }
            }
}

TEST(Splits, KnownBoundaries) {
    const auto u = splitDistances({4, SplitScheme::Uniform}, n, f, half);
    EXPECT_NEAR(u[1], 25.75, 1e-9);
    const auto l = splitDistances({2, SplitScheme::Log}, n, f, half);
    EXPECT_NEAR(l[1], 10.0, 1e-9);
    SplitParams practical{2, SplitScheme::Practical};
    practical.lambda = 0.5;
    EXPECT_NEAR(splitDistances(practical, n, f, half)[1], 0.5 * 10.0 + 0.5 * 50.5, 1e-9);
    SplitParams pssm{3, SplitScheme::Pssm};
    pssm.ratio = 2;
    const auto g = splitDistances(pssm, n, f, half); // lengths 99/7, 2·99/7, 4·99/7
    EXPECT_NEAR(g[1] - g[0], 99.0 / 7.0, 1e-9);
    EXPECT_NEAR(g[2] - g[1], 2 * 99.0 / 7.0, 1e-9);
}

TEST(Splits, AdaptiveEqualsLogAtNinetyDegrees) {
    for (int k = 1; k <= 8; ++k) {
        SplitParams a{k, SplitScheme::Adaptive};
        a.alpha = 3;
        const auto ad = splitDistances(a, n, f, half);
        const auto lg = splitDistances({k, SplitScheme::Log}, n, f, half);
        for (int i = 0; i <= k; ++i) EXPECT_NEAR(ad[i], lg[i], 1e-9 * f) << "k=" << k << " i=" << i;
    }
}

TEST(Splits, AdaptiveAtZeroGammaHasRatioAlphaBeyondTheFirstSplit) {
    for (double alpha : {1.5, 2.0, 4.0}) {
        SplitParams a{4, SplitScheme::Adaptive};
        a.alpha = alpha;
        const auto c = splitDistances(a, n, f, 0.0);
        for (int i = 2; i <= 4; ++i) EXPECT_NEAR(c[i] / c[i - 1], alpha, 1e-9) << "split " << i;
    }
}

TEST(Splits, ResolutionFalloffHalvesPerSplit) {
    SplitParams p{4, SplitScheme::Pssm};
    EXPECT_EQ(splitResolution(p, 2048, 3), 2048);
    p.resolutionFalloff = true;
    EXPECT_EQ(splitResolution(p, 2048, 0), 2048);
    EXPECT_EQ(splitResolution(p, 2048, 1), 1024);
    EXPECT_EQ(splitResolution(p, 2048, 3), 256);
    // Memory of all maps ≤ 4/3 of the first (Zhang 003).
    double mem = 0;
    for (int i = 0; i < 8; ++i) mem += std::pow(splitResolution(p, 4096, i), 2);
    EXPECT_LE(mem, 4.0 / 3.0 * 4096.0 * 4096.0);
}

// Preconditions (geometry/scene/invariant.h) abort the checked build with the condition named, where
// a release build would once have clamped the split count to 1.
TEST(Splits, ABrokenPreconditionAbortsTheCheckedBuild) {
#ifndef SHADOWSCOPE_CHECKED
    GTEST_SKIP() << "preconditions are checked in the checked build (scripts/build-checked)";
#else
    geometry::shadow::SplitParams p;
    p.count = 0;
    EXPECT_DEATH((void)geometry::shadow::splitDistances(p, 1.0, 100.0, 0.0), "precondition failed: .*count >= 1");
    p.count = 2;
    EXPECT_DEATH((void)geometry::shadow::splitDistances(p, 1.0, 0.5, 0.0), "precondition failed: n > 0.0 && f > n");
#endif
}
