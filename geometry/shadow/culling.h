#pragma once
// Chunk culling against a clip volume (a split's light frustum or the eye frustum).
#include "geometry/scene/aabb.h"

namespace geometry::shadow {

enum class ClipOverlap { Outside, Partly, Inside };

/// Outside only when the box lies entirely outside one of the six clip planes of `viewProj`
/// (conservative: a box straddling a corner may be Partly); Inside when all its corners are
/// inside all six. Empty boxes are Outside.
[[nodiscard]] ClipOverlap clipOverlap(const scene::Aabb& box, const glm::mat4& viewProj) noexcept;

} // namespace geometry::shadow
