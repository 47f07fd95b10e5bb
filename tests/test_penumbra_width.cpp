// The penumbra-width estimator (geometry/analysis/penumbra_width.h) on synthetic pixels: a grid of
// receivers on the ground under a horizontal straight edge, their lit fraction made up from the
// analytic disk profile, a hard step or a disk twice as wide; too few pixels; the constant W_a.
#include "geometry/analysis/penumbra_width.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace geometry::analysis;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kHeight = 2.f; // of the edge above the ground

/// The visible fraction of a unit disk cut by a straight edge at normalized offset x, written out
/// again here so the test does not check the library against itself.
double disk(double x) {
    if (x <= -1.0) return 0.0;
    if (x >= 1.0) return 1.0;
    return 0.5 + (x * std::sqrt(1.0 - x * x) + std::asin(x)) / kPi;
}

/// Receivers on the ground y = 0 under the edge from (0, h, −10) to (0, h, 10), the sun at
/// `elevationDeg` above the horizon in the x–y plane (perpendicular to the edge), on the −x side
/// when below 90°. Each pixel's offset u = d / D (the edge's offset from the ray towards the sun's
/// centre, over the distance along it), found in the x–y plane alone; f = profile(u).
struct Pixels {
    std::vector<glm::vec3> positions;
    std::vector<float> lit;
    std::vector<uint8_t> receiver;
    glm::vec3 l{0.f};
    std::array<glm::vec3, 2> edge{glm::vec3(0.f, kHeight, -10.f), glm::vec3(0.f, kHeight, 10.f)};
};

Pixels grid(double elevationDeg, float spacing, const std::function<double(double)>& profile) {
    Pixels px;
    const double e = elevationDeg * kPi / 180.0;
    const glm::dvec2 toSun(-std::cos(e), std::sin(e)); // x, y
    px.l = -glm::vec3(float(toSun.x), float(toSun.y), 0.f);
    // The ground point whose ray towards the sun's centre meets the edge.
    const double x0 = -double(kHeight) * toSun.x / toSun.y;
    for (float z = -7.5f; z <= 7.5f; z += 0.5f)
        for (float dx = -0.2f; dx <= 0.2f; dx += spacing) {
            const glm::dvec2 w(0.0 - (x0 + dx), double(kHeight)); // ground point → edge
            const double D = glm::dot(w, toSun), d = toSun.x * w.y - toSun.y * w.x;
            px.positions.emplace_back(float(x0 + dx), 0.f, z);
            px.lit.push_back(float(profile(d / D)));
            px.receiver.push_back(1);
        }
    return px;
}

double widthError(const Pixels& px, double thetaRad) {
    return penumbraWidth(px.positions, px.lit, px.receiver, px.l, px.edge, thetaRad).error;
}

const double kTheta = 2.0 * kPi / 180.0;
const double kR = std::tan(0.5 * kTheta); // R'

} // namespace

TEST(PenumbraWidth, TheReferenceIntegralIsWhatTheHeaderSays) {
    constexpr int kSteps = 200000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double x = -1.0 + (i + 0.5) * (2.0 / kSteps);
        sum += 4.0 * disk(x) * (1.0 - disk(x)) * (2.0 / kSteps);
    }
    EXPECT_NEAR(kDiskEdgeWidth, sum, 1e-8);
    for (const double x : {-1.5, -1.0, -0.7, -0.2, 0.0, 0.3, 0.9, 1.0, 2.0})
        EXPECT_NEAR(diskEdgeVisibility(x), disk(x), 1e-12) << x;
}

