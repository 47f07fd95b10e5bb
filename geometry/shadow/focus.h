#pragma once
// Focus body B (Scherzer §4.1, Zhang 003 eq 5): the part of a (sub-)frustum inside the scene
// bounds S, extruded towards the light until it leaves S.
#include "geometry/scene/scene.h"
#include "geometry/shadow/convex_body.h"

#include <array>
#include <span>
#include <vector>

namespace geometry::shadow {

/// World-space corners of the camera frustum between view distances `near` and `far`, indexed
/// by bits (x: right, y: top, z: far) as ConvexBody::fromCorners expects.
[[nodiscard]] std::array<glm::vec3, 8> frustumCorners(const scene::Camera& cam, float aspect, float near,
                                                      float far) noexcept;

/// Where the ray from p towards the light (direction −l) leaves the box; p itself if p is
/// outside or the ray is degenerate.
[[nodiscard]] glm::vec3 exitTowardLight(const glm::vec3& p, const glm::vec3& l, const scene::Aabb& S) noexcept;

/// B_i as a point set: the vertices of V_i ∩ S (∩ every plane of `clip`: the visible samples' prism,
/// focus.mode = samples) and, for each, its exit point towards the light, so no caster between the
/// focus and the light is lost. Empty (not NaN) when nothing is left.
[[nodiscard]] std::vector<glm::vec3> focusBody(const std::array<glm::vec3, 8>& frustum, const scene::Aabb& S,
                                               const glm::vec3& l, std::span<const Plane> clip = {});

} // namespace geometry::shadow
