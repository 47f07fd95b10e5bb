#pragma once
// What the shadow-map passes read from a plan, as one comparable value: two plans with equal keys
// draw identical maps, so a renderer may keep the maps it drew last (ViewOptions::reuseShadowMaps)
// when only eye-side values changed (filter taps, receiver and normal offsets, blend bands).
#include "geometry/shadow/shadow_plan.h"

#include <glm/glm.hpp>

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
    int biasType = 0; // second depth, midpoint and dual depth draw other faces or peel
    bool linearZ = false;
    int momentFilter = -1;          // the moment filter (FilterType) whose moments pass and blur ran; −1: none
    int momentsKernel = 0;          // its blur width
    glm::vec3 momentExponents{0.f}; // esm c, evsm c+ and c− (the moments depend on them)
    float casterLodTexels = 0;      // the caster levels chosen per chunk…
    glm::vec3 lodEye{0.f};          // …measure their texels from the eye (caster_detail.h)
    [[nodiscard]] bool operator==(const ShadowMapKey&) const = default;
};

/// The values of `plan` the shadow passes (depth, peeling, combine, moments) depend on.
[[nodiscard]] ShadowMapKey shadowMapKey(const geometry::shadow::ShadowPlan& plan);

} // namespace renderer
