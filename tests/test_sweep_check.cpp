// The rules of `sweep gamma --check` on hand-made rows, and sweep.csv round trips
// (app/sweep_check.h): each rule fails on a deliberately broken input and passes a clean one.
#include "app/sweep_check.h"
#include "app/sweep_command.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using app::SweepRecord;

namespace {

SweepRecord row(double angle, const std::string& method, double p95, double p95Uniform = 100) {
    SweepRecord r;
    r.angleDeg = angle;
    r.method = method;
    r.nPrime = method == "uniform" ? INFINITY : 20;
    r.nPrimeMin = r.nPrime;
    r.p95 = p95;
    r.max = 10 * p95;
    r.p50 = p95 / 2;
    r.mean = p95 / 2;
    r.gammaDeg = std::min(angle, 180 - angle);
    r.lambda = 0.01;
    r.receivers = 5000;
    r.clippedCasters = 0;
    r.falseLitClipped = 0;
    r.falseLit = 0.05;
    r.falseShadow = 0.1;
    r.p95Uniform = p95Uniform;
    return r;
}

/// A clean sweep: lispsm's gain over uniform changes smoothly.
std::vector<SweepRecord> clean() {
    std::vector<SweepRecord> rows;
    for (int a = 0; a <= 180; a += 15) {
        rows.push_back(row(a, "uniform", 100));
        rows.push_back(row(a, "lispsm", 10 + a / 10.0));
    }
    return rows;
}

/// clean() steps 15°: judge continuity at that step (the default only judges steps up to 1°).
app::SweepThresholds at15() {
    app::SweepThresholds t;
    t.continuityStepDeg = 15;
    return t;
}

bool mentions(const std::vector<std::string>& failures, const std::string& a, const std::string& b) {
    for (const auto& f : failures)
        if (f.find(a) != std::string::npos && f.find(b) != std::string::npos) return true;
    return false;
}

} // namespace

TEST(SweepCheck, CleanSweepPasses) { EXPECT_TRUE(app::checkSweep(clean(), at15()).empty()); }

TEST(SweepCheck, NaNAndInfFailButUniformNPrimeIsInfinity) {
    auto rows = clean();
    rows[3].p95 = NAN;              // lispsm at 15°
    rows[5].falseShadow = INFINITY; // lispsm at 30°
    rows[7].nPrime = -INFINITY;     // lispsm at 45°
    const auto f = app::checkSweep(rows);
    EXPECT_TRUE(mentions(f, "method lispsm at 15.00 deg", "p95 is nan"));
    EXPECT_TRUE(mentions(f, "method lispsm at 30.00 deg", "false_shadow is inf"));
    EXPECT_TRUE(mentions(f, "method lispsm at 45.00 deg", "n_prime is -inf"));
    for (const auto& line : f) EXPECT_EQ(line.find("method uniform"), std::string::npos) << line;
}

TEST(SweepCheck, GainJumpFailsForContinuityMethodsOnly) {
    auto rows = clean();
    rows[9].p95 = 60; // lispsm at 60°: gain 0.145 at 45° → 0.6 (4.14×) → 0.175 at 75° (3.43×)
    auto f = app::checkSweep(rows, at15());
    EXPECT_TRUE(mentions(f, "method lispsm at 60.00 deg", "jumped 4.14x"));
    EXPECT_TRUE(mentions(f, "method lispsm at 75.00 deg", "jumped 3.43x")) << "and back down";
    EXPECT_EQ(f.size(), 2u);
    // The same jump of p95 together with uniform's is the scene, not the warp.
    rows[9].p95Uniform = 400;
    EXPECT_TRUE(app::checkSweep(rows, at15()).empty());
    // psm promises nothing: the same jump passes.
    rows = clean();
    for (auto& r : rows)
        if (r.method == "lispsm") r.method = "psm";
    rows[9].p95 = 60;
    EXPECT_TRUE(app::checkSweep(rows, at15()).empty());
    // Steps beyond continuityStepDeg (1° by default), and rows below minReceivers, are not judged.
    rows = clean();
    rows[9].p95 = 60;
    EXPECT_TRUE(app::checkSweep(rows).empty());
    rows[9].receivers = 10;
    EXPECT_TRUE(app::checkSweep(rows, at15()).empty());
    EXPECT_FALSE(app::promisesContinuity("psm"));
    EXPECT_FALSE(app::promisesContinuity("uniform"));
    EXPECT_TRUE(app::promisesContinuity("lispsm"));
    EXPECT_TRUE(app::promisesContinuity("glispsm"));
    EXPECT_TRUE(app::promisesContinuity("gmnpr"));
    // A p95 at the shader's cap for a singular J (1e10) is not judged, for the method or uniform.
    rows = clean();
    rows[9].p95 = 1e10;
    EXPECT_TRUE(app::checkSweep(rows, at15()).empty());
    rows = clean();
    rows[8].p95 = rows[9].p95Uniform = 1e10;
    EXPECT_TRUE(app::checkSweep(rows, at15()).empty());
    // Nor is a frame where more than 5 % of the receivers have a singular J (their m is left out
    // of p95, which then describes a different set of pixels).
    rows = clean();
    rows[9].p95 = 60;
    rows[9].singular = 0.2;
    EXPECT_TRUE(app::checkSweep(rows, at15()).empty());
    rows[9].singular = 0.01;
    EXPECT_FALSE(app::checkSweep(rows, at15()).empty());
    // At 1° steps the default applies: a 3.5× change of the gain fails.
    std::vector<app::SweepRecord> fine{row(150, "uniform", 100), row(150, "gmnpr", 20), row(151, "uniform", 100),
                                       row(151, "gmnpr", 70)};
    f = app::checkSweep(fine);
    ASSERT_EQ(f.size(), 1u);
    EXPECT_TRUE(mentions(f, "method gmnpr at 151.00 deg", "jumped 3.50x")) << f[0];
}

