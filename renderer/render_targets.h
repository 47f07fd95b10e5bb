#pragma once
// Off-screen targets: layered (texture array) targets for shadow maps and VSM moments, the eye
// pass's buffers, and plain colour targets for the views.
#include "geometry/shadow/splits.h"
#include "gl/gl_api.h"

namespace renderer {

/// A texture array (one layer per split) with an optional colour array and an optional depth
/// array, and one framebuffer per layer.
class LayeredTarget {
public:
    LayeredTarget() = default;
    ~LayeredTarget();
    LayeredTarget(const LayeredTarget&) = delete;
    LayeredTarget& operator=(const LayeredTarget&) = delete;
    /// (Re)allocates when size, layers or formats change. colourFormat 0 = none; depth false = none.
    void ensure(int resolution, int layers, GLenum colourFormat, bool depth);
    /// Binds layer `layer` and sets the viewport to `size`² (a split may use less than the array).
    void bindLayer(int layer, int size) const noexcept;
    [[nodiscard]] GLuint depthTexture() const noexcept { return depth_; }
    [[nodiscard]] GLuint colourTexture() const noexcept { return colour_; }
    [[nodiscard]] int resolution() const noexcept { return resolution_; }
    [[nodiscard]] int layers() const noexcept { return layers_; }

private:
    void release() noexcept;
    GLuint depth_ = 0, colour_ = 0;
    GLuint fbos_[geometry::shadow::kMaxSplits] = {}; // one per layer
    int resolution_ = 0, layers_ = 0;
    GLenum colourFormat_ = 0;
    bool hasDepth_ = false;
};

/// Colour (RGBA8 unless told otherwise) + depth target (views, exports, the lights' sum).
class ColorTarget {
public:
    ColorTarget() = default;
    ~ColorTarget();
    ColorTarget(const ColorTarget&) = delete;
    ColorTarget& operator=(const ColorTarget&) = delete;
    void ensure(int width, int height, GLenum format = GL_RGBA8);
    void bind() const noexcept;
    /// Binds and clears to an opaque colour (off-screen UI frames: the dashboard, chart PNGs).
    void bindAndClear(float r, float g, float b) const noexcept;
    /// Back to the default framebuffer.
    static void unbind() noexcept;
    [[nodiscard]] GLuint texture() const noexcept { return color_; }
    [[nodiscard]] GLuint framebuffer() const noexcept { return fbo_; }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

private:
    void release() noexcept;
    GLuint fbo_ = 0, color_ = 0, depth_ = 0;
    GLenum format_ = GL_RGBA8; // of the texture made (a 0 × 0 target has none)
    int width_ = 0, height_ = 0;
};

/// The eye pass's outputs: base (albedo·ambient, view depth), direct light, shadow mask, aux
/// (map texel, split, map depth), position (world, aliasing m), normal (n, N·L), depth; plus two
/// mask buffers for the eye-space blur.
class EyeBuffers {
public:
    enum Attachment { Base, Direct, Mask, Aux, Position, Normal, Count };
    EyeBuffers() = default;
    ~EyeBuffers();
    EyeBuffers(const EyeBuffers&) = delete;
    EyeBuffers& operator=(const EyeBuffers&) = delete;
    void ensure(int width, int height);
    void bind() const noexcept;
    /// Binds blur buffer i (0 or 1) as the only render target.
    void bindBlur(int i) const noexcept;
    [[nodiscard]] GLuint texture(Attachment a) const noexcept { return textures_[a]; }
    [[nodiscard]] GLuint blurTexture(int i) const noexcept { return blur_[i]; }
    [[nodiscard]] GLuint depthTexture() const noexcept { return depth_; }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

private:
    void release() noexcept;
    GLuint fbo_ = 0, depth_ = 0, textures_[Count] = {};
    GLuint blurFbos_[2] = {}, blur_[2] = {};
    int width_ = 0, height_ = 0;
};

} // namespace renderer
