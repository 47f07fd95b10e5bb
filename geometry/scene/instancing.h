#pragma once
// Instanced meshes (docs/design.md §2 "Instances"): placements made from a grid, and the same
// scene with every placement a mesh of its own (what instancing must be indistinguishable from).
#include "geometry/scene/scene.h"

#include <array>
#include <cstdint>
#include <vector>

namespace geometry::scene {

/// At most this many placements per mesh (64 bytes each): a million bolts is a plant.
inline constexpr size_t kMaxInstances = size_t(1) << 20;

/// Translations on a regular grid: count[0] × count[1] × count[2] placements, x fastest, at
/// origin + (i·spacing.x, j·spacing.y, k·spacing.z). Empty when any count is 0.
[[nodiscard]] std::vector<glm::mat4> gridInstances(const std::array<uint32_t, 3>& count, const glm::vec3& spacing,
                                                   const glm::vec3& origin = glm::vec3(0.f));

/// The scene with each placement of an instanced mesh copied into a mesh of its own (transform
/// instances[i] · transform, chunk bounds carried by instances[i]: the same boxes
/// Mesh::placementBounds gives), in placement order where the instanced mesh was.
[[nodiscard]] Scene flattenInstances(const Scene& scene);

} // namespace geometry::scene
