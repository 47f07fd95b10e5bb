#include "light_list.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ui {

namespace {

bool finite3(const glm::vec3& v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string shortNumber(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

} // namespace

std::optional<std::string> lightProblem(const geometry::scene::Light& l) {
    if (!finite3(l.direction)) return "the direction must be finite";
    if (!(glm::length(l.direction) > 0.f)) return "the direction must not be zero";
    if (!finite3(l.position)) return "the position must be finite";
    // Checked for every type, as scene files do: a directional light may become a spot light later.
    if (!(l.coneDeg > 0.f && l.coneDeg < 180.f))
        return "the cone angle must be in (0, 180)°, got " + shortNumber(l.coneDeg);
    if (!(l.range > 0.f && std::isfinite(l.range))) return "the range must be > 0, got " + shortNumber(l.range);
    if (!(l.radius >= 0.f && std::isfinite(l.radius))) return "the radius must be ≥ 0, got " + shortNumber(l.radius);
    return std::nullopt;
}

std::optional<std::string> lightListProblem(std::span<const geometry::scene::Light> lights) {
    if (lights.empty() || lights.size() > geometry::scene::kMaxLights)
        return "a scene holds 1 to " + std::to_string(geometry::scene::kMaxLights) + " lights, not " +
               std::to_string(lights.size());
    for (size_t i = 0; i < lights.size(); ++i)
        if (auto problem = lightProblem(lights[i])) return "light " + std::to_string(i) + ": " + *problem;
    return std::nullopt;
}

geometry::scene::Light defaultSpotLight(const geometry::scene::Aabb& bounds) {
    geometry::scene::Light l;
    l.type = geometry::scene::LightType::Spot;
    l.direction = {0.f, -1.f, 0.f};
    l.coneDeg = 60.f;
    l.radius = 0.f;
    if (bounds.empty() || !finite3(bounds.lo) || !finite3(bounds.hi)) {
        l.position = {0.f, 10.f, 0.f};
        l.range = 100.f;
        return l;
    }
    const glm::vec3 c = bounds.center(), size = bounds.hi - bounds.lo;
    // Above the top by a quarter of the diagonal, so the cone sees a good part of the scene.
    const float lift = std::max(0.25f * glm::length(size), 1.f);
    l.position = {c.x, bounds.hi.y + lift, c.z};
    float reach = 0.f;
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner{k & 1 ? bounds.hi.x : bounds.lo.x, k & 2 ? bounds.hi.y : bounds.lo.y,
                               k & 4 ? bounds.hi.z : bounds.lo.z};
        reach = std::max(reach, glm::length(corner - l.position));
    }
    l.range = reach * 1.01f;
    return l;
}

} // namespace ui
