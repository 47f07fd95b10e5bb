#pragma once
// Draws overlay segments (geometry::OverlaySegment) into the bound framebuffer, a colour per kind.
#include "geometry/shadow/overlays.h"
#include "program.h"

#include <vector>

namespace renderer {

class LineRenderer {
public:
    LineRenderer();
    ~LineRenderer();
    LineRenderer(const LineRenderer&) = delete;
    LineRenderer& operator=(const LineRenderer&) = delete;

    /// World segments go through `worldToClip`; map-NDC segments through the identity.
    void draw(const std::vector<geometry::shadow::OverlaySegment>& segments, const glm::mat4& worldToClip);
    [[nodiscard]] static glm::vec4 colour(geometry::shadow::OverlayKind kind) noexcept;

private:
    Program program_{"lines.vert", "lines.frag"};
    GLuint vao_ = 0, vbo_ = 0;
    std::vector<float> vertices_; // reused between frames
};

} // namespace renderer
