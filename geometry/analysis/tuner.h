#pragma once
// The search behind `shadowscope tune` and the dashboard's "Recommend" (docs/design.md §4 "Tuning"): the
// cheapest shadow settings that meet an accuracy target. Pure and incremental (ask/tell): next()
// says which configuration to measure at which size, report() hands back its figures, so the
// command line loops and the GUI measures one configuration per frame. No GL.
//
// The search: a beam search by coordinate descent over the declared settings at a screening size
// (half the width and height, half the map resolution, so texels per pixel stay the same): axis by
// axis, every candidate value is tried on each of the best `beam` configurations so far, and the
// best `beam` of them go on, no two of them differing only in amounts (a beam of two gets past the
// commonest trap, where a warp pays off only together with a lower resolution). Then the best
// screened candidates are confirmed at full size. Configurations that
// differ only in settings their other settings make irrelevant (bias.constant under a slope bias, α with one split) are
// measured once.
#include "geometry/analysis/inspection.h"
#include "geometry/shadow/settings.h"
#include "geometry/shadow/shadow_plan.h"

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
    [[nodiscard]] bool empty() const noexcept { return !p95 && !interior && !edge && !misclassified; }
};

/// "p95=2,interior=0.001": keys p95, interior, edge, misclassified, each once, values finite and
/// ≥ 0. Throws std::invalid_argument (one line, naming --target) otherwise.
[[nodiscard]] TuneTarget parseTuneTarget(std::string_view text);
/// The target as parseTuneTarget reads it back.
[[nodiscard]] std::string formatTuneTarget(const TuneTarget& target);

/// One configuration's figures (over all views: the worst accuracy, the summed time).
struct TuneFigures {
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    double p95 = kNaN, interior = kNaN, edge = kNaN, misclassified = kNaN;
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

/// One searched setting and its candidate values (as `--set` spells them).
struct TuneAxis {
    std::string key;
    std::vector<std::string> values;
};

/// bias.type and its amounts, filter.type and kernel, resolution, warp.method, splits count, scheme
/// and α, tangent plane (docs/design.md §4 "Tuning" lists the values).
[[nodiscard]] std::vector<TuneAxis> defaultTuneSpace();
/// Applies "key=v1,v2,...": replaces that key's candidates, or adds the key. Throws
/// std::invalid_argument (naming --space) for a malformed spec, an unknown key or an invalid value.
void overrideTuneAxis(std::vector<TuneAxis>& space, std::string_view spec);
/// The number of configurations the space spans (the product of its axes' sizes).
[[nodiscard]] double tuneSpaceSize(const std::vector<TuneAxis>& space) noexcept;

/// Whether `key` changes anything under the other settings of `s` (bias.slope only for the slope
/// biases, splits.alpha only for adaptive splits with more than one split, …).
[[nodiscard]] bool settingMatters(const shadow::ShadowSettings& s, std::string_view key) noexcept;

enum class TuneStage { Screen, Full };

struct TuneRequest {
    shadow::ShadowSettings settings; // what to measure (at the screening size: half the map resolution)
    shadow::Viewport size;
    TuneStage stage = TuneStage::Screen;
    std::string label; // the candidate's searched keys that differ from the start, "key=value ..."
};

struct TuneEvaluation {
    TuneRequest request;
    shadow::ShadowSettings candidate; // the configuration itself (full resolution)
    TuneFigures figures;
    double violation = 0;
    [[nodiscard]] bool meets() const noexcept { return violation == 0; }
};

struct TuneOptions {
    shadow::Viewport size{640, 360}; // full size; screening at half of it
    int budgetEvals = 80;            // measurements in all, screening and confirmation
    int confirm = 4;                 // screened candidates confirmed at full size (more while none meets)
    int maxPasses = 3;               // passes over the axes
    int beam = 2;                    // configurations carried from axis to axis
};

class Tuner {
public:
    /// Throws std::invalid_argument for an empty target or space, a budget below 2 or a start
    /// the declaration rejects.
    Tuner(shadow::ShadowSettings start, std::vector<TuneAxis> space, TuneTarget target, TuneOptions options);

    /// The next configuration to measure; nullopt when the search is over.
    [[nodiscard]] std::optional<TuneRequest> next();
    /// The figures of the request next() returned last. A screening measurement's edge error is
    /// scaled by the width ratio (edges are 1-D: half the size, about twice the fraction). Throws
    /// std::logic_error without a request.
    void report(const TuneFigures& figures);

    [[nodiscard]] bool done() const noexcept { return phase_ == Phase::Done; }
    /// Fraction of the budget spent (1 when done).
    [[nodiscard]] double progress() const noexcept;
    [[nodiscard]] const std::vector<TuneEvaluation>& evaluations() const noexcept { return evaluations_; }
    /// The cheapest full-size evaluation that meets the target (index into evaluations()).
    [[nodiscard]] std::optional<size_t> recommended() const noexcept;
    /// The full-size evaluation that misses the target least (or the screened one, if none is full-size).
    [[nodiscard]] std::optional<size_t> closest() const noexcept;
    [[nodiscard]] int fullEvaluations() const noexcept;
    [[nodiscard]] const TuneTarget& target() const noexcept { return target_; }
    [[nodiscard]] const std::vector<TuneAxis>& space() const noexcept { return space_; }

private:
    enum class Phase { Screen, Confirm, Done };
    /// The canonical text of a configuration: its relevant settings only.
    [[nodiscard]] std::string canonical(const shadow::ShadowSettings& s) const;
    [[nodiscard]] std::string label(const shadow::ShadowSettings& s) const;
    [[nodiscard]] bool better(const TuneEvaluation& a, const TuneEvaluation& b) const noexcept;
    /// The same configuration but for continuous amounts (float settings: bias amounts, α, …).
    [[nodiscard]] bool siblings(const shadow::ShadowSettings& a, const shadow::ShadowSettings& b) const;
    [[nodiscard]] std::optional<size_t> screened(const std::string& key) const noexcept;
    [[nodiscard]] int budgetLeft() const noexcept;
    void finishAxis();
    void startConfirm();

    shadow::ShadowSettings start_;
    std::vector<TuneAxis> space_;
    TuneTarget target_;
    TuneOptions options_;

    Phase phase_ = Phase::Screen;
    std::vector<TuneEvaluation> evaluations_;
    std::vector<std::string> keys_; // canonical() of each evaluation's candidate
    std::optional<TuneEvaluation> pending_;
    std::string pendingKey_;
    // Screening: the beam (the best few screened evaluations, ranked), the axis being varied, the
    // beam member and value to vary next, and the axis's evaluations so far (memoized ones included).
    std::vector<size_t> beam_, axisBeam_, axisEvals_;
    size_t axis_ = 0, member_ = 0, value_ = 0;
    int pass_ = 0;
    bool changed_ = false;
    // Confirmation: screened evaluations in rank order and the next to confirm.
    std::vector<size_t> ranked_;
    size_t nextConfirm_ = 0;
};

} // namespace geometry::analysis
