#pragma once
// How much of a caster's detail a split's map can show (casters.lod = auto; docs/design.md §3.8):
// the geometric error a simplified level of a chunk may have in that map. Pure; the renderer asks
// it per chunk and draws the coarsest level within it.
#include "geometry/shadow/shadow_plan.h"

namespace geometry::shadow {

/// The smallest world-space texel side of split `split`'s map over the box's corners and centre,
/// those in front of the map's projection centre; NaN when there is none.
[[nodiscard]] float finestTexelOver(const ShadowPlan& plan, int split, const scene::Aabb& box) noexcept;

/// casters.lod_texels × finestTexelOver: no part of the chunk may be drawn coarser than that. 0
/// (full detail) when caster LOD is off or the map gives no texel size there.
[[nodiscard]] float casterErrorBudget(const ShadowPlan& plan, int split, const scene::Aabb& box) noexcept;

} // namespace geometry::shadow
