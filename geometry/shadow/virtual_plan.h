#pragma once
// The virtual shadow map's part of a frame's plan (technique = virtual; issue 34, docs/design.md
// §3.11): the levels around the eye, the depth range every page shares, and each page's projection.
// It depends on the scene bounds, the light and the eye alone, so a page keeps its texels from one
// frame to the next until the light or the scene changes (`content`).
#include "geometry/scene/scene.h"
#include "geometry/shadow/settings.h"
#include "geometry/shadow/virtual_pages.h"

#include <cstdint>
#include <vector>

namespace geometry::shadow {

struct VirtualPlan {
    bool enabled = false;
    VirtualMapConfig config;
    LightFrame frame;
    glm::dvec3 eye{0.0};
    std::vector<ClipLevel> levels;
    /// l·x over the scene bounds S: every page's depth runs over it (orthographic along l), so depths of
    /// all pages and levels compare alike and a kept page stays valid while the eye moves.
    double depthLo = 0, depthHi = 1;
    /// What a page's texels depend on besides its key: the light, the depth range, the levels' sizes
    /// (and, set by the planner, the biases that change how the pages are drawn).
    uint64_t content = 0;

    /// World → clip space of page k: orthographic along l over the page's square and [depthLo, depthHi].
    [[nodiscard]] glm::dmat4 pageViewProj(const PageKey& k) const noexcept;
    /// Level k's square's lower-left corner in the light's plane, relative to the eye's projection
    /// (what the shaders add to a point's plane coordinates taken relative to the eye).
    [[nodiscard]] glm::dvec2 levelOrigin(int k) const noexcept;
    /// Linear depth of x in the pages: (l·x − depthLo) / (depthHi − depthLo).
    [[nodiscard]] double depthOf(const glm::dvec3& x) const noexcept;
};

/// The pool's depth texels (32-bit) and the page table (32 bits per page of every level).
[[nodiscard]] uint64_t virtualMemoryBytes(const VirtualMapConfig& config) noexcept;

/// The virtual plan for directional light `l` seen from `eye` over scene bounds S. Level 0's side is
/// chosen from S and l alone (never from the eye, which would change every texel as it moves): the
/// coarsest level's square, which follows the eye, covers S from any eye above S.
[[nodiscard]] VirtualPlan planVirtual(const VirtualSettings& settings, const scene::Aabb& S, const glm::vec3& eye,
                                      const glm::vec3& l);

} // namespace geometry::shadow
