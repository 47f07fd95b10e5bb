#include "geometry/shadow/caster_detail.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geometry::shadow {

namespace {

/// The smaller world-space side of one texel of `split`'s map at p: a small step across the light
/// in two directions, measured in the map.
float finestTexelAt(const ShadowPlan& plan, const SplitPlan& split, const glm::vec3& p) noexcept {
    const auto uv = [&](const glm::vec3& x, bool& ok) {
        const glm::vec4 c = split.lightViewProj * glm::vec4(x, 1.f);
        ok = ok && c.w > 0.f;
        return glm::vec2(c) / c.w * 0.5f;
    };
    const glm::vec3 l = plan.l;
    const glm::vec3 e1 = glm::normalize(glm::cross(l, std::abs(l.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 e2 = glm::cross(l, e1);
    const float h = 1e-3f * std::max(1.f, glm::length(p - plan.eye));
    bool ok = true;
    const glm::vec2 p0 = uv(p, ok);
    const float du = glm::length(uv(p + e1 * h, ok) - p0), dv = glm::length(uv(p + e2 * h, ok) - p0);
    const float size = h / (std::max(du, dv) * float(std::max(split.resolution, 1)));
    return ok && std::isfinite(size) && size > 0.f ? size : std::numeric_limits<float>::quiet_NaN();
}

} // namespace

float finestTexelOver(const ShadowPlan& plan, int split, const scene::Aabb& box) noexcept {
    float finest = std::numeric_limits<float>::quiet_NaN();
    if (split < 0 || split >= int(plan.splits.size()) || box.empty()) return finest;
    const SplitPlan& s = plan.splits[size_t(split)];
    const auto take = [&](const glm::vec3& p) {
        const float t = finestTexelAt(plan, s, p);
        if (std::isfinite(t) && !(t >= finest)) finest = t; // NaN-safe: the first finite one wins
    };
    for (const glm::vec3& c : box.corners()) take(c);
    take(box.center());
    return finest;
}

float casterErrorBudget(const ShadowPlan& plan, int split, const scene::Aabb& box) noexcept {
    if (!(plan.casterLodTexels > 0.f)) return 0.f;
    const float texel = finestTexelOver(plan, split, box);
    return std::isfinite(texel) ? plan.casterLodTexels * texel : 0.f;
}

} // namespace geometry::shadow
