#include "render_targets.h"

#include <stdexcept>
#include <string>

namespace renderer {

static void checkComplete(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + " framebuffer incomplete (status " + std::to_string(status) + ")");
}

ShadowMapArray::~ShadowMapArray() { release(); }

void ShadowMapArray::release() noexcept {
    if (layers_ > 0) glDeleteFramebuffers(layers_, fbos_);
    if (texture_) glDeleteTextures(1, &texture_);
    texture_ = 0;
    layers_ = resolution_ = 0;
}

void ShadowMapArray::ensure(int resolution, int layers) {
    if (resolution == resolution_ && layers == layers_) return;
    if (layers < 1 || layers > 8) throw std::runtime_error("shadow map layers must be 1..8");
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (resolution < 1 || resolution > maxSize)
        throw std::runtime_error("shadow map resolution " + std::to_string(resolution) + " is outside 1.." +
                                 std::to_string(maxSize) + " (GL_MAX_TEXTURE_SIZE)");
    release();
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture_);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH_COMPONENT32F, resolution, resolution, layers);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glGenFramebuffers(layers, fbos_);
    for (int i = 0; i < layers; ++i) {
        glBindFramebuffer(GL_FRAMEBUFFER, fbos_[i]);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture_, 0, i);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        checkComplete("shadow map");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    resolution_ = resolution;
    layers_ = layers;
}

void ShadowMapArray::bindLayer(int layer) const noexcept {
    glBindFramebuffer(GL_FRAMEBUFFER, fbos_[layer]);
    glViewport(0, 0, resolution_, resolution_);
}

ColorTarget::~ColorTarget() { release(); }

void ColorTarget::release() noexcept {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (color_) glDeleteTextures(1, &color_);
    if (depth_) glDeleteTextures(1, &depth_);
    fbo_ = color_ = depth_ = 0;
    width_ = height_ = 0;
}

void ColorTarget::ensure(int width, int height) {
    if (width == width_ && height == height_) return;
    if (width < 1 || height < 1) throw std::runtime_error("view size must be at least 1x1");
    release();
    glGenTextures(1, &color_);
    glBindTexture(GL_TEXTURE_2D, color_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenTextures(1, &depth_);
    glBindTexture(GL_TEXTURE_2D, depth_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, width, height);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
    checkComplete("colour");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    width_ = width;
    height_ = height;
}

void ColorTarget::bind() const noexcept {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
}

} // namespace renderer
