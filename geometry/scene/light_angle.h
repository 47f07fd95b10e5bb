#pragma once
// Turning the light about the eye so that its angle with the view direction takes a chosen value
// (docs/design.md §1, hunting failure cases: γ sweeps through the dueling frusta). Pure, no GL; the
// `sweep gamma` command and the GUI's "set γ" control share it.
#include <glm/glm.hpp>

namespace geometry::scene {

/// The unit light direction l (from the light into the scene) whose angle with the view direction
/// v is `angleDeg`: 0 = light from behind the eye along the view (l = v), 90 = perpendicular,
/// 180 = light facing the camera (l = −v, the dueling frusta). l lies in the plane of v and
/// `reference` (usually the current light), on reference's side of v, so turning the angle keeps
/// the light where it was around the view axis:
///     l = cos(angle)·v + sin(angle)·u,   u = unit part of `reference` ⊥ v.
/// When reference is (anti)parallel to v, zero or not finite, u is world down (0, −1, 0) made ⊥ v
/// (so that at 90° the sun shines from above), or world −x when v is vertical. angleDeg is clamped
/// to [0, 180]; NaN counts as 0. A zero or non-finite v counts as (0, 0, −1). Never NaN.
/// Its inverse is lightViewAngleDeg (scene.h).
[[nodiscard]] glm::vec3 lightAtViewAngle(const glm::vec3& v, const glm::vec3& reference, float angleDeg) noexcept;

} // namespace geometry::scene
