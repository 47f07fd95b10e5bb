#pragma once
// Chunk culling against a clip volume (a split's light frustum or the eye frustum).
#include "aabb.h"

namespace geometry {

/// False only when the box lies entirely outside one of the six clip planes of `viewProj`
/// (conservative: a box straddling a corner may be kept). Empty boxes are outside.
[[nodiscard]] bool intersectsClipVolume(const Aabb& box, const glm::mat4& viewProj) noexcept;

} // namespace geometry
