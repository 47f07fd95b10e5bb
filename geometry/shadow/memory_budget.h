#pragma once
// How much shadow-map memory a configuration needs and the resolution that fits the budget
// (docs/design.md §3 "Memory budget"). The plan applies it, so splits[i].resolution states what is
// drawn and screening at half size follows the same rule as full size. Pure.
#include "geometry/shadow/settings.h"

#include <cstdint>

namespace geometry::shadow {

/// All shadow textures together: depth layers, peeling's three arrays, moments and their blur target.
inline constexpr double kShadowMemoryBudgetBytes = 1.5 * 1024 * 1024 * 1024;

/// Bytes per texel of one split's layer: 4 (32-bit depth), 12 when peeling (bias midpoint or dual
/// depth keep three arrays), 4 + 2·4·moments for the moment filters (the map and its blur target).
[[nodiscard]] double shadowBytesPerTexel(const ShadowSettings& s) noexcept;

/// The bytes of splits.count layers of resolution² texels.
[[nodiscard]] double shadowMapBytes(const ShadowSettings& s, int resolution) noexcept;

/// s.resolution halved until the maps fit `budget` (at least 16): the resolution the plan draws.
[[nodiscard]] int budgetedResolution(const ShadowSettings& s, double budget = kShadowMemoryBudgetBytes) noexcept;

} // namespace geometry::shadow
