#include "renderer/image.h"

namespace renderer {

geometry::analysis::Image readTexture(GLuint texture, int width, int height) {
    geometry::analysis::Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(size_t(width) * height * 4);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    flipRows(img.rgba, size_t(width) * 4, height);
    return img;
}

} // namespace renderer
