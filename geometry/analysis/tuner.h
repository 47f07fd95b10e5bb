#pragma once
// The search behind `shadowscope tune` and the dashboard's "Recommend" (docs/design.md §4
// "Tuning"): the cheapest shadow settings that meet an accuracy target. Pure and incremental
// (ask/tell): next() says which configuration to measure at which size, report() hands back its
// figures, so the command line loops and the GUI measures one configuration per frame. No GL.
//
// The search: a beam search by coordinate descent over the declared settings at a screening size
// (half the width and height, half the map resolution, so texels per pixel stay the same, where one
// pixel there is under a tenth of the tightest fractional target; else at full size): axis by
// axis, every candidate value is tried on each of the best `beam` configurations so far, and the
// best `beam` of them go on, no two of them differing only in amounts (a beam of two gets past the
// commonest trap, where a warp pays off only together with a lower resolution). Then the best
// screened candidates are confirmed at full size. Configurations that differ only in settings
// their other settings make irrelevant (bias.constant under a slope bias, α with one split) are
// measured once, and so are resolutions the memory budget draws alike (memory_budget.h). Ranking
// uses the modelled cost (cost_model.h), never the measured time: the same figures give the same
// recommendation on every run.
#include "geometry/analysis/tune_space.h"
#include "geometry/analysis/tune_target.h"
#include "geometry/shadow/shadow_plan.h"

#include <optional>
#include <string>
#include <vector>

namespace geometry::analysis {

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
    int budgetEvals = 120;           // measurements in all; a sixth (at least `confirm`) kept for full size
    int confirm = 4;                 // screened candidates confirmed at full size (more while none meets)
    int maxPasses = 3;               // passes over the axes
    int beam = 2;                    // configurations carried from axis to axis
    // The fewest receiver pixels any view has at full size (they do not depend on the settings);
    // 0: unknown, so screening stays at full size.
    double receiverPixels = 0;
};

class Tuner {
public:
    /// Throws std::invalid_argument for an empty target or space, a budget below 2, a start the
    /// declaration rejects, or a soft target without a sun of size to measure it against.
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
    /// Whether screening runs at half size (one pixel there under a tenth of the tightest fraction).
    [[nodiscard]] bool screensAtHalfSize() const noexcept { return halfSize_; }

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

    bool halfSize_ = true;
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
