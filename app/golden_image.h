#pragma once
// Comparing a render with its golden image (`shadowscope check`), as pure functions on CPU images.
#include "geometry/analysis/image.h"

#include <cstddef>
#include <string>

namespace app {

struct ImageComparison {
    bool sameSize = false;
    int width = 0, height = 0;             // the render's
    int goldenWidth = 0, goldenHeight = 0; // the golden's
    size_t differing = 0; // pixels where some channel (RGBA) differs by more than the channel tolerance
    size_t pixels = 0;    // pixels compared (0 when the sizes differ)
    int maxChannelDifference = 0;
    [[nodiscard]] double fraction() const noexcept { return pixels ? double(differing) / double(pixels) : 0.0; }
    /// The case's golden verdict: same size, and at most `allowedFraction` of the pixels differing
    /// (a NaN allowance passes nothing).
    [[nodiscard]] bool passes(double allowedFraction) const noexcept {
        return sameSize && fraction() <= allowedFraction;
    }
};

/// Counts the pixels of `render` that differ from `golden` by more than `channelTolerance` in any
/// channel. Images of different sizes are not compared (sameSize false).
[[nodiscard]] ImageComparison compareImages(const geometry::analysis::Image& render,
                                            const geometry::analysis::Image& golden, int channelTolerance);

/// The colour of a differing pixel in diffImage(): saturated magenta, which the grey copy never is.
inline constexpr unsigned char kDiffColour[4] = {255, 0, 255, 255};

/// A picture of the comparison, the size of `render`: pixels that differ (as compareImages counts
/// them) in kDiffColour over a dimmed grey copy of the render (so where they lie stays readable).
/// Throws std::invalid_argument when the sizes differ.
[[nodiscard]] geometry::analysis::Image diffImage(const geometry::analysis::Image& render,
                                                  const geometry::analysis::Image& golden, int channelTolerance);

/// The verdict's text: "golden G: 2345 of 14400 pixels (16.3%) differ by more than 8 > fraction 0.001"
/// ("<=" when it passes), or "golden G: the render is 160x90, the golden 240x135".
[[nodiscard]] std::string comparisonText(const std::string& golden, const ImageComparison& c, int channelTolerance,
                                         double allowedFraction);

} // namespace app
