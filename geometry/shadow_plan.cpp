#include "shadow_plan.h"

#include "focus.h"

#include <glm/gtc/matrix_transform.hpp>
#include <algorithm>
#include <cmath>

namespace geometry {

glm::mat4 lightSpaceRotation(const glm::vec3& l, const glm::vec3& v) noexcept {
    glm::vec3 up = v - glm::dot(v, l) * l;
    if (glm::length(up) < 1e-4f) up = std::abs(l.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, -1);
    return glm::lookAt(glm::vec3(0.f), l, glm::normalize(up));
}

glm::mat4 fitOrthographic(const glm::mat4& lightView, const std::vector<glm::vec3>& points, const Aabb& S) noexcept {
    Aabb box;
    for (const auto& p : points) box.add(glm::vec3(lightView * glm::vec4(p, 1.f)));
    if (box.empty()) return glm::mat4(1.f);
    // Light space looks down −z, so +z points towards the light.
    for (const auto& c : S.corners()) box.hi.z = std::max(box.hi.z, (lightView * glm::vec4(c, 1.f)).z);
    // A small margin keeps points on the boundary inside after rounding, and never a zero-size box.
    const glm::vec3 margin = glm::max(box.extent() * 1e-4f, glm::vec3(1e-4f));
    box.lo -= margin;
    box.hi += margin;
    return glm::ortho(box.lo.x, box.hi.x, box.lo.y, box.hi.y, -box.hi.z, -box.lo.z);
}

/// Window depth [0, 1] range covered by `points` under `viewProj`.
static glm::vec2 depthRangeInMap(const glm::mat4& viewProj, const std::vector<glm::vec3>& points) noexcept {
    glm::vec2 r{1.f, 0.f};
    for (const auto& p : points) {
        const glm::vec4 c = viewProj * glm::vec4(p, 1.f);
        if (!(c.w > 0.f)) continue;
        const float d = std::clamp(c.z / c.w * 0.5f + 0.5f, 0.f, 1.f);
        r = {std::min(r.x, d), std::max(r.y, d)};
    }
    return r.x <= r.y ? r : glm::vec2(0.f, 1.f);
}

ShadowPlan planShadows(const ShadowSettings& settings, const Aabb& S, const Camera& camera,
                       const DirectionalLight& light, const Viewport& viewport) {
    ShadowPlan plan;
    plan.l = light.l();
    plan.v = camera.viewDir();
    plan.gammaDeg = gammaDeg(plan.v, plan.l);
    plan.lightViewAngleDeg = lightViewAngleDeg(plan.v, plan.l);
    plan.eyeView = camera.view();
    plan.eyeProj = camera.projection(viewport.aspect());

    SplitPlan split;
    split.near = camera.near;
    split.far = camera.far;
    split.resolution = settings.resolution;
    split.body = focusBody(frustumCorners(camera, viewport.aspect(), camera.near, camera.far), S, plan.l);
    if (!split.empty()) {
        split.lightView = lightSpaceRotation(plan.l, plan.v);
        split.lightProj = fitOrthographic(split.lightView, split.body, S);
        split.lightViewProj = split.lightProj * split.lightView;
        // glm::ortho maps view z to depth in [0, 1] with slope proj[2][2] / 2 per scene unit.
        split.depthBias = settings.constantBias * std::abs(split.lightProj[2][2]) * 0.5f;
        split.bodyDepthRange = depthRangeInMap(split.lightViewProj, split.body);
    }
    plan.splits.push_back(std::move(split));
    return plan;
}

} // namespace geometry
