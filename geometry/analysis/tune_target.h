#pragma once
// What `tune` must reach and what a measurement scores against it (docs/design.md §4 "Tuning"):
// the target, a configuration's figures, how far they miss. Pure.
#include "geometry/analysis/inspection.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geometry::analysis {

/// What tune must reach: each given figure at or below its value.
struct TuneTarget {
    std::optional<double> p95;           // aliasing m, 95th percentile
    std::optional<double> interior;      // interior false shadow + interior false lit (fractions)
    std::optional<double> edge;          // edge error (fraction)
    std::optional<double> misclassified; // false shadow + false lit at the pixel centre (fraction)
    std::optional<double> soft;          // soft_mean_abs: mean |s − v| against the sun's disk (needs its size)
    std::optional<double> umbra;         // umbra_light: mean s in the truth's umbra (light bleeding, leaks)
    [[nodiscard]] bool empty() const noexcept {
        return !p95 && !interior && !edge && !misclassified && !soft && !umbra;
    }
};

/// "p95=2,interior=0.001": keys p95, interior, edge, misclassified, soft, umbra, each once, values finite and
/// ≥ 0. Throws std::invalid_argument (one line, naming --target) otherwise.
[[nodiscard]] TuneTarget parseTuneTarget(std::string_view text);
/// The target as parseTuneTarget reads it back.
[[nodiscard]] std::string formatTuneTarget(const TuneTarget& target);

/// One configuration's figures (over all views: the worst accuracy, the summed time).
struct TuneFigures {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    double p95 = kNaN, interior = kNaN, edge = kNaN, misclassified = kNaN, soft = kNaN, umbra = kNaN;
    double frameMs = kNaN;    // median GPU frame time (CPU when the GPU timer gave nothing)
    uint64_t memoryBytes = 0; // shadow-map memory
};

/// The figures of one measured frame with truth (addTruth); NaN accuracy without it.
[[nodiscard]] TuneFigures tuneFigures(const Inspection& in, double frameMs, uint64_t memoryBytes) noexcept;
/// Several views as one: the worst of each accuracy figure, the summed time, the largest memory.
[[nodiscard]] TuneFigures combineViews(const std::vector<TuneFigures>& views) noexcept;

/// How far figures miss the target: Σ over its keys of max(0, log2((value + ε) / (target + ε)))
/// (ε 1e-4 for fractions, 1e-2 for p95); 0 when met, +∞ when a needed figure is NaN.
[[nodiscard]] double targetViolation(const TuneFigures& f, const TuneTarget& target) noexcept;
/// The worst of (value + ε) / (target + ε) over the target's keys: ≤ 1 when met (the tune chart's y);
/// +∞ when a needed figure is NaN.
[[nodiscard]] double targetRatio(const TuneFigures& f, const TuneTarget& target) noexcept;
/// The target's keys that `f` misses, as "edge 0.031 > 0.02", comma-separated ("" when met).
[[nodiscard]] std::string describeMisses(const TuneFigures& f, const TuneTarget& target);

/// -1 when `a` is cheaper, 1 when `b` is, 0 for a tie: median frame time (within 10 % a tie; NaN
/// is dearest), then shadow-map memory.
[[nodiscard]] int compareTuneCost(const TuneFigures& a, const TuneFigures& b) noexcept;

/// "a,b,,c" → {"a", "b", "", "c"}: the comma lists of --target and --space.
[[nodiscard]] std::vector<std::string_view> splitCommas(std::string_view text);

} // namespace geometry::analysis
