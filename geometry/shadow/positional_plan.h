#pragma once
// Maps for spot and point lights (docs/design.md §3.10): one perspective map from a spot light's
// position, six cube faces for a point light; each fitted to what the camera sees of S inside its
// frustum. Positional maps are the light's own perspective: no warp, no z-partitioning.
#include "geometry/shadow/shadow_plan.h"

namespace geometry::shadow {

/// The faces of a point light, in split order.
inline constexpr int kCubeFaces = 6;

/// The cube face direction d (from the light) falls in: its major axis, 0..5 = +X, −X, +Y, −Y, +Z, −Z
/// (ties go to the earlier axis, as the eye pass decides). NaN-safe: 0.
[[nodiscard]] int cubeFace(const glm::vec3& d) noexcept;

/// tan of a cube face's half field of view: 90° widened so that `reachTexels` texels on each side of
/// an N-texel map lie beyond the face's 90° (filter taps near a face edge stay on the face's map).
[[nodiscard]] double cubeFaceTanHalf(int resolution, double reachTexels) noexcept;

/// The splits of a spot (one) or point (kCubeFaces) light's plan, appended to `plan.splits`, and
/// plan.l (spot: the axis; point: towards what the camera sees). A split whose frustum sees no part of
/// V ∩ S within the light's range is empty. `plan` holds the frame's values (eye, S, settings);
/// never NaN, whatever the light's position (inside S, inside V, behind the camera).
void planPositionalSplits(const scene::Aabb& S, const scene::Camera& camera, float aspect, const scene::Light& light,
                          int resolution, double reachTexels, ShadowPlan& plan);

/// What a positional light does not apply of `settings` (warp, splits, sample fitting, stabilization,
/// caster levels), one line each, for ShadowPlan::warnings.
[[nodiscard]] std::vector<std::string> positionalLightWarnings(const ShadowSettings& settings,
                                                               const scene::Light& light);

} // namespace geometry::shadow
