#include "geometry/analysis/image.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>

namespace geometry::analysis {

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

} // namespace geometry::analysis