TEST(SweepCheck, LostCastersAndGlErrorsFail) {
    auto rows = clean();
    rows[25].falseLitClipped = 0.04; // lispsm at 180°
    rows[25].clippedCasters = 0.2;
    rows[10].glErrors = 1; // uniform at 75°
    const auto f = app::checkSweep(rows, at15());
    EXPECT_TRUE(mentions(f, "method lispsm at 180.00 deg", "false_lit_clipped 0.0400 exceeds 0.0010"));
    EXPECT_TRUE(mentions(f, "method lispsm at 180.00 deg", "clipped_casters 0.2000"));
    EXPECT_TRUE(mentions(f, "method uniform at 75.00 deg", "GL error"));
    EXPECT_EQ(f.size(), 2u);
    rows[25].falseLitClipped = 0.001; // at the threshold: passes
    EXPECT_EQ(app::checkSweep(rows, at15()).size(), 1u);
    app::SweepThresholds strict = at15();
    strict.maxFalseLitClipped = 0;
    EXPECT_EQ(app::checkSweep(rows, strict).size(), 2u);
}

TEST(SweepCheck, CsvRoundTripsAndStartsWithTheAgreedColumns) {
    EXPECT_EQ(app::sweepCsvHeader().rfind("angle_deg,method,n_prime,p95,max,false_lit,false_shadow,", 0), 0u);
    auto rows = clean();
    rows[1].p95 = 1.0 / 3.0;
    std::string text = app::sweepCsvHeader() + "\n";
    for (const auto& r : rows) text += app::sweepCsvRow(r) + "\n";
    const auto back = app::parseSweepCsv(text);
    ASSERT_EQ(back.size(), rows.size());
    EXPECT_EQ(back[1].p95, 1.0 / 3.0) << "shortest round-trip formatting";
    EXPECT_TRUE(std::isinf(back[0].nPrime));
    EXPECT_EQ(back[1].method, "lispsm");
    EXPECT_EQ(back[5].p95Uniform, 100);
}

// A sweep.csv written before the `singular` column existed still reads (as 0).
TEST(SweepCheck, CsvWithoutTheSingularColumnReads) {
    std::string text = app::sweepCsvHeader() + "\n";
    for (const auto& r : clean()) text += app::sweepCsvRow(r) + "\n";
    std::string header = text.substr(0, text.find('\n'));
    ASSERT_EQ(header.substr(header.size() - 9), ",singular");
    std::string old;
    for (size_t start = 0; start < text.size();) {
        const size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end - start);
        old += line.substr(0, line.rfind(',')) + "\n"; // drop the last column
        start = end + 1;
    }
    const auto rows = app::parseSweepCsv(old);
    ASSERT_EQ(rows.size(), clean().size());
    EXPECT_EQ(rows[0].singular, 0.0);
}

TEST(SweepCheck, BrokenCsvIsAOneLineError) {
    EXPECT_THROW((void)app::parseSweepCsv(""), std::runtime_error);
    EXPECT_THROW((void)app::parseSweepCsv("angle_deg,method\n0,uniform\n"), std::runtime_error); // missing columns
    const std::string header = app::sweepCsvHeader() + "\n";
    EXPECT_THROW((void)app::parseSweepCsv(header + "0,uniform,1\n"), std::runtime_error); // short row
    std::string bad = app::sweepCsvRow(row(0, "uniform", 1));
    bad.replace(bad.find(",uniform,") + 9, 3, "abc");
    try {
        (void)app::parseSweepCsv(header + bad + "\n");
        ADD_FAILURE() << "parsed a non-number";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
}

TEST(SweepAngles, RangeStepAndLimits) {
    auto a = app::sweepAngles(0, 180, 15);
    ASSERT_EQ(a.size(), 13u);
    EXPECT_EQ(a.front(), 0);
    EXPECT_EQ(a.back(), 180);
    a = app::sweepAngles(10, 20, 4); // 10, 14, 18 and the end itself
    EXPECT_EQ(a, (std::vector<double>{10, 14, 18, 20}));
    EXPECT_EQ(app::sweepAngles(90, 90, 1), std::vector<double>{90});
    EXPECT_EQ(app::sweepAngles(0, 180, 0.05).size(), 3601u);
    EXPECT_EQ(app::sweepAngles(0, 180, 0.1).back(), 180.0) << "no drift";
    EXPECT_THROW((void)app::sweepAngles(0, 180, 0), std::invalid_argument);
    EXPECT_THROW((void)app::sweepAngles(0, 180, -1), std::invalid_argument);
    EXPECT_THROW((void)app::sweepAngles(0, 180, NAN), std::invalid_argument);
    EXPECT_THROW((void)app::sweepAngles(-1, 180, 1), std::invalid_argument);
    EXPECT_THROW((void)app::sweepAngles(0, 181, 1), std::invalid_argument);
    EXPECT_THROW((void)app::sweepAngles(100, 90, 1), std::invalid_argument);
    EXPECT_THROW((void)app::sweepAngles(0, 180, 0.01), std::invalid_argument) << "too many angles";
    EXPECT_THROW((void)app::sweepAngles(0, 180, 1e-300), std::invalid_argument);
}
