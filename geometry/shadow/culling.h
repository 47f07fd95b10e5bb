#pragma once
// Chunk culling against a clip volume (a split's light frustum or the eye frustum).
#include "geometry/scene/aabb.h"

namespace geometry::shadow {

/// False only when the box lies entirely outside one of the six clip planes of `viewProj`
/// (conservative: a box straddling a corner may be kept). Empty boxes are outside.
[[nodiscard]] bool intersectsClipVolume(const scene::Aabb& box, const glm::mat4& viewProj) noexcept;

} // namespace geometry::shadow
