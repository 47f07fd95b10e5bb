#include "image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <stdexcept>

namespace renderer {

Image readTexture(GLuint texture, int width, int height) {
    Image img;
    img.width = width;
    img.height = height;
    std::vector<uint8_t> raw(size_t(width) * height * 4);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    img.rgba.resize(raw.size());
    const size_t row = size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::memcpy(&img.rgba[size_t(y) * row], &raw[size_t(height - 1 - y) * row], row);
    return img;
}

void writePng(const std::string& path, const Image& image) {
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
        throw std::runtime_error("cannot write PNG " + path);
}

Image readImageFile(const std::string& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!data) throw std::runtime_error("cannot read image " + path + ": " + stbi_failure_reason());
    Image img{w, h, std::vector<uint8_t>(data, data + size_t(w) * h * 4)};
    stbi_image_free(data);
    return img;
}

} // namespace renderer
