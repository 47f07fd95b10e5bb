#pragma once
// Progressive refinement of the eye view (docs/design.md §2.6): while the user drags, the eye pass
// runs at a reduced resolution chosen to fit a frame-time budget; when input pauses it runs once
// at full resolution. Pure decisions on plain values.
namespace ui {

/// What a side draws this frame.
enum class Draw { None, Coarse, Full };

/// Input pause after which a coarse image is refined, seconds.
inline constexpr double kRefinePause = 0.15;

/// `changed`: the side's inputs differ from what it shows; `continuous`: the change comes from a
/// drag, the wheel or fly keys (more will follow); `shownCoarse`: the image shown is coarse;
/// `sinceChange`: seconds since the inputs last changed.
[[nodiscard]] constexpr Draw decideDraw(bool changed, bool continuous, bool shownCoarse, double sinceChange) noexcept {
    if (changed) return continuous ? Draw::Coarse : Draw::Full;
    if (shownCoarse && !(sinceChange < kRefinePause)) return Draw::Full; // NaN-safe: refine
    return Draw::None;
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
