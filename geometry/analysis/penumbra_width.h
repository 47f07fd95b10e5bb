#pragma once
// The width of the penumbra a straight occluder edge casts from a sun of angular diameter θ, as a
// shadow (rendered s or traced v) draws it, against the width the analytic disk gives
// (docs/design.md §4 "Soft truth"). Pure: no scene, no rays.
#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace geometry::analysis {

/// ∫_{−1}^{1} 4·v(x)·(1 − v(x)) dx for the disk edge profile v (diskEdgeVisibility), integrated
/// numerically once (midpoint rule, 2·10⁶ intervals; tests/test_penumbra_width.cpp repeats it).
inline constexpr double kDiskEdgeWidth = 1.1528099116639643;

/// The bins across the penumbra: u over [−kPenumbraSpan·R', kPenumbraSpan·R'], R' = tan(θ/2).
inline constexpr int kPenumbraBins = 16;
inline constexpr double kPenumbraSpan = 1.5;
/// A bin with fewer pixels makes the whole measurement NaN.
inline constexpr size_t kMinPixelsPerPenumbraBin = 3;

/// The visible fraction of a uniform unit disk cut by a straight edge at normalized offset x (the
/// part of the disk on the side x grows towards): 0.5 + (x·√(1 − x²) + asin x)/π, 0 for x ≤ −1 and
/// 1 for x ≥ 1.
[[nodiscard]] double diskEdgeVisibility(double x) noexcept;

struct PenumbraWidth {
    double error = std::numeric_limits<double>::quiet_NaN();     // width / reference − 1
    double width = std::numeric_limits<double>::quiet_NaN();     // W(f) = Σ_bins 4·f̄(1 − f̄)·Δu
    double reference = std::numeric_limits<double>::quiet_NaN(); // W_a = R'·kDiskEdgeWidth
    size_t pixels = 0;                                           // pixels binned
    size_t fewestInBin = 0;                                      // the emptiest bin's pixels
};

/// The effective penumbra width of the lit fraction f across the shadow of `edge` (two distinct
/// points, world space) cast by a sun of angular diameter θ = angularDiameterRad centred on −l.
/// For each receiver pixel p with finite p and f: the ray p + t·(−l̂); its closest approach to the
/// edge's line, kept when the closest point on the line lies within the middle 80 % of the segment
/// and t = D > 0 (the edge lies above the receiver towards the sun); d = the signed distance of
/// closest approach along (−l̂) × (edge direction), perpendicular to both; u = d / D, the edge's
/// offset from the sun's centre in the plane ⊥ l at unit distance, where the sun's disk has radius
/// R' = tan(θ/2) (so a disk's f is diskEdgeVisibility(±u/R')). Pixels with u in
/// [−1.5R', 1.5R'] fall into 16 bins of width Δu; W(f) = Σ 4·f̄(1 − f̄)·Δu over the bins' mean f̄.
/// 4f(1 − f) is 0 where the pixel is wholly lit or wholly shadowed and 1 at half, so W measures
/// the transition alone, on either side alike, whatever its profile; against the disk's own W_a it
/// reads 0 for a true disk penumbra, −1 for a hard edge, +1 for a penumbra twice too wide (less
/// the tails the ±1.5R' window cuts: +0.91 for a disk of twice the radius).
/// error is NaN when θ ≤ 0 or not finite, l or the edge is degenerate, or any bin holds fewer than
/// kMinPixelsPerPenumbraBin pixels. Throws std::invalid_argument when the sizes differ.
[[nodiscard]] PenumbraWidth penumbraWidth(std::span<const glm::vec3> positions, std::span<const float> litFraction,
                                          std::span<const uint8_t> receiver, const glm::vec3& l,
                                          const std::array<glm::vec3, 2>& edge, double angularDiameterRad);

} // namespace geometry::analysis
