#include "light_gizmo.h"

#include <algorithm>
#include <cmath>

namespace ui {

namespace {

/// The image direction of world direction `d` at world point `p` (projected at `at`): the step to a
/// point a little along d, normalised; none when that point does not project or d is seen end-on.
std::optional<glm::vec2> imageDirection(const geometry::scene::Camera& camera, glm::vec2 size, const glm::vec3& p,
                                        glm::vec2 at, const glm::vec3& d) noexcept {
    // A step short against p's distance keeps the tip in front of the eye for any d.
    const float step = 0.05f * std::max(glm::length(p - camera.eye), 1e-6f);
    const auto tip = projectToImage(camera, size, p + step * d);
    if (!tip) return std::nullopt;
    const glm::vec2 v = *tip - at;
    const float len = glm::length(v);
    if (!(len > 1e-3f * std::max(size.x, size.y))) return std::nullopt; // end-on: no readable arrow
    return v / len;
}

} // namespace

std::optional<glm::vec2> projectToImage(const geometry::scene::Camera& camera, glm::vec2 size,
                                        const glm::vec3& p) noexcept {
    if (!(size.x > 0.f && size.y > 0.f)) return std::nullopt;
    const glm::vec4 clip = camera.projection(size.x / size.y) * camera.view() * glm::vec4(p, 1.f);
    if (!(clip.w > 1e-12f) || !std::isfinite(clip.x) || !std::isfinite(clip.y)) return std::nullopt;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2((ndc.x + 1.f) * 0.5f * size.x, (1.f - ndc.y) * 0.5f * size.y);
}

std::vector<LightMark> lightMarks(const geometry::scene::Camera& camera, glm::vec2 size,
                                  std::span<const geometry::scene::Light> lights, size_t inspected) {
    std::vector<LightMark> marks;
    marks.reserve(lights.size());
    for (size_t i = 0; i < lights.size(); ++i) {
        const geometry::scene::Light& light = lights[i];
        LightMark m;
        m.index = i;
        m.type = light.type;
        m.inspected = i == inspected;
        // A directional light has no place: its arrow starts at the view centre, the target.
        const glm::vec3 anchor = light.positional() ? light.position : camera.target;
        m.at = light.positional() ? projectToImage(camera, size, anchor) : std::optional<glm::vec2>(0.5f * size);
        if (m.at && light.type != geometry::scene::LightType::Point)
            m.direction = imageDirection(camera, size, anchor, *m.at, light.l());
        marks.push_back(m);
    }
    return marks;
}

} // namespace ui
