#include "texture.h"

#include "renderer/image.h"

#include <cstring>

namespace renderer {

Texture2D::~Texture2D() {
    if (texture_) glDeleteTextures(1, &texture_);
}

void Texture2D::upload(const geometry::analysis::Image& image) {
    if (image.width <= 0 || image.height <= 0) return;
    if (texture_ == 0 || width_ != image.width || height_ != image.height) {
        if (texture_) glDeleteTextures(1, &texture_);
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, image.width, image.height);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        width_ = image.width;
        height_ = image.height;
    }
    // GL textures are bottom row first, like the rendered views: upload flipped so every texture
    // the dashboard shows has the same orientation.
    std::vector<uint8_t> flipped(image.rgba.size());
    const size_t row = size_t(image.width) * 4;
    for (int y = 0; y < image.height; ++y)
        std::memcpy(&flipped[size_t(y) * row], &image.rgba[size_t(image.height - 1 - y) * row], row);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
}

geometry::analysis::Image readFramebuffer(GLuint framebuffer, int width, int height) {
    geometry::analysis::Image img;
    if (width <= 0 || height <= 0) return img;
    img.width = width;
    img.height = height;
    img.rgba.resize(size_t(width) * height * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (framebuffer == 0) glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    flipRows(img.rgba, size_t(width) * 4, height);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255; // the window has no meaningful alpha
    return img;
}

} // namespace renderer
