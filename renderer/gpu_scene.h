#pragma once
// The scene's meshes in GL buffers, drawn chunk by chunk.
#include "geometry/scene/scene.h"
#include "gl/gl_api.h"

#include <cstdint>
#include <vector>

namespace renderer {

struct GpuMesh {
    GLuint vao = 0, vbo = 0, ebo = 0;
    glm::mat4 transform{1.f};
    glm::vec3 color{0.7f};
    std::vector<geometry::scene::Chunk> chunks;
    uint64_t triangles = 0;
    bool twoSided = true; // casts from both faces (open surfaces)
};

class GpuScene {
public:
    explicit GpuScene(const geometry::scene::Scene& scene);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    [[nodiscard]] const std::vector<GpuMesh>& meshes() const noexcept { return meshes_; }
    /// Draws the chunks of `m` whose bounds pass `visible(bounds)`, merging contiguous runs into
    /// one call; returns the triangles submitted.
    template <class Visible> uint64_t draw(const GpuMesh& m, Visible&& visible) const noexcept {
        glBindVertexArray(m.vao);
        uint64_t drawn = 0;
        uint32_t runStart = 0, runCount = 0;
        for (const auto& c : m.chunks) {
            if (!visible(c.bounds)) continue;
            if (runCount > 0 && c.firstTriangle == runStart + runCount) {
                runCount += c.triangleCount;
                continue;
            }
            drawRun(runStart, runCount);
            drawn += runCount;
            runStart = c.firstTriangle;
            runCount = c.triangleCount;
        }
        drawRun(runStart, runCount);
        return drawn + runCount;
    }

private:
    static void drawRun(uint32_t firstTriangle, uint32_t triangles) noexcept {
        if (triangles == 0) return;
        glDrawElements(GL_TRIANGLES, GLsizei(triangles * 3), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(uintptr_t(firstTriangle) * 3 * sizeof(uint32_t)));
    }
    std::vector<GpuMesh> meshes_;
};

} // namespace renderer
