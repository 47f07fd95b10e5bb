#pragma once
// Lost casters, measured geometrically (issue 9): whatever can shadow a receiver lies on the
// segment from it towards the light until that segment leaves the scene bounds S, so a correct
// plan keeps that whole segment inside the light frustum of the split the receiver samples
// (the focus body B_i extruded towards the light, docs/design.md §3.1). Counting receivers whose segment
// leaves the frustum finds a plan that drops casters whatever the map resolution, where
// false_lit cannot tell lost casters from casters thinner than a texel. Pure, no GL.
#include "geometry/shadow/shadow_plan.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace geometry::analysis {

struct CasterCoverage {
    double clipped = 0;         // fraction of counted receivers whose caster segment leaves their split's map
    double falseLitClipped = 0; // fraction that is false lit (truth shadowed, s >= 0.5) with a clipped segment
    size_t clippedCount = 0, falseLitClippedCount = 0;
    size_t count = 0; // receivers with a finite position and a valid split index
};

/// Per pixel (row-major, like metrics.h): world position, aux (aux[i].z: the split index the eye
/// pass used, rounded; < 0 sky), receiver flag, and optionally the ray-traced truth (occluded[i]
/// != 0: shadowed) with the rendered shadow factor s (empty spans: falseLitClipped stays 0). The segment runs from the
/// position to exitTowardLight(position, l, S) (focus.h); it is inside the split's map when both ends are inside the
/// clip cube of lightViewProj (x, y within ±(1 + 1e-3), z ≥ −1 − 1e-3, w > 0: the map volume is convex); depth beyond
/// the far side does not matter for casters. Empty splits count as clipped when the receiver's segment is not a single
/// point. Mismatched sizes throw std::invalid_argument.
[[nodiscard]] CasterCoverage casterCoverage(const shadow::ShadowPlan& plan, std::span<const glm::vec3> positions,
                                            std::span<const glm::vec4> aux, std::span<const uint8_t> receiver,
                                            std::span<const uint8_t> occluded = {}, std::span<const float> shadow = {});

} // namespace geometry::analysis
