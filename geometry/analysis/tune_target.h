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
    std::optional<double> contact;       // contact_false_lit: shadow lost near contacts (peter-panning)
    std::optional<double> interiorAbs;   // interior_mean_abs: mean |s − c| inside lit or shadowed regions
    std::optional<double> edgeWidth;     // edge_width.texels: the wrong band across edges, in texels
    [[nodiscard]] bool empty() const noexcept {
        return !p95 && !interior && !edge && !misclassified && !soft && !umbra && !contact && !interiorAbs &&
               !edgeWidth;
    }
    /// The tightest target on a fraction of the receivers (interior, edge, misclassified, contact);
    /// nullopt without one: screening at half size must resolve a tenth of it (tuner.h).
    [[nodiscard]] std::optional<double> tightestFraction() const noexcept;
};

/// "p95=2,interior=0.001": keys p95, interior, edge, misclassified, soft, umbra, contact, interior_abs,
/// edge_width, each once, values finite and ≥ 0. Throws std::invalid_argument (one line, naming
/// --target) otherwise.
[[nodiscard]] TuneTarget parseTuneTarget(std::string_view text);
/// The target as parseTuneTarget reads it back.
[[nodiscard]] std::string formatTuneTarget(const TuneTarget& target);

/// One configuration's figures (over all views: the worst accuracy, the summed time).
struct TuneFigures {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    double p95 = kNaN, interior = kNaN, edge = kNaN, misclassified = kNaN, soft = kNaN, umbra = kNaN;
    double contact = kNaN, interiorAbs = kNaN, edgeWidth = kNaN;
    double costMs = kNaN;     // the cost model's (cost_model.h): what tune ranks by, the same on every run
    double frameMs = kNaN;    // measured: median GPU frame time (CPU when the GPU timer gave nothing); shown only
    uint64_t memoryBytes = 0; // shadow-map memory
};

/// The figures of one measured frame with truth (addTruth); NaN accuracy without it.
[[nodiscard]] TuneFigures tuneFigures(const Inspection& in, double costMs, double frameMs,
                                      uint64_t memoryBytes) noexcept;
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

/// -1 when `a` is cheaper, 1 when `b` is, 0 for a tie: the modelled cost (NaN is dearest), then
/// shadow-map memory. Never the measured time: the ranking is the same on every run.
[[nodiscard]] int compareTuneCost(const TuneFigures& a, const TuneFigures& b) noexcept;

/// "a,b,,c" → {"a", "b", "", "c"}: the comma lists of --target and --space.
[[nodiscard]] std::vector<std::string_view> splitCommas(std::string_view text);

} // namespace geometry::analysis
