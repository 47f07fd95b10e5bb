#pragma once
// Frames along a scene file's camera or light path (scene_file.h ScenePath): the keys are equally
// spaced in the path parameter t ∈ [0, 1] (key i at t = i/(K−1)), and values between two keys are
// interpolated, so any number of frames covers the whole path. Pure, no GL.
#include "geometry/scene/scene.h"

#include <vector>

namespace geometry::scene {

/// The path parameter of frame `index` of `frames`: index/(frames − 1), 0 for a single frame.
[[nodiscard]] double pathParameter(int index, int frames) noexcept;

/// The camera at t (clamped to [0, 1]; NaN counts as 0): eye, target and up linearly between the
/// two neighbouring keys, the field of view linearly, near and far geometrically (they are scale
/// parameters, so n·(f/n) ratios vary smoothly). One key: that key. No keys: a default Camera.
[[nodiscard]] Camera cameraAlongPath(const std::vector<Camera>& keys, double t) noexcept;

/// The unit light direction at t: between two keys it turns at a constant rate in their common
/// plane (spherical interpolation, through lightAtViewAngle, which also settles opposite keys).
/// One key: that key normalized. No keys or zero keys: (0, −1, 0).
[[nodiscard]] glm::vec3 lightAlongPath(const std::vector<glm::vec3>& keys, double t) noexcept;

/// The position at t: linearly between the two neighbouring keys. One key: that key. No keys: (0, 0, 0).
[[nodiscard]] glm::vec3 positionAlongPath(const std::vector<glm::vec3>& keys, double t) noexcept;

/// A path's keys for one light (docs/design.md §3.10): its direction and its position, each moved
/// only where the path has keys for it.
struct LightPathKeys {
    std::vector<glm::vec3> directions;
    std::vector<glm::vec3> positions;
    [[nodiscard]] bool empty() const noexcept { return directions.empty() && positions.empty(); }
};

/// `light` at t along `keys`: lightAlongPath for the direction, positionAlongPath for the position;
/// what has no keys stays as it is.
[[nodiscard]] Light lightAlongPath(Light light, const LightPathKeys& keys, double t) noexcept;

} // namespace geometry::scene
