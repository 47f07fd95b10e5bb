#pragma once
// Frame-to-frame and across-split stability measures (docs/design.md §4 "Seams", "Flicker"). Pure
// functions over per-pixel readbacks, no GL; inputs are one value per eye pixel, row-major, top
// row first, as in metrics.h. `receiver[i] != 0` marks visible geometry facing the light.
// Spans of different lengths (or not width·height long, for seamStats) throw std::invalid_argument.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

#include "geometry/analysis/inspection.h"
#include "geometry/analysis/metrics.h"

namespace geometry::analysis {

/// Flicker between two consecutive frames of a camera or light path: of the pixels that are
/// receivers in both frames, have a finite shadow factor s in both and whose ray-traced truth
/// does not change (occluded both times or lit both times), the fraction whose rendered state
/// (lit: s >= 0.5, the threshold of truthStats) changes. A flip where the truth stays put is the
/// renderer's doing: shadow edges swimming with the map's texel grid, acne crawling, splits
/// moving. Pixels whose truth changes (a shadow edge really moving) are left out of both counts.
struct FlickerStats {
    double rate = 0;   // flips / stable; 0 when stable == 0
    size_t flips = 0;  // stable pixels whose rendered state changed
    size_t stable = 0; // pixels counted: receivers in both frames, truth unchanged, s finite
};

[[nodiscard]] FlickerStats flickerStats(std::span<const float> sBefore, std::span<const uint8_t> occludedBefore,
                                        std::span<const uint8_t> receiverBefore, std::span<const float> sAfter,
                                        std::span<const uint8_t> occludedAfter, std::span<const uint8_t> receiverAfter);

/// World-space flicker (shimmer): the same world point, followed from frame to frame. Each receiver
/// pixel of `after` is reprojected through `beforeViewProj` (the previous frame's eye) to the nearest
/// pixel of `before`; it counts when that pixel is a receiver whose view depth agrees within 2 %
/// (the previous frame saw the same surface), whose truth equals this pixel's, and whose 3 × 3
/// neighbourhood shares its rendered state (s ≥ 0.5): the point lay inside a rendered region, so a
/// flip is the state changing there, not the half-pixel gap between the point and the nearest pixel
/// straddling an edge that held still. It flips when the rendered states differ. (Edges that move
/// by less than a pixel are not counted: shimmer of maps finer than the screen.) Unlike flickerStats, a camera move
/// does not count world-fixed stair-steps sliding across pixels, only states that change at a point. Without truth in
/// both frames the truth condition is dropped. Throws std::invalid_argument when a frame's fields do not match its
/// size.
[[nodiscard]] FlickerStats worldFlickerStats(const Inspection& before, const glm::mat4& beforeViewProj,
                                             const Inspection& after);

/// Both flickers of one frame pair with truth (flickerStats on the same pixels, worldFlickerStats
/// on the same points): what `sweep path` and renderer::measurePath record per pair. Throws
/// std::invalid_argument when either frame lacks truth.
struct FramePairFlicker {
    FlickerStats screen, world;
};
[[nodiscard]] FramePairFlicker framePairFlicker(const Inspection& before, const glm::mat4& beforeViewProj,
                                                const Inspection& after);

/// Seams (docs/design.md §4: "ratio of m on the two sides of each split boundary"). Walks every row and
/// column through four consecutive pixels c, a | b, e (a and b neighbours): a split boundary
/// lies between a and b when their split indices (aux[i].z, rounded; < 0 for sky) differ, while
/// c shares a's split and e shares b's. All four must be receivers with 0 < m < 1e6 (larger m is
/// the eye shader's cap for a singular J, e.g. a surface edge-on to the light) on the
/// same surface as a (normals within ~8°, each point within 1 % of a's distance to the eye from
/// a's tangent plane): on this CAD scene most neighbours with different splits are a grating bar
/// next to the sea seen through the grating, whose m ratio says nothing about the partition.
/// The seam of one crossing is the jump of log m from a to b beyond the local slope of m on
/// either side (m changes steeply near a horizon, where a plain neighbour ratio would count that
/// gradient as a seam):
///     seam = exp|ln(m_b/m_a) − ½·ln(m_a/m_c) − ½·ln(m_e/m_b)|  ≥ 1,  1 = no seam.
/// The same quantity over four pixels inside one split is the baseline (≈ 1 on smooth surfaces),
/// and max(m_a, m_b)/min(m_a, m_b) of the crossing pairs is reported as the raw ratio.
/// Medians use the nearest-rank rule of aliasingStats (one of the values, never interpolated).
struct SeamStats {
    double median = 0;         // median seam over boundary crossings; 0 when none
    double p95 = 0;            // 95th percentile of those
    size_t pairs = 0;          // boundary crossings counted
    double rawMedian = 0;      // median max(m)/min(m) of the crossing pairs a, b
    double baselineMedian = 0; // median of the same measure inside one split
    size_t baselinePairs = 0;
};

[[nodiscard]] SeamStats seamStats(std::span<const float> m, std::span<const glm::vec4> aux,
                                  std::span<const uint8_t> receiver, std::span<const glm::vec3> positions,
                                  std::span<const glm::vec3> normals, const glm::vec3& eye, int width, int height);

} // namespace geometry::analysis
