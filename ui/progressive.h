#pragma once
// Progressive refinement of the eye view (docs/design.md §2.6): while the user drags, the eye pass
// runs at a reduced resolution chosen to fit a frame-time budget; when input pauses it runs once
// at full resolution. Pure decisions on plain values.
namespace ui {

/// What a side draws this frame.
enum class Draw { None, Coarse, Full };

/// Input pause after which a coarse image is refined, seconds.
inline constexpr double kRefinePause = 0.15;

/// GPU milliseconds a frame may take for the first visible response to a discrete change (a combo,
/// a typed value, A/B on): above it the change is drawn coarse first and refined on the next frame,
/// so the response stays within a quarter second on llvmpipe (issue 32) with the dashboard's own
/// drawing and the plan added.
inline constexpr double kResponseBudgetMs = 150.0;

/// What a side draws this frame. `changed`: its inputs differ from what it shows; `continuous`:
/// the change comes from a drag, the wheel or fly keys (more will follow); `fullFits`: a full-
/// resolution frame is predicted to fit kResponseBudgetMs (unknown: true); `shownCoarse`: the
/// image shown is coarse; `sinceChange`: seconds since the inputs last changed; `refinePause`:
/// how long input must pause before a coarse image is refined (kRefinePause after a drag, 0 after
/// a discrete change).
[[nodiscard]] constexpr Draw decideDraw(bool changed, bool continuous, bool fullFits, bool shownCoarse,
                                        double sinceChange, double refinePause) noexcept {
    if (changed) return continuous || !fullFits ? Draw::Coarse : Draw::Full;
    if (shownCoarse && !(sinceChange < refinePause)) return Draw::Full; // NaN-safe: refine
    return Draw::None;
}

/// Whether a full-resolution frame of every shown side fits `budgetMs`, from one side's predicted
/// full-frame GPU time; an unknown prediction (NaN, ≤ 0: no frame timed yet) fits.
[[nodiscard]] constexpr bool fullFrameFits(double predictedSideMs, int sides, double budgetMs) noexcept {
    return !(predictedSideMs * sides > budgetMs);
}

/// The divisor of each side of the view for a coarse frame (2 or 4): the smaller one whose
/// predicted frame fits `budgetMs`, given the full-resolution eye-side cost (`perPixelMs`, the
/// part that scales with the pixel count) and the fixed cost (`fixedMs`: shadow maps, light views).
/// Unknown costs (NaN, ≤ 0) give 2.
[[nodiscard]] constexpr int coarseDivisor(double perPixelMs, double fixedMs, double budgetMs) noexcept {
    if (!(perPixelMs > 0.0)) return 2;
    const double fixed = fixedMs > 0.0 ? fixedMs : 0.0;
    return fixed + perPixelMs / 4.0 <= budgetMs ? 2 : 4;
}

} // namespace ui
