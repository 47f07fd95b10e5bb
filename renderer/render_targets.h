#pragma once
// Off-screen targets: the shadow-map array and colour targets for the views.
#include "gl/gl_api.h"

namespace renderer {

/// Depth texture array, one layer per split, with one framebuffer per layer.
class ShadowMapArray {
public:
    ShadowMapArray() = default;
    ~ShadowMapArray();
    ShadowMapArray(const ShadowMapArray&) = delete;
    ShadowMapArray& operator=(const ShadowMapArray&) = delete;
    /// (Re)allocates when size or layer count change.
    void ensure(int resolution, int layers);
    void bindLayer(int layer) const noexcept;
    [[nodiscard]] GLuint texture() const noexcept { return texture_; }
    [[nodiscard]] int resolution() const noexcept { return resolution_; }
    [[nodiscard]] int layers() const noexcept { return layers_; }

private:
    void release() noexcept;
    GLuint texture_ = 0;
    GLuint fbos_[8] = {};
    int resolution_ = 0, layers_ = 0;
};

/// RGBA8 colour + depth target.
class ColorTarget {
public:
    ColorTarget() = default;
    ~ColorTarget();
    ColorTarget(const ColorTarget&) = delete;
    ColorTarget& operator=(const ColorTarget&) = delete;
    void ensure(int width, int height);
    void bind() const noexcept;
    [[nodiscard]] GLuint texture() const noexcept { return color_; }
    [[nodiscard]] GLuint framebuffer() const noexcept { return fbo_; }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

private:
    void release() noexcept;
    GLuint fbo_ = 0, color_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace renderer
