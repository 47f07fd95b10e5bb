#pragma once
// Read-back of colour textures into CPU images.
#include "geometry/analysis/image.h"
#include "renderer/gl/gl_api.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace renderer {

/// GL's rows run bottom-up; images and the analysis read the top row first. `rowLength` elements a
/// row, `rows` rows, swapped in place: a second image-sized array would come on top of the truth's
/// peak at plant scale.
template <class T> void flipRows(std::vector<T>& image, size_t rowLength, int rows) {
    for (int y = 0; y < rows / 2; ++y)
        std::swap_ranges(image.begin() + std::ptrdiff_t(size_t(y) * rowLength),
                         image.begin() + std::ptrdiff_t(size_t(y + 1) * rowLength),
                         image.begin() + std::ptrdiff_t(size_t(rows - 1 - y) * rowLength));
}

/// Reads a colour texture's level 0 (RGBA8), flipped so the top row comes first.
[[nodiscard]] geometry::analysis::Image readTexture(GLuint texture, int width, int height);

} // namespace renderer
