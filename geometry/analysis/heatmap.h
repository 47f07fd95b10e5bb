#pragma once
// The image side of inspection heatmaps (docs/design.md §4): colour maps, heatmap images, legends and
// PFM float dumps. CPU only, no GL calls; per-pixel inputs are row-major, top row first, like
// renderer::Image.
#include "geometry/analysis/image.h"
#include "geometry/analysis/truth_classes.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace geometry::analysis {

// ---- colour maps (RGB in [0,1], display/sRGB values) ----------------------------------------

/// Colour for a pixel whose value cannot be shown (NaN, ±Inf, m ≤ 0): magenta, because it
/// appears on none of the scales below and so cannot be mistaken for a measurement.
inline constexpr glm::vec3 kInvalidColour{1.f, 0.f, 1.f};
/// Pixels outside the statistics (sky, back-facing; not receivers): dark grey.
inline constexpr glm::vec3 kNonReceiverColour{0.15f, 0.15f, 0.15f};

/// Aliasing error m on a diverging blue–white–red scale of log2 m over [−range, range]
/// (docs/design.md §4 "Heatmap"): blue = oversampled (m < 1),
/// white = m = 1, red = undersampled (m > 1); beyond the range the end colours hold. Lightness
/// falls monotonically from white towards both ends (a ColorBrewer RdBu-like ramp), so the
/// magnitude reads the same on both sides. Non-finite or non-positive m, or range ≤ 0, give
/// kInvalidColour.
[[nodiscard]] glm::vec3 divergingLog2(float m, float range = 4);

/// Shadow factor s (lit fraction) against truth (docs/design.md §4 "Heatmap"): red where truth is lit and s < 0.5, blue
/// where truth is shadowed and s ≥ 0.5, otherwise a grey whose level follows s (0.3 shadowed … 0.9 lit), so the scene
/// stays readable under the errors. Non-finite s gives kInvalidColour.
[[nodiscard]] glm::vec3 falseColourTruth(float s, bool occluded);
inline constexpr glm::vec3 kFalseShadowColour{0.95f, 0.12f, 0.1f};
inline constexpr glm::vec3 kFalseLitColour{0.15f, 0.4f, 1.f};
/// The truth classes (truth_classes.h) beyond false shadow (red, interior) and false lit (blue,
/// interior): an edge drawn in the wrong place, amber; a pixel whose truth is ambiguous, teal.
inline constexpr glm::vec3 kEdgeErrorColour{1.f, 0.72f, 0.1f};
inline constexpr glm::vec3 kAmbiguousColour{0.1f, 0.75f, 0.65f};

/// Categorical colour of split i (8 distinct hues, Tableau 10-like; cycles past 8, negative i
/// folds into the same cycle).
[[nodiscard]] glm::vec3 splitColour(int i);

// ---- heatmap images -------------------------------------------------------------------------

/// divergingLog2(m) on receivers, kNonReceiverColour elsewhere. Throws std::invalid_argument
/// unless both spans hold width·height values and range > 0.
[[nodiscard]] Image aliasingHeatmap(std::span<const float> m, std::span<const uint8_t> receiver, int width, int height,
                                    float range = 4);
/// falseColourTruth(s, occluded) on receivers, kNonReceiverColour elsewhere. Throws
/// std::invalid_argument unless every span holds w·h values.
[[nodiscard]] Image truthHeatmap(std::span<const float> s, std::span<const uint8_t> occluded,
                                 std::span<const uint8_t> receiver, int w, int h);

/// One colour per TruthClass: kFalseShadowColour interior false shadow, kFalseLitColour interior
/// false lit, kEdgeErrorColour edge error, kAmbiguousColour ambiguous, a grey following s where the
/// render agrees, kNonReceiverColour off the receivers, and kInvalidColour on receivers whose s is
/// not finite. Throws std::invalid_argument unless both spans hold w·h values.
[[nodiscard]] Image truthClassHeatmap(std::span<const TruthClass> classes, std::span<const float> s,
                                      std::span<const uint8_t> receiver, int w, int h);

