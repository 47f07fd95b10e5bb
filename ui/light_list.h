#pragma once
// The dashboard's light list (docs/design.md §3.10): what makes a light acceptable (the rules of
// scene files, geometry/io/scene_file.cpp, so a light the dashboard accepts is one a scene file may
// hold) and the light "Add" makes. Pure; the Lights group and the config file use it.
#include "geometry/scene/scene.h"

#include <optional>
#include <span>
#include <string>

namespace ui {

/// Why `light` cannot be drawn, as one line, or nullopt when it can: a direction that is not finite
/// or is zero, a position that is not finite, a cone angle outside (0, 180)°, a range that is not
/// finite and > 0, a radius that is not finite and ≥ 0.
[[nodiscard]] std::optional<std::string> lightProblem(const geometry::scene::Light& light);

/// Why `lights` cannot be a scene's light list (1 to kMaxLights valid lights), naming the light.
[[nodiscard]] std::optional<std::string> lightListProblem(std::span<const geometry::scene::Light> lights);

/// The light "Add" makes: a spot light above the centre of `bounds` (y up) looking straight down,
/// its range reaching every corner of the bounds. Empty bounds: 10 units above the origin.
[[nodiscard]] geometry::scene::Light defaultSpotLight(const geometry::scene::Aabb& bounds);

} // namespace ui
