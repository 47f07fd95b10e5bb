#pragma once
// A CPU image shown on screen: the dashboard's heatmaps are computed on the CPU (from the read-back
// inspection buffers) and uploaded here so ImGui can draw them like the rendered views.
#include "image.h"

namespace renderer {

class Texture2D {
public:
    Texture2D() = default;
    ~Texture2D();
    Texture2D(const Texture2D&) = delete;
    Texture2D& operator=(const Texture2D&) = delete;
    /// Replaces the texture's content (reallocating when the size changes). Nearest filtering
    /// when magnified, so zoomed-in pixels stay pixels.
    void upload(const geometry::analysis::Image& image);
    [[nodiscard]] GLuint id() const noexcept { return texture_; }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

private:
    GLuint texture_ = 0;
    int width_ = 0, height_ = 0;
};

/// The bound read framebuffer's colour (the window's back buffer when `framebuffer` is 0) as an
/// image, top row first: the whole-dashboard screenshot.
[[nodiscard]] geometry::analysis::Image readFramebuffer(GLuint framebuffer, int width, int height);

} // namespace renderer
