#pragma once
// The shadow plan: everything the renderer needs to draw shadows, decided here and nowhere
// else (DESIGN §2). A plain value: rendering, overlays, charts and tests use the same plan.
#include "scene.h"

#include <vector>

namespace geometry {

struct Viewport {
    int width = 1280;
    int height = 720;
    [[nodiscard]] float aspect() const noexcept { return height > 0 ? float(width) / float(height) : 1.f; }
};

struct ShadowSettings {
    int resolution = 2048;     // shadow-map side in texels
    float constantBias = 0.05f; // z_offset (Barroso Table 1), in scene units along l
};

struct SplitPlan {
    float near = 0.f, far = 0.f;       // [n_i, f_i], view distance
    std::vector<glm::vec3> body;       // focus body B_i (world space); empty when V_i misses S
    glm::mat4 lightView{1.f};          // world → light space
    glm::mat4 lightProj{1.f};          // light space → shadow clip space (B_i inside the unit cube)
    glm::mat4 lightViewProj{1.f};
    int resolution = 0;
    float depthBias = 0.f;             // the constant bias in this map's depth units [0, 1]
    glm::vec2 bodyDepthRange{0.f, 1.f}; // depth of B_i in this map, for display
    [[nodiscard]] bool empty() const noexcept { return body.empty(); }
};

struct ShadowPlan {
    glm::vec3 l{0.f, -1.f, 0.f}; // light direction, unit
    glm::vec3 v{0.f, 0.f, -1.f}; // view direction, unit
    float gammaDeg = 0.f;        // γ = acos(|v·l|)
    float lightViewAngleDeg = 0.f; // acos(v·l): 0 light behind the eye, 180 facing it
    glm::mat4 eyeView{1.f}, eyeProj{1.f};
    std::vector<SplitPlan> splits;
};

/// Plans the shadow maps for one frame. Pure; never returns NaN matrices (an empty focus
/// body gives an empty split, which the renderer treats as "nothing casts a shadow").
[[nodiscard]] ShadowPlan planShadows(const ShadowSettings& settings, const Aabb& S, const Camera& camera,
                                     const DirectionalLight& light, const Viewport& viewport);

/// Light-space rotation looking along l, with light-space +y along the view direction projected
/// onto the plane ⊥ l (a fixed axis when v ∥ l).
[[nodiscard]] glm::mat4 lightSpaceRotation(const glm::vec3& l, const glm::vec3& v) noexcept;

/// Orthographic projection fitting `points` in light space; its near plane (towards the light)
/// is pulled back to S so that every caster between B and the light is kept (DESIGN §3.1).
[[nodiscard]] glm::mat4 fitOrthographic(const glm::mat4& lightView, const std::vector<glm::vec3>& points,
                                        const Aabb& S) noexcept;

} // namespace geometry
