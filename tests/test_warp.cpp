// Warp parameters against docs/design.md §3.2's reference values (n = 1, f = 100, φ = π/6).
#include "geometry/shadow/analytic_error.h"
#include "geometry/shadow/settings.h"
#include "geometry/shadow/warp.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace geometry::shadow;

namespace {
constexpr double n = 1, f = 100, phi = std::numbers::pi / 6, half = std::numbers::pi / 2;
double deg(double d) { return d * std::numbers::pi / 180.0; }
/// Every declared warp method (a new one is tested the day it is declared).
std::vector<WarpMethod> allMethods() {
    std::vector<WarpMethod> out;
    for (const auto name : findSetting("warp.method")->choices) {
        ShadowSettings s;
        applySetting(s, "warp.method", name);
        out.push_back(s.warp.method);
    }
    return out;
}
} // namespace

TEST(Warp, GlispsmReferenceValues) {
    EXPECT_NEAR(glm::degrees(gammaLimit(n, f, phi)), 30.5, 0.05);
    EXPECT_NEAR(nPrimeGlispsm1(n, f, phi, half), 11.0, 1e-6); // n + √(fn), the classic LiSPSM value
    EXPECT_NEAR(nPrimeGlispsm1(n, f, phi, gammaLimit(n, f, phi)), 5.09, 0.01);
    EXPECT_NEAR(nPrimeGlispsm(n, f, phi, half), 11.0, 1e-6);
    EXPECT_GT(nPrimeGlispsm(n, f, phi, 1e-6), 1e6); // → ∞ as γ → 0
}

TEST(Warp, GmnprReferenceValues) {
    EXPECT_NEAR(lambdaGmnpr(n, f, phi, half), 11.0 / 99.0, 1e-6);
    EXPECT_NEAR(lambdaGmnpr(n, f, phi, phi), 0.05, 1e-6); // √(fn) / (2f)
    EXPECT_NEAR(nPrimeGmnpr(n, f, phi, half), 11.0, 1e-6);
}

TEST(Warp, ContinuityAtTheSwitchingAngles) {
    const double gLim = gammaLimit(n, f, phi);
    for (auto falloff : {GlispsmFalloff::Eq18, GlispsmFalloff::Eq17})
        EXPECT_NEAR(nPrimeGlispsm(n, f, phi, gLim - 1e-9, falloff), nPrimeGlispsm(n, f, phi, gLim + 1e-9, falloff),
                    1e-6);
    EXPECT_NEAR(lambdaGmnpr(n, f, phi, phi - 1e-9), lambdaGmnpr(n, f, phi, phi + 1e-9), 1e-6);
    EXPECT_NEAR(nPrimeGmnpr(n, f, phi, phi - 1e-9), nPrimeGmnpr(n, f, phi, phi + 1e-9), 1e-6);
    EXPECT_NEAR(warpDepthRange(n, f, phi, phi - 1e-9), warpDepthRange(n, f, phi, phi + 1e-9), 1e-6);
}

TEST(Warp, BarrosoAndZhangAgreeAbovePhi) {
    for (double g = deg(31); g <= half; g += deg(1))
        EXPECT_NEAR(nPrimeGlispsm1(n, f, phi, g), nPrimeGmnpr(n, f, phi, g), 1e-9) << glm::degrees(g);
}

TEST(Warp, LispsmAtNinetyDegreesBalancesNearAndFarError) {
    const double np = warpNPrime({WarpMethod::Lispsm}, n, f, phi, half, f - n);
    EXPECT_NEAR(np, 11.0, 1e-9);
    const ErrorModel m{n, f, phi, half, 1080, 2048};
    EXPECT_NEAR(aliasingErrorZ(m, np, n) / aliasingErrorZ(m, np, f), 1.0, 1e-9);
    // Uniform is far worse near than far; PSM strength the other way round.
    EXPECT_GT(aliasingErrorZ(m, kUniform, n) / aliasingErrorZ(m, kUniform, f), 50.0);
    EXPECT_LT(aliasingErrorZ(m, n, n) / aliasingErrorZ(m, n, f), 0.1);
}

TEST(Warp, EveryMethodConvergesToUniformAsGammaGoesToZero) {
    for (auto method : allMethods()) {
        WarpParams p{method};
        EXPECT_EQ(warpNPrime(p, n, f, phi, 0.0, f - n), kUniform) << warpMethodName(method);
        const double tiny = warpNPrime(p, n, f, phi, 1e-7, f - n);
        EXPECT_GT(tiny, 1e5) << warpMethodName(method);
    }
}

TEST(Warp, FiniteAndPositiveForEveryAngleNeverNaN) {
    for (auto method : allMethods())
        for (auto falloff : {GlispsmFalloff::Eq18, GlispsmFalloff::Eq17})
            for (double g = -0.5; g <= 2.0; g += 0.001) { // outside [0, π/2] too: clamped
                WarpParams p{method, falloff};
                const double v = warpNPrime(p, n, f, phi, g, f - n);
                ASSERT_FALSE(std::isnan(v)) << warpMethodName(method) << " γ=" << g;
                ASSERT_GT(v, 0.0);
                const double lambda = lambdaFromNPrime(v, n, f, phi, g);
                ASSERT_TRUE(std::isfinite(lambda));
            }
    EXPECT_EQ(warpNPrime({WarpMethod::Lispsm}, n, f, phi, NAN, f - n), kUniform);
    EXPECT_EQ(warpNPrime({WarpMethod::Lispsm}, 0.0, f, phi, half, f), kUniform); // n ≤ 0: no warp
    EXPECT_EQ(warpNPrime({WarpMethod::Lispsm}, n, n, phi, half, 0.0), kUniform); // f ≤ n
}

TEST(Warp, WarpsWeakenMonotonicallyTowardsSmallGamma) {
    for (auto method : {WarpMethod::Lispsm, WarpMethod::Glispsm, WarpMethod::Gmnpr}) {
        double prev = warpNPrime({method}, n, f, phi, deg(1), f - n);
        for (double d = 2; d <= 25; d += 1) {
            const double v = warpNPrime({method}, n, f, phi, deg(d), f - n);
            EXPECT_LT(v, prev) << warpMethodName(method) << " at " << d;
            prev = v;
        }
    }
}

TEST(Warp, ManualAndMultiplier) {
    WarpParams p{WarpMethod::Manual};
    p.manualNPrime = 42;
    EXPECT_NEAR(warpNPrime(p, n, f, phi, half, f - n), 42.0, 1e-9);
    EXPECT_NEAR(warpNPrime(p, n, f, phi, deg(30), f - n), 84.0, 1e-9);
    WarpParams q{WarpMethod::Glispsm};
    q.multiplier = 3;
    EXPECT_NEAR(warpNPrime(q, n, f, phi, half, f - n), 33.0, 1e-9);
}

TEST(Warp, LispsmVisibleFarTightensTheWarp) {
    const double full = nPrimeLispsm(n, half, f - n);
    const double visible = nPrimeLispsm(n, half, f - n, 25.0);
    EXPECT_NEAR(visible, n + std::sqrt(n * 25.0), 1e-9);
    EXPECT_LT(visible, full);
}
