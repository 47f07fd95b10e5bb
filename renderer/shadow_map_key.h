#pragma once
// What the shadow-map passes read from a plan, as one comparable value: two plans with equal keys
// draw identical maps, so a renderer may keep the maps it drew last (ViewOptions::reuseShadowMaps)
// when only eye-side values changed (filter taps, receiver and normal offsets, PCSS's sun). The
// settings it covers are those whose declaration says so (geometry/shadow/settings.h).
#include "geometry/shadow/shadow_plan.h"

#include <glm/glm.hpp>

#include <utility>
#include <vector>

namespace renderer {

struct ShadowMapKey {
    struct Split {
        glm::mat4 lightViewProj{1.f};
        int resolution = 0;
        bool empty = true;
        glm::vec2 linearDepth{0.f}; // lo and scale of the linear depth (linear z, moments)
        float dualDepthCap = 0.f;   // combine pass of dual depth
        [[nodiscard]] bool operator==(const Split&) const = default;
    };
    std::vector<Split> splits;
    glm::vec3 l{0.f};
    glm::vec2 polygonOffset{0.f};
    bool linearZ = false;  // the plan's choice (linear z, moments, PCSS)
    glm::vec3 lodEye{0.f}; // casters.lod = auto measures its texels from the eye (caster_detail.h)
    /// (row, value) for every setting whose row says the maps depend on it and that applies
    /// (SettingInfo::drawsMaps): derived from the declaration, never listed here by hand.
    std::vector<std::pair<int, double>> mapSettings;
    [[nodiscard]] bool operator==(const ShadowMapKey&) const = default;
};

/// The values of `plan` the shadow passes (depth, peeling, combine, moments) depend on.
[[nodiscard]] ShadowMapKey shadowMapKey(const geometry::shadow::ShadowPlan& plan);
/// The same, written over `key` (every field; its vectors keep their capacity, so a renderer's
/// per-frame key allocates nothing once warm).
void shadowMapKey(const geometry::shadow::ShadowPlan& plan, ShadowMapKey& key);

} // namespace renderer
