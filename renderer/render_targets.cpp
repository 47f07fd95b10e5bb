#include "render_targets.h"

#include <stdexcept>
#include <string>

namespace renderer {

static void checkComplete(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + " framebuffer incomplete (status " + std::to_string(status) + ")");
}

static GLuint makeTexture2D(GLenum format, int w, int h, GLenum filter) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

static GLuint makeTextureArray(GLenum format, int res, int layers, GLenum filter) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D_ARRAY, t);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, format, res, res, layers);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

LayeredTarget::~LayeredTarget() { release(); }

void LayeredTarget::release() noexcept {
    if (layers_ > 0) glDeleteFramebuffers(layers_, fbos_);
    if (depth_) glDeleteTextures(1, &depth_);
    if (colour_) glDeleteTextures(1, &colour_);
    depth_ = colour_ = 0;
    layers_ = resolution_ = 0;
}

void LayeredTarget::ensure(int resolution, int layers, GLenum colourFormat, bool depth) {
    if (resolution == resolution_ && layers == layers_ && colourFormat == colourFormat_ && depth == hasDepth_) return;
    if (layers < 1 || layers > geometry::shadow::kMaxSplits)
        throw std::runtime_error("shadow map layers must be 1.." + std::to_string(geometry::shadow::kMaxSplits));
    release();
    if (depth) depth_ = makeTextureArray(GL_DEPTH_COMPONENT32F, resolution, layers, GL_NEAREST);
    if (colourFormat) colour_ = makeTextureArray(colourFormat, resolution, layers, GL_LINEAR);
    glGenFramebuffers(layers, fbos_);
    for (int i = 0; i < layers; ++i) {
        glBindFramebuffer(GL_FRAMEBUFFER, fbos_[i]);
        if (depth_) glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_, 0, i);
        if (colour_) {
            glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, colour_, 0, i);
            glDrawBuffer(GL_COLOR_ATTACHMENT0);
        } else {
            glDrawBuffer(GL_NONE);
            glReadBuffer(GL_NONE);
        }
        checkComplete("shadow map");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    resolution_ = resolution;
    layers_ = layers;
    colourFormat_ = colourFormat;
    hasDepth_ = depth;
}

void LayeredTarget::bindLayer(int layer, int size) const noexcept {
    glBindFramebuffer(GL_FRAMEBUFFER, fbos_[layer]);
    glViewport(0, 0, size, size);
}

ColorTarget::~ColorTarget() { release(); }

void ColorTarget::release() noexcept {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (color_) glDeleteTextures(1, &color_);
    if (depth_) glDeleteTextures(1, &depth_);
    fbo_ = color_ = depth_ = 0;
    width_ = height_ = 0;
}

void ColorTarget::ensure(int width, int height, GLenum format) {
    if (width == width_ && height == height_ && format == format_) return;
    if (width < 1 || height < 1) throw std::runtime_error("view size must be at least 1x1");
    release();
    format_ = format;
    color_ = makeTexture2D(format, width, height, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    depth_ = makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
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

void ColorTarget::bindAndClear(float r, float g, float b) const noexcept {
    bind();
    glClearColor(r, g, b, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void ColorTarget::unbind() noexcept { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

EyeBuffers::~EyeBuffers() { release(); }

void EyeBuffers::release() noexcept {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    glDeleteFramebuffers(2, blurFbos_);
    glDeleteTextures(Count, textures_);
    glDeleteTextures(2, blur_);
    if (depth_) glDeleteTextures(1, &depth_);
    fbo_ = depth_ = 0;
    for (auto& t : textures_) t = 0;
    for (int i = 0; i < 2; ++i) blur_[i] = blurFbos_[i] = 0;
    width_ = height_ = 0;
}

void EyeBuffers::ensure(int width, int height) {
    if (width == width_ && height == height_) return;
    if (width < 1 || height < 1) throw std::runtime_error("view size must be at least 1x1");
    release();
    const GLenum formats[Count] = {GL_RGBA16F, GL_RGBA16F, GL_R16F, GL_RGBA32F, GL_RGBA32F, GL_RGBA16F};
    for (int i = 0; i < Count; ++i)
        textures_[i] = makeTexture2D(formats[i], width, height, i == Aux || i == Position ? GL_NEAREST : GL_LINEAR);
    depth_ = makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    GLenum drawBuffers[Count];
    for (int i = 0; i < Count; ++i) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, textures_[i], 0);
        drawBuffers[i] = GL_COLOR_ATTACHMENT0 + i;
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
    glDrawBuffers(Count, drawBuffers);
    checkComplete("eye");
    glGenFramebuffers(2, blurFbos_);
    for (int i = 0; i < 2; ++i) {
        blur_[i] = makeTexture2D(GL_R16F, width, height, GL_LINEAR);
        glBindFramebuffer(GL_FRAMEBUFFER, blurFbos_[i]);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, blur_[i], 0);
        checkComplete("eye blur");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    width_ = width;
    height_ = height;
}

void EyeBuffers::bind() const noexcept {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
}

void EyeBuffers::bindBlur(int i) const noexcept {
    glBindFramebuffer(GL_FRAMEBUFFER, blurFbos_[i]);
    glViewport(0, 0, width_, height_);
}

} // namespace renderer
