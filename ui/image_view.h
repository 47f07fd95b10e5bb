#pragma once
// Zoom and pan of an image inside a panel (RenderDoc's texture viewer): fit, 1:1, zoom around
// the cursor, pan by dragging, and the image pixel under a screen point. Pure math; the panels
// draw with the placement it returns.
#include "dashboard_layout.h"

#include <glm/glm.hpp>

#include <optional>

namespace ui {

struct ImageView {
    float zoom = 0.f;       // screen pixels per image pixel; 0 = fit the panel
    glm::vec2 centre{0.5f}; // the image point (0..1, top-left origin) shown at the panel centre
};

/// Where an image lands: the on-screen rectangle (clipped to the panel) and the image's
/// normalised coordinates at its corners (top-left origin, like renderer::Image).
struct ImagePlacement {
    Rect screen;
    glm::vec2 uvMin{0.f}, uvMax{1.f};
    float scale = 1.f; // screen pixels per image pixel
};

inline constexpr float kMinZoom = 1.f / 64.f;
inline constexpr float kMaxZoom = 64.f;

/// The scale at which a width × height image fits the panel (0 for an empty panel or image).
[[nodiscard]] float fitScale(const Rect& panel, int width, int height) noexcept;

[[nodiscard]] ImagePlacement placeImage(const ImageView& view, const Rect& panel, int width, int height) noexcept;

/// The image pixel (x right, y down) under screen point p, if the image covers it.
[[nodiscard]] std::optional<glm::ivec2> pixelAt(const ImageView& view, const Rect& panel, int width, int height,
                                                glm::vec2 p) noexcept;

/// The screen point where image point `imagePoint` (pixels, x right, y down from the top-left corner)
/// lands, inside the panel or not (overlays clip themselves); nullopt for an empty panel or image.
[[nodiscard]] std::optional<glm::vec2> screenAt(const ImageView& view, const Rect& panel, int width, int height,
                                                glm::vec2 imagePoint) noexcept;

/// Multiplies the zoom by `factor`, keeping the image point under `cursor` where it is.
[[nodiscard]] ImageView zoomAround(const ImageView& view, const Rect& panel, int width, int height, glm::vec2 cursor,
                                   float factor) noexcept;
/// Moves the image by `delta` screen pixels (a drag).
[[nodiscard]] ImageView panBy(const ImageView& view, const Rect& panel, int width, int height,
                              glm::vec2 delta) noexcept;
/// One image pixel per screen pixel, keeping the centre.
[[nodiscard]] ImageView oneToOne(const ImageView& view) noexcept;

} // namespace ui
