#pragma once
// CPU-side RGBA8 images and their PNG files.
#include <cstdint>
#include <string>
#include <vector>

namespace geometry::analysis {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba; // top row first
    [[nodiscard]] const uint8_t* at(int x, int y) const noexcept { return &rgba[4 * (size_t(y) * width + x)]; }
};

/// Writes PNG; throws std::runtime_error naming the path on failure.
void writePng(const std::string& path, const Image& image);
/// Reads PNG/any stb-supported image as RGBA8; throws on failure.
[[nodiscard]] Image readImageFile(const std::string& path);

} // namespace geometry::analysis
