#include "geometry/shadow/contact_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geometry::shadow {
namespace {

glm::vec2 mapUv(const SplitPlan& split, const glm::vec3& world) noexcept {
    const glm::vec4 clip = split.lightViewProj * glm::vec4(world, 1.f);
    return glm::vec2(clip) / clip.w * 0.5f + 0.5f;
}

} // namespace

float texelWorldSize(const ShadowPlan& plan, int split, const glm::vec3& p, int resolution) noexcept {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    if (split < 0 || split >= int(plan.splits.size()) || resolution <= 0) return nan;
    const SplitPlan& s = plan.splits[size_t(split)];
    // Two directions across the light, a step that scales with the distance to the eye (as eye.frag).
    const glm::vec3 l = plan.l;
    const glm::vec3 e1 = glm::normalize(glm::cross(l, std::abs(l.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 e2 = glm::cross(l, e1);
    const float h = 0.01f * std::max(1.f, glm::length(p - plan.eye));
    const glm::vec2 p0 = mapUv(s, p);
    const float du = glm::length(mapUv(s, p + e1 * h) - p0), dv = glm::length(mapUv(s, p + e2 * h) - p0);
    const float size = h / (std::max(std::min(du, dv), 1e-12f) * float(resolution));
    return std::isfinite(size) ? size : nan;
}

float contactDistance(const ShadowPlan& plan, int split, const glm::vec3& p, int resolution) noexcept {
    const float texel = texelWorldSize(plan, split, p, resolution);
    if (!std::isfinite(texel)) return texel;
    float bias = 0.f;
    switch (plan.bias.type) {
    case BiasType::Constant: bias = plan.receiverOffset; break;
    case BiasType::NormalOffset: bias = plan.bias.normalOffset * texel; break;
    case BiasType::Slope: bias = plan.bias.slope * texel; break;
    case BiasType::SlopeNormalOffset: bias = (plan.bias.slope + plan.bias.normalOffset) * texel; break;
    default: break; // depth peeling and second depth move the stored depth by the caster's thickness
    }
    return std::max(texel, bias);
}

} // namespace geometry::shadow