// f = the disk's own profile: the error is the binning's alone (+0.5 %). The sign of u does not
// matter (4f(1 − f) is symmetric), and neither does the sun's elevation.
TEST(PenumbraWidth, TheAnalyticProfileMeasuresZero) {
    for (const double elevation : {90.0, 60.0, 35.0}) {
        for (const double sign : {1.0, -1.0}) {
            const Pixels px = grid(elevation, 0.0005f, [&](double u) { return disk(sign * u / kR); });
            const PenumbraWidth w = penumbraWidth(px.positions, px.lit, px.receiver, px.l, px.edge, kTheta);
            EXPECT_NEAR(w.error, 0.0, 0.05) << elevation << "°";
            EXPECT_GE(w.fewestInBin, kMinPixelsPerPenumbraBin);
            EXPECT_NEAR(w.reference, kR * kDiskEdgeWidth, 1e-12);
            std::printf("elevation %.0f°, sign %+.0f: error %+.4f over %zu pixels (fewest in a bin %zu)\n", elevation,
                        sign, w.error, w.pixels, w.fewestInBin);
        }
    }
}

TEST(PenumbraWidth, AHardEdgeMeasuresMinusOne) {
    const Pixels px = grid(60.0, 0.0005f, [](double u) { return u >= 0.0 ? 1.0 : 0.0; });
    const double error = widthError(px, kTheta);
    EXPECT_NEAR(error, -1.0, 0.02);
    std::printf("hard step: error %+.4f\n", error);
}

// A disk of twice the radius: W doubles, less the tails beyond the ±1.5R' window (+0.906 with
// continuous u).
TEST(PenumbraWidth, ADiskTwiceAsWideMeasuresPlusOne) {
    const Pixels px = grid(60.0, 0.0005f, [](double u) { return disk(u / (2.0 * kR)); });
    const double error = widthError(px, kTheta);
    EXPECT_NEAR(error, 1.0, 0.1);
    std::printf("doubled R': error %+.4f\n", error);
}

// Pixels 1 cm apart across a penumbra 7 cm wide: some of the 16 bins get none.
TEST(PenumbraWidth, TooFewPixelsAcrossThePenumbraIsNaN) {
    const Pixels coarse = grid(90.0, 0.01f, [](double u) { return disk(u / kR); });
    const PenumbraWidth w = penumbraWidth(coarse.positions, coarse.lit, coarse.receiver, coarse.l, coarse.edge, kTheta);
    EXPECT_TRUE(std::isnan(w.error));
    EXPECT_LT(w.fewestInBin, kMinPixelsPerPenumbraBin);
    EXPECT_GT(w.pixels, 0u);
    // A point sun has no penumbra to measure; no receivers, nothing.
    const Pixels fine = grid(90.0, 0.0005f, [](double u) { return disk(u / kR); });
    EXPECT_TRUE(std::isnan(widthError(fine, 0.0)));
    std::vector<uint8_t> none(fine.receiver.size(), 0);
    EXPECT_TRUE(std::isnan(penumbraWidth(fine.positions, fine.lit, none, fine.l, fine.edge, kTheta).error));
    EXPECT_THROW((void)penumbraWidth(fine.positions, {}, fine.receiver, fine.l, fine.edge, kTheta),
                 std::invalid_argument);
}

// Only the middle 80 % of the edge, and only receivers below it, count: wrong values elsewhere
// change nothing.
TEST(PenumbraWidth, PixelsPastTheEdgesEndsOrAboveItAreLeftOut) {
    const Pixels px = grid(90.0, 0.0005f, [](double u) { return disk(u / kR); });
    const double clean = widthError(px, kTheta);
    Pixels noisy = px;
    for (size_t i = 0; i < px.positions.size(); ++i) {
        const glm::vec3 p = px.positions[i];
        noisy.positions.push_back(p + glm::vec3(0.f, 0.f, p.z > 0.f ? 8.5f : -8.5f)); // |z| > 8 of the 10
        noisy.lit.push_back(0.5f);
        noisy.receiver.push_back(1);
        noisy.positions.push_back(p + glm::vec3(0.f, 2.f * kHeight, 0.f)); // above the edge
        noisy.lit.push_back(0.5f);
        noisy.receiver.push_back(1);
        noisy.positions.push_back(p);
        noisy.lit.push_back(0.5f);
        noisy.receiver.push_back(0); // not a receiver
    }
    EXPECT_EQ(widthError(noisy, kTheta), clean);
}
