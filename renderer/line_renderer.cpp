#include "line_renderer.h"

namespace renderer {

LineRenderer::LineRenderer() {
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glBindVertexArray(0);
}

LineRenderer::~LineRenderer() {
    glDeleteBuffers(1, &vbo_);
    glDeleteVertexArrays(1, &vao_);
}

glm::vec4 LineRenderer::colour(geometry::shadow::OverlayKind kind) noexcept {
    switch (kind) {
    case geometry::shadow::OverlayKind::SceneBounds: return {0.65f, 0.65f, 0.65f, 1.f};
    case geometry::shadow::OverlayKind::ViewFrustum: return {1.f, 0.85f, 0.1f, 1.f};
    case geometry::shadow::OverlayKind::SplitFrustum: return {1.f, 0.45f, 0.1f, 1.f};
    case geometry::shadow::OverlayKind::FocusBody: return {0.2f, 0.95f, 0.3f, 1.f};
    case geometry::shadow::OverlayKind::WarpFrustum: return {0.2f, 0.8f, 1.f, 1.f};
    case geometry::shadow::OverlayKind::SampleBounds: return {1.f, 0.3f, 0.9f, 1.f};
    case geometry::shadow::OverlayKind::LightVolume: return {1.f, 1.f, 0.55f, 1.f};
    case geometry::shadow::OverlayKind::Count: break;
    }
    return {1.f, 0.f, 1.f, 1.f};
}

void LineRenderer::draw(const std::vector<geometry::shadow::OverlaySegment>& segments, const glm::mat4& worldToClip) {
    if (segments.empty()) return;
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_DEPTH_CLAMP);
    program_.use();
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    for (const bool ndc : {false, true}) {
        vertices_.clear();
        for (const auto& s : segments) {
            if (s.inMapNdc != ndc) continue;
            const glm::vec4 c = colour(s.kind);
            for (const glm::vec3& p : {s.a, s.b})
                vertices_.insert(vertices_.end(), {p.x, p.y, p.z, c.r, c.g, c.b, c.a});
        }
        if (vertices_.empty()) continue;
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices_.size() * sizeof(float)), vertices_.data(), GL_STREAM_DRAW);
        program_.set("uMatrix", ndc ? glm::mat4(1.f) : worldToClip);
        glDrawArrays(GL_LINES, 0, GLsizei(vertices_.size() / 7));
    }
    glDisable(GL_DEPTH_CLAMP);
    glBindVertexArray(0);
}

} // namespace renderer
