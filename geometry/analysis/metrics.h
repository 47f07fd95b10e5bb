#pragma once
// CPU-side inspection metrics over per-pixel readbacks (docs/design.md §4). Pure functions, no GL.
//
// Every input is one value per eye pixel in the same order (row-major, top row first; the order
// does not matter to the statistics). `receiver[i] != 0` marks visible geometry facing the light
// (N·l < 0); sky and back-facing pixels are left out of every statistic, as docs/design.md §4 asks.
// Non-finite values (NaN, ±Inf) are skipped and counted in `skipped`, so one bad pixel cannot
// turn a whole statistic into NaN. Spans of different lengths throw std::invalid_argument.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace geometry::analysis {

/// The eye shader floors σ_min(J) at 1e-10 (m = 1e10) where J is singular, e.g. on a surface
/// edge-on to the light; m at or above this bound is that cap, not a measured value.
inline constexpr float kSingularM = 1e6f;

/// Aliasing error m (docs/design.md §4: m = 1/σ_min(J), screen pixels per texel along the worst
/// direction; m > 1 undersampled) summarized over receiver pixels. Pixels whose J is singular
/// (m ≥ kSingularM: the shader's cap, not a measurement) are counted in `singular` and left out of
/// every other figure, so a few edge-on pixels cannot turn the mean into 1e6.
struct AliasingStats {
    double mean = 0, p50 = 0, p95 = 0, max = 0;
    double undersampled = 0; // fraction of counted pixels with m > 1
    double singular = 0;     // fraction of receiver pixels with a finite m whose J is singular
    size_t count = 0;        // receiver pixels with a finite, non-singular m
    size_t skipped = 0;      // receiver pixels with a non-finite m
};

/// Percentiles use the nearest-rank definition: of the n sorted values, the p-th percentile is
/// the ⌈p·n/100⌉-th smallest (1-based), so it is always one of the values, never interpolated.
/// All fields are zero when no receiver pixel has a finite m.
[[nodiscard]] AliasingStats aliasingStats(std::span<const float> m, std::span<const uint8_t> receiver);

/// Rendered shadow factor s against ray-cast ground truth (docs/design.md §4 "Ground truth").
/// s is the lit fraction: 1 fully lit, 0 fully shadowed.
struct TruthStats {
    double falseShadow = 0; // fraction of counted pixels with truth lit and s < 0.5 (acne, over-bias)
    double falseLit = 0;    // fraction with truth shadowed and s >= 0.5 (peter-panning, leaks)
    double meanAbs = 0;     // mean |s − truth|, truth lit = 1, shadowed = 0
    size_t count = 0;       // receiver pixels with a finite s
    size_t skipped = 0;     // receiver pixels with a non-finite s
};

/// `occluded[i] != 0`: the ray towards the light is blocked (truth shadowed). All fields are
/// zero when no receiver pixel has a finite s.
[[nodiscard]] TruthStats truthStats(std::span<const float> s, std::span<const uint8_t> occluded,
                                    std::span<const uint8_t> receiver);

/// Mean |s − v| over the receiver pixels where both are finite: the rendered shadow factor against
/// the soft truth's sun visibility v (docs/design.md §4 "Soft truth"). NaN when no pixel counts.
/// Throws std::invalid_argument when the sizes differ.
[[nodiscard]] double softMeanAbs(std::span<const float> s, std::span<const float> v, std::span<const uint8_t> receiver);

/// Texel utilization (docs/design.md §4): the fraction of split `split`'s resolution² texels that hold
/// at least one receiver pixel's sample point. aux[i] = (u, v in texels of the split's map,
/// split index, map depth); a pixel belongs to the split when its index rounds to `split`, and
/// it marks texel (⌊u⌋, ⌊v⌋). Pixels with non-finite u, v or index, or with (u, v) outside
/// [0, resolution)², mark nothing. resolution must lie in [1, 16384] (std::invalid_argument
/// otherwise); the texel set is a bit vector, so 16384² costs 32 MiB.
[[nodiscard]] double texelUtilization(std::span<const glm::vec4> aux, std::span<const uint8_t> receiver, int split,
                                      int resolution);

/// The texel set behind texelUtilization(), one byte per texel (1 used, 0 unused), row v first
/// (index = v·resolution + u, v = 0 is the map's first row as stored in the GL texture), for
/// an overlay. Costs resolution² bytes: 256 MiB at 16384, so prefer texelUtilization() when only
/// the fraction is needed.
[[nodiscard]] std::vector<uint8_t> texelUsageMask(std::span<const glm::vec4> aux, std::span<const uint8_t> receiver,
                                                  int split, int resolution);

} // namespace geometry::analysis
