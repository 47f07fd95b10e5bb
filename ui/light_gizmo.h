#pragma once
// Where the light gizmo over the eye view draws each light (docs/design.md §3.10): a positional
// light's position projected into the eye image with its index, a spot light's axis as a short
// arrow, a directional light as an arrow from the view centre. Pure math on plain values; the eye
// panel draws the marks with ImDrawList.
#include "geometry/scene/scene.h"

#include <optional>
#include <span>
#include <vector>

namespace ui {

/// Where world point `p` appears in the eye image that `camera` draws at `size` pixels: image
/// coordinates, x right and y down from the image's top-left corner ((0, 0) that corner, `size` the
/// opposite one). nullopt when p is behind the eye or on the eye's plane (or the input is degenerate).
[[nodiscard]] std::optional<glm::vec2> projectToImage(const geometry::scene::Camera& camera, glm::vec2 size,
                                                      const glm::vec3& p) noexcept;

/// One light's mark in the eye image.
struct LightMark {
    size_t index = 0;
    geometry::scene::LightType type = geometry::scene::LightType::Directional;
    bool inspected = false;
    /// The marker: a positional light's projected position (none when behind the eye), a directional
    /// light's arrow start, the image centre.
    std::optional<glm::vec2> at;
    /// Unit direction in the image of the light's axis (spot) or l (directional) at `at`; none for a
    /// point light, or where the axis is seen end-on.
    std::optional<glm::vec2> direction;
};

[[nodiscard]] std::vector<LightMark> lightMarks(const geometry::scene::Camera& camera, glm::vec2 size,
                                                std::span<const geometry::scene::Light> lights, size_t inspected);

} // namespace ui
