#pragma once
// Read-back of colour textures into CPU images.
#include "geometry/analysis/image.h"
#include "renderer/gl/gl_api.h"

namespace renderer {

/// Reads a colour texture's level 0 (RGBA8), flipped so the top row comes first.
[[nodiscard]] geometry::analysis::Image readTexture(GLuint texture, int width, int height);

} // namespace renderer
