#include "renderer/image.h"

#include <cstring>

namespace renderer {

geometry::analysis::Image readTexture(GLuint texture, int width, int height) {
    geometry::analysis::Image img;
    img.width = width;
    img.height = height;
    std::vector<uint8_t> raw(size_t(width) * height * 4);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    img.rgba.resize(raw.size());
    const size_t row = size_t(width) * 4;
    for (int y = 0; y < height; ++y) std::memcpy(&img.rgba[size_t(y) * row], &raw[size_t(height - 1 - y) * row], row);
    return img;
}

} // namespace renderer
