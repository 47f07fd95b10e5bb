#pragma once
// How close an occluder may touch a receiver before a shadow map with this plan's bias cannot
// resolve it (docs/design.md §4 "Truth classes": contact ambiguity). Pure; mirrors eye.frag.
#include "geometry/shadow/shadow_plan.h"

#include <glm/glm.hpp>

namespace geometry::shadow {

/// World-space side of one texel of split `split`'s map at `p` (the smaller of its two sides
/// across the light), for a map `resolution` texels wide: eye.frag's texelWorldSize. NaN when the
/// split does not exist or the map is degenerate there.
[[nodiscard]] float texelWorldSize(const ShadowPlan& plan, int split, const glm::vec3& p, int resolution) noexcept;

/// The distance along the light within which an occluder counts as touching the receiver at `p`:
/// the larger of one texel (no map places a caster more finely) and the distance the plan's bias
/// moves the receiver (constant: bias.constant; normal offset: normal_offset texels; slope:
/// polygon-offset factor texels, the offset at a 45° slope). NaN as texelWorldSize.
[[nodiscard]] float contactDistance(const ShadowPlan& plan, int split, const glm::vec3& p, int resolution) noexcept;

} // namespace geometry::shadow
