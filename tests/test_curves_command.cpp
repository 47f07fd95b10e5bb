// `shadowscope curves`: the CSV tables hold the docs/design.md §3 reference values, the SVG charts have a
// line and a legend entry per series, bad input gives a one-line error; and the chart axis ticks
// (ui/charts/chart.h) are round numbers.
#include "cli_test_util.h"
#include "ui/charts/chart.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using CurvesResult = testutil::CommandResult;
using testutil::runShadowscope;

fs::path curvesDir(const std::string& name) { return testutil::freshDir("curves_" + name); }

const std::string kFrustum = "curves --near 1 --far 100 --fov-y 60 --gamma-step 5";

/// Runs curves with the reference frustum plus `extra`, expecting success; returns the folder.
fs::path runCurvesInto(const std::string& name, const std::string& extra = "") {
    const fs::path dir = curvesDir(name);
    const CurvesResult r = runShadowscope(kFrustum + " " + extra + " --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return dir;
}

struct Csv {
    std::string header;
    std::vector<std::vector<std::string>> rows;
};

Csv readCsv(const fs::path& path) {
    Csv csv;
    std::ifstream in(path);
    std::getline(in, csv.header);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
        csv.rows.push_back(cells);
    }
    return csv;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

size_t countOf(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

} // namespace

TEST(CurvesCommand, WarpCsvHoldsTheReferenceValues) {
    const fs::path dir = curvesDir("warp");
    const CurvesResult r = runShadowscope(kFrustum + " --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* file : {"warp.csv", "error.csv", "splits.csv", "warp.svg", "error.svg", "splits.svg"})
        EXPECT_NE(r.output.find((dir / file).string()), std::string::npos) << "prints the paths it wrote: " << file;

    const Csv csv = readCsv(dir / "warp.csv");
    EXPECT_EQ(csv.header, "gamma_deg,method,n_prime,lambda");
    ASSERT_EQ(csv.rows.size(), 19u * 5u); // γ = 0, 5, …, 90 × five methods
    const std::array<std::string, 5> methods{"uniform", "psm", "lispsm", "glispsm", "gmnpr"};
    std::map<std::pair<double, std::string>, std::pair<std::string, std::string>> byKey;
    for (size_t i = 0; i < csv.rows.size(); ++i) {
        const auto& row = csv.rows[i];
        ASSERT_EQ(row.size(), 4u) << i;
        EXPECT_DOUBLE_EQ(std::stod(row[0]), 5.0 * double(i / 5)) << "γ ascending by the step";
        EXPECT_EQ(row[1], methods[i % 5]) << "methods in order";
        byKey[{std::stod(row[0]), row[1]}] = {row[2], row[3]};
        if (row[1] == "uniform") {
            EXPECT_EQ(row[2], "inf") << i;
            EXPECT_EQ(std::stod(row[3]), 0.0) << i;
        }
    }
    // docs/design.md §3.2 reference: n'₁(90°) = n + √(fn) = 11; GMNPR λ₁(90°) = 11/99.
    const double glispsm90 = std::stod(byKey[{90.0, "glispsm"}].first);
    const double gmnprLambda90 = std::stod(byKey[{90.0, "gmnpr"}].second);
    EXPECT_NEAR(glispsm90, 11.0, 1e-6);
    EXPECT_NEAR(gmnprLambda90, 11.0 / 99.0, 1e-6);
    // Light ∥ view: every warp converges to uniform.
    for (const char* m : {"lispsm", "glispsm", "gmnpr"}) {
        const std::string atZero = byKey[{0.0, m}].first;
        EXPECT_EQ(atZero, "inf") << m;
    }
    // Away from γ = 0 every warp is finite (a warp that silently fell back to uniform would show here).
    for (const char* m : {"psm", "lispsm", "glispsm", "gmnpr"})
        for (double g = 5; g <= 90; g += 5) {
            const double nPrime = std::stod(byKey[{g, m}].first);
            EXPECT_TRUE(std::isfinite(nPrime)) << m << " " << g;
        }
}

TEST(CurvesCommand, GammaSamplesAlwaysEndAtNinety) {
    const fs::path dir = curvesDir("step7");
    const CurvesResult r = runShadowscope("curves --near 1 --far 100 --fov-y 60 --gamma-step 7 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Csv csv = readCsv(dir / "warp.csv");
    ASSERT_EQ(csv.rows.size(), 14u * 5u); // 0, 7, …, 84, then 90
    EXPECT_EQ(csv.rows.back()[0], "90");
    EXPECT_EQ(csv.rows[csv.rows.size() - 6][0], "84");
}

TEST(CurvesCommand, ErrorCsvLispsmIsBalancedAtNinetyDegrees) {
    const fs::path dir = runCurvesInto("error", "--gamma 90");
    const Csv csv = readCsv(dir / "error.csv");
    EXPECT_EQ(csv.header, "z,method,m_z");
    ASSERT_GE(csv.rows.size(), 5u * 50u);
    ASSERT_EQ(csv.rows.size() % 5, 0u);
    std::vector<std::pair<double, double>> lispsm; // (z, m_z)
    for (const auto& row : csv.rows) {
        ASSERT_EQ(row.size(), 3u);
        const double mz = std::stod(row[2]);
        EXPECT_TRUE(std::isfinite(mz) && mz > 0) << row[1] << " at z = " << row[0];
        if (row[1] == "lispsm") lispsm.emplace_back(std::stod(row[0]), mz);
    }
    ASSERT_EQ(lispsm.size(), csv.rows.size() / 5);
    EXPECT_DOUBLE_EQ(lispsm.front().first, 1.0);
    EXPECT_DOUBLE_EQ(lispsm.back().first, 100.0);
    for (size_t i = 1; i < lispsm.size(); ++i) EXPECT_GT(lispsm[i].first, lispsm[i - 1].first) << "z increases";
    // LiSPSM's n' = n + √(fn) is the optimum of eq 12 at γ = 90°: m_z(n) = m_z(f) (docs/design.md §3.3).
    EXPECT_NEAR(lispsm.front().second / lispsm.back().second, 1.0, 1e-6);
}

TEST(CurvesCommand, ErrorCsvDependsOnGamma) {
    const Csv at30 = readCsv(runCurvesInto("error30", "--gamma 30") / "error.csv");
    const Csv at90 = readCsv(runCurvesInto("error90", "--gamma 90") / "error.csv");
    ASSERT_EQ(at30.rows.size(), at90.rows.size());
    ASSERT_FALSE(at30.rows.empty());
    EXPECT_NE(at30.rows[2][2], at90.rows[2][2]) << "--gamma must change the lispsm curve";
}

TEST(CurvesCommand, SplitsCsvPartitionsTheFrustumForEveryScheme) {
    const fs::path dir = runCurvesInto("splits", "--set splits.count=4");
    const Csv csv = readCsv(dir / "splits.csv");
    EXPECT_EQ(csv.header, "gamma_deg,scheme,i,near,far");
    ASSERT_EQ(csv.rows.size(), 19u * 5u * 4u);
    std::map<std::pair<double, std::string>, std::vector<std::pair<double, double>>> groups;
    for (const auto& row : csv.rows) {
        ASSERT_EQ(row.size(), 5u);
        auto& g = groups[{std::stod(row[0]), row[1]}];
        EXPECT_EQ(std::stoi(row[2]), static_cast<int>(g.size())) << "i is 0-based and in order";
        g.emplace_back(std::stod(row[3]), std::stod(row[4]));
    }
    ASSERT_EQ(groups.size(), 19u * 5u);
    for (const char* scheme : {"uniform", "log", "practical", "pssm", "adaptive"})
        EXPECT_EQ(groups.count({45.0, scheme}), 1u) << scheme;
    for (const auto& [key, splits] : groups) {
        const std::string where = key.second + " at " + std::to_string(key.first);
        ASSERT_EQ(splits.size(), 4u) << where;
        EXPECT_DOUBLE_EQ(splits.front().first, 1.0) << where;
        EXPECT_DOUBLE_EQ(splits.back().second, 100.0) << where;
        for (size_t i = 0; i < splits.size(); ++i) {
            EXPECT_LT(splits[i].first, splits[i].second) << where << " split " << i;
            if (i > 0) {
                EXPECT_DOUBLE_EQ(splits[i].first, splits[i - 1].second) << where << " splits are contiguous";
            }
        }
    }
    // The adaptive scheme follows γ (Barroso eq 19): log at 90°, f_i/n_i = α = 2 at 0°.
    const double adaptiveC3AtZero = groups[{0.0, "adaptive"}][3].first;
    const double adaptiveC1AtNinety = groups[{90.0, "adaptive"}][1].first;
    EXPECT_NEAR(adaptiveC3AtZero, 50.0, 1e-9);
    EXPECT_NEAR(adaptiveC1AtNinety, std::pow(100.0, 0.25), 1e-9);
}

TEST(CurvesCommand, SvgChartsHaveALineAndLegendEntryPerSeries) {
    const fs::path dir = runCurvesInto("svg", "--set splits.count=4");
    const auto check = [&](const char* file, const std::vector<std::string>& names, size_t minLines) {
        const std::string svg = readText(dir / file);
        ASSERT_FALSE(svg.empty()) << file;
        EXPECT_TRUE(svg.rfind("<svg", 0) == 0 || svg.rfind("<?xml", 0) == 0) << file;
        EXPECT_NE(svg.find("</svg>"), std::string::npos) << file;
        EXPECT_GE(countOf(svg, "<polyline"), minLines) << file;
        for (const auto& name : names)
            EXPECT_NE(svg.find(">" + name), std::string::npos) << file << ": legend " << name;
        EXPECT_EQ(svg.find("nan"), std::string::npos) << file << ": no NaN coordinates";
        EXPECT_EQ(svg.find("inf\""), std::string::npos) << file << ": no infinite coordinates";
    };
    // warp.svg: uniform is n' = ∞ (not on a log axis), the four warps are lines.
    check("warp.svg", {"psm", "lispsm", "glispsm", "gmnpr", "γ (degrees)"}, 4);
    check("error.svg", {"uniform", "psm", "lispsm", "glispsm", "gmnpr", "z (eye depth)"}, 5);
    // splits.svg: a panel per scheme, each with the boundaries C0 … C4.
    check("splits.svg", {"uniform", "log", "practical", "pssm", "adaptive", "C0 = n", "C1", "C2", "C3", "C4 = f"},
          5u * 5u);
}

TEST(CurvesCommand, BadInputGivesOneLineErrorAndNonZeroExit) {
    const char* cases[] = {
        "curves --near 0 --far 100 --fov-y 60",
        "curves --near 1 --far 0.5 --fov-y 60",
        "curves --near 1 --far 100 --fov-y 200",
        "curves --near 1 --far 100 --fov-y 60 --gamma-step 0",
        "curves --near 1 --far 100 --fov-y 60 --gamma-step 91",
        "curves --near 1 --far 100 --fov-y 60 --gamma-step 1e-12",
        "curves --near 1 --far 100 --fov-y 60 --gamma 95",
        "curves --near 1 --far 100 --fov-y 60 --gamma -1",
        "curves --near 1 --far 100 --fov-y 60 --screen-res 0",
        "curves --near 1 --far 100 --fov-y 60 --map-res 0",
        "curves --near 1 --far 100 --fov-y 60 --set splits.count=9",
        "curves --near nan --far 100 --fov-y 60",
        "curves --far 100 --fov-y 60",
    };
    for (const char* args : cases) {
        const CurvesResult r = runShadowscope(std::string(args) + " --out " + curvesDir("bad").string());
        EXPECT_NE(r.exitCode, 0) << args;
        std::string text = r.output;
        while (!text.empty() && text.back() == '\n') text.pop_back();
        EXPECT_EQ(text.find('\n'), std::string::npos) << args << ": " << r.output;
        EXPECT_NE(text.find("error"), std::string::npos) << args << ": " << r.output;
    }
}

// ---- ui/charts/chart.h axis helpers -------------------------------------------------------------------

TEST(ChartAxes, LinearTicksAreRoundSteps) {
    const std::vector<double> ticks = ui::charts::niceTicks(0, 90, false);
    ASSERT_GE(ticks.size(), 3u);
    EXPECT_EQ(ticks.front(), 0.0);
    EXPECT_LE(ticks.back(), 90.0);
    const double step = ticks[1] - ticks[0];
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9)
        << step;
    for (size_t i = 1; i < ticks.size(); ++i) EXPECT_NEAR(ticks[i] - ticks[i - 1], step, 1e-9);
    EXPECT_GT(ticks.back() + step, 90.0) << "no round tick left out at the top";
    // Decimal steps come out as the decimal values, not as accumulated 0.1 + 0.2.
    const std::vector<double> small = ui::charts::niceTicks(0, 0.5, false, 6);
    ASSERT_EQ(small.size(), 6u);
    EXPECT_EQ(small[3], 0.3);
    EXPECT_EQ(ui::charts::formatTick(small[3]), "0.3");
}

TEST(ChartAxes, LogTicksArePowersOfTen) {
    EXPECT_EQ(ui::charts::niceTicks(1, 100, true), (std::vector<double>{1, 10, 100}));
    EXPECT_EQ(ui::charts::niceTicks(2, 20, true), (std::vector<double>{2, 5, 10, 20}));
    const std::vector<double> wide = ui::charts::niceTicks(1e-3, 1e9, true, 5);
    ASSERT_FALSE(wide.empty());
    EXPECT_LE(wide.size(), 5u);
    EXPECT_TRUE(ui::charts::niceTicks(0, 10, true).empty()) << "no log ticks through zero";
    EXPECT_EQ(ui::charts::formatTick(1e6), "1e6");
    EXPECT_EQ(ui::charts::formatTick(2.5e-5), "2.5e-5");
}

TEST(ChartAxes, RangesAndRuns) {
    const ui::charts::AxisRange log = ui::charts::niceRange(3, 4000, true);
    EXPECT_DOUBLE_EQ(log.lo, 1);
    EXPECT_DOUBLE_EQ(log.hi, 1e4);
    const ui::charts::AxisRange lin = ui::charts::niceRange(0.3, 87, false);
    EXPECT_DOUBLE_EQ(lin.lo, 0);
    EXPECT_DOUBLE_EQ(lin.hi, 90);
    EXPECT_DOUBLE_EQ(ui::charts::axisFraction(10, log, true), 0.25);

    ui::charts::Chart c;
    c.y.log = true;
    c.series.push_back({"s",
                        ui::charts::paletteColour(0),
                        {{0, 1}, {1, 2}, {2, INFINITY}, {3, 4}, {4, 80}, {5, -1}, {6, 3}},
                        ui::charts::SeriesStyle::Lines,
                        3.f,
                        {}});
    const auto runs = ui::charts::plottableRuns(c.series[0], false, true);
    ASSERT_EQ(runs.size(), 3u) << "∞ and non-positive (on a log axis) break the line";
    EXPECT_EQ(runs[0].size(), 2u);
    EXPECT_EQ(runs[1].size(), 2u);
    EXPECT_EQ(runs[2].size(), 1u);
    const ui::charts::AxisRange y = ui::charts::axisRange(c, false);
    EXPECT_DOUBLE_EQ(y.lo, 1);
    EXPECT_DOUBLE_EQ(y.hi, 100) << "∞ is not part of the range, 80 is";
    c.y.max = 1000.0;
    EXPECT_DOUBLE_EQ(ui::charts::axisRange(c, false).hi, 1000) << "a fixed bound wins";
    // Less than a decade of data keeps a linear-style range rather than a whole decade.
    const ui::charts::AxisRange narrow = ui::charts::niceRange(1, 1.0001, true);
    EXPECT_GE(narrow.lo, 0.99);
    EXPECT_LE(narrow.hi, 1.01);
    EXPECT_GE(ui::charts::niceTicks(narrow.lo, narrow.hi, true).size(), 2u);
}