// ---- legends --------------------------------------------------------------------------------

struct LegendTick {
    float position = 0; // along the colour bar, 0 = left end, 1 = right end
    std::string label;  // printable ASCII; other bytes show as '?'
};

struct LegendEntry {
    glm::vec3 colour{0.f};
    std::string label;
};

/// A continuous colour bar with ticks, a list of categorical swatches, or both (bar first).
struct Legend {
    std::string title;
    std::function<glm::vec3(float)> bar; // colour at t ∈ [0,1]; no bar when empty
    std::vector<LegendTick> ticks;
    std::vector<LegendEntry> entries;
    /// No title, bar or swatches: nothing to draw.
    [[nodiscard]] bool empty() const noexcept;
};

/// The aliasing legend: the divergingLog2 bar over log2 m ∈ [−range, range], ticks at powers of
/// two ("1/16", "1/4", "1", "4", "16" for range 4), title "m (pixels per texel)", plus swatches
/// for non-receivers and invalid pixels.
[[nodiscard]] Legend aliasingLegend(float range = 4);
/// Red "false shadow", blue "false lit", grey "agrees (grey = s)", plus non-receivers.
[[nodiscard]] Legend truthLegend();
/// The legend of truthClassHeatmap(): a swatch for every colour the image shows, and for nothing
/// else (invalid pixels included when there are any).
[[nodiscard]] Legend truthClassLegend(std::span<const TruthClass> classes, std::span<const float> s,
                                      std::span<const uint8_t> receiver);
/// One swatch per split: "split i [n, f]" with the split's eye-space depth range (x = near,
/// y = far).
[[nodiscard]] Legend splitLegend(std::span<const glm::vec2> depthRanges);
/// technique = virtual: one swatch per level the pixels sample, "level k (texel t)" with the level's
/// texel in scene units; (x = level, y = texel).
[[nodiscard]] Legend levelLegend(std::span<const glm::dvec2> levels);

struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0; // top-left corner, image pixels
};

/// Where drawLegend() puts its box in a width×height image: the bottom-left corner, text at
/// scale 2 on images at least 600 pixels tall when the legend fits the width at that size, scale 1
/// otherwise; the title and swatch labels wrap at spaces to fit the width, so no text is cut
/// (issue 32). May reach past the image on tiny images; drawing clips.
[[nodiscard]] PixelRect legendRect(int width, int height, const Legend& legend);

/// Draws the legend into its legendRect(): a dark translucent box, the title, the colour bar with
/// tick marks and labels, and the swatches. Text is stb_easy_font rasterized on the CPU. Pixels
/// outside the box are left untouched.
void drawLegend(Image& img, const Legend& legend);
/// `img` with the legend drawn in (unchanged for an empty legend): files keep their legend where
/// the dashboard draws it in its UI font instead.
[[nodiscard]] Image withLegend(Image img, const Legend& legend);

// ---- PFM float dumps ------------------------------------------------------------------------

/// Writes a greyscale Portable Float Map ("Pf", scale −1.0 = little-endian floats, rows bottom
/// to top per the format; `values` are top row first and get flipped). Non-finite values are
/// written bit for bit, as PFM allows, so readers see exactly what the renderer produced.
/// Throws std::invalid_argument on a size mismatch, std::runtime_error naming the path on I/O
/// failure.
void writePfm(const std::string& path, std::span<const float> values, int width, int height);

/// Reads a greyscale PFM written by writePfm() or any other tool (either byte order), top row
/// first. Throws std::runtime_error with a one-line message for a missing file, a bad magic
/// (colour "PF" included), a malformed header, sizes beyond 65536 per side or 2^28 pixels, or a
/// file shorter than its header promises.
[[nodiscard]] std::vector<float> readPfm(const std::string& path, int& w, int& h);

} // namespace geometry::analysis
