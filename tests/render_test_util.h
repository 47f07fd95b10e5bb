#pragma once
// Helpers for headless render tests: projecting world points to image pixels, reading colours.
#include "geometry/shadow/shadow_plan.h"
#include "renderer/image.h"

#include <optional>

namespace testutil {

/// Pixel (x right, y down, top row 0) of a world point in the eye image, if on screen.
inline std::optional<glm::ivec2> project(const geometry::shadow::ShadowPlan& plan, const glm::vec3& p, int w, int h) {
    const glm::vec4 c = plan.eyeProj * plan.eyeView * glm::vec4(p, 1.f);
    if (!(c.w > 0.f)) return std::nullopt;
    const glm::vec3 ndc = glm::vec3(c) / c.w;
    const int x = int((ndc.x * 0.5f + 0.5f) * float(w));
    const int y = int((0.5f - ndc.y * 0.5f) * float(h));
    if (x < 0 || y < 0 || x >= w || y >= h) return std::nullopt;
    return glm::ivec2(x, y);
}

inline float luminance(const geometry::analysis::Image& img, glm::ivec2 p) {
    const uint8_t* px = img.at(p.x, p.y);
    return (0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2]) / 255.f;
}

} // namespace testutil
