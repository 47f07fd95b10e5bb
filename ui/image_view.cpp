#include "image_view.h"

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
bool usable(const Rect& panel, int width, int height) noexcept {
    return width > 0 && height > 0 && panel.w > 0.f && panel.h > 0.f && std::isfinite(panel.w) &&
           std::isfinite(panel.h);
}
float scaleOf(const ImageView& v, const Rect& panel, int width, int height) noexcept {
    if (v.zoom > 0.f && std::isfinite(v.zoom)) return std::clamp(v.zoom, kMinZoom, kMaxZoom);
    return fitScale(panel, width, height);
}
glm::vec2 centreOf(const ImageView& v) noexcept {
    if (v.zoom <= 0.f || !std::isfinite(v.zoom)) return glm::vec2(0.5f); // fit is always centred
    return {std::isfinite(v.centre.x) ? std::clamp(v.centre.x, 0.f, 1.f) : 0.5f,
            std::isfinite(v.centre.y) ? std::clamp(v.centre.y, 0.f, 1.f) : 0.5f};
}
} // namespace

float fitScale(const Rect& panel, int width, int height) noexcept {
    if (!usable(panel, width, height)) return 0.f;
    return std::min(panel.w / float(width), panel.h / float(height));
}

ImagePlacement placeImage(const ImageView& view, const Rect& panel, int width, int height) noexcept {
    ImagePlacement p;
    p.screen = {panel.x, panel.y, 0.f, 0.f};
    if (!usable(panel, width, height)) return p;
    const float s = scaleOf(view, panel, width, height);
    const glm::vec2 c = centreOf(view);
    const glm::vec2 size{float(width), float(height)};
    // The image's top-left corner on screen, then the visible part clipped to the panel.
    const glm::vec2 origin = glm::vec2(panel.x + panel.w * 0.5f, panel.y + panel.h * 0.5f) - c * size * s;
    const glm::vec2 lo = glm::max(origin, glm::vec2(panel.x, panel.y));
    const glm::vec2 hi = glm::min(origin + size * s, glm::vec2(panel.right(), panel.bottom()));
    p.scale = s;
    if (hi.x <= lo.x || hi.y <= lo.y) return p;
    p.screen = {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
    p.uvMin = (lo - origin) / (size * s);
    p.uvMax = (hi - origin) / (size * s);
    return p;
}

std::optional<glm::vec2> screenAt(const ImageView& view, const Rect& panel, int width, int height,
                                  glm::vec2 imagePoint) noexcept {
    if (!usable(panel, width, height)) return std::nullopt;
    const float s = scaleOf(view, panel, width, height);
    const glm::vec2 size{float(width), float(height)};
    const glm::vec2 origin = glm::vec2(panel.x + panel.w * 0.5f, panel.y + panel.h * 0.5f) - centreOf(view) * size * s;
    return origin + imagePoint * s;
}

std::optional<glm::ivec2> pixelAt(const ImageView& view, const Rect& panel, int width, int height,
                                  glm::vec2 p) noexcept {
    const ImagePlacement place = placeImage(view, panel, width, height);
    if (!place.screen.contains(p.x, p.y) || !std::isfinite(p.x) || !std::isfinite(p.y)) return std::nullopt;
    const glm::vec2 uv = place.uvMin + (p - glm::vec2(place.screen.x, place.screen.y)) /
                                           glm::vec2(place.screen.w, place.screen.h) * (place.uvMax - place.uvMin);
    const glm::ivec2 px(std::clamp(int(std::floor(uv.x * float(width))), 0, width - 1),
                        std::clamp(int(std::floor(uv.y * float(height))), 0, height - 1));
    return px;
}

ImageView zoomAround(const ImageView& view, const Rect& panel, int width, int height, glm::vec2 cursor,
                     float factor) noexcept {
    if (!usable(panel, width, height) || !std::isfinite(factor) || factor <= 0.f) return view;
    const float s0 = scaleOf(view, panel, width, height);
    const float s1 = std::clamp(s0 * factor, kMinZoom, kMaxZoom);
    const glm::vec2 size{float(width), float(height)};
    const glm::vec2 mid(panel.x + panel.w * 0.5f, panel.y + panel.h * 0.5f);
    if (!std::isfinite(cursor.x) || !std::isfinite(cursor.y)) cursor = mid;
    // The image point under the cursor stays put: c1 = q − (cursor − mid) / (s1·size).
    const glm::vec2 c0 = centreOf(view);
    const glm::vec2 q = c0 + (cursor - mid) / (s0 * size);
    ImageView out;
    out.zoom = s1;
    out.centre = glm::clamp(q - (cursor - mid) / (s1 * size), glm::vec2(0.f), glm::vec2(1.f));
    return out;
}

ImageView panBy(const ImageView& view, const Rect& panel, int width, int height, glm::vec2 delta) noexcept {
    if (!usable(panel, width, height) || !std::isfinite(delta.x) || !std::isfinite(delta.y)) return view;
    const float s = scaleOf(view, panel, width, height);
    ImageView out;
    out.zoom = s; // a panned view is no longer "fit"
    out.centre = glm::clamp(centreOf(view) - delta / (s * glm::vec2(float(width), float(height))), glm::vec2(0.f),
                            glm::vec2(1.f));
    return out;
}

ImageView oneToOne(const ImageView& view) noexcept {
    ImageView out = view;
    out.centre = centreOf(view);
    out.zoom = 1.f;
    return out;
}

} // namespace ui
