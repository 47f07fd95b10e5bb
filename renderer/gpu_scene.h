#pragma once
// The scene's meshes in GL buffers, drawn chunk by chunk.
#include "gl/gl_api.h"
#include "geometry/scene.h"

#include <vector>

namespace renderer {

struct GpuMesh {
    GLuint vao = 0, vbo = 0, ebo = 0;
    glm::mat4 transform{1.f};
    glm::vec3 color{0.7f};
    std::vector<geometry::Chunk> chunks;
    uint64_t triangles = 0;
};

class GpuScene {
public:
    explicit GpuScene(const geometry::Scene& scene);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    [[nodiscard]] const std::vector<GpuMesh>& meshes() const noexcept { return meshes_; }
    /// Draws every chunk of mesh `m` (contiguous runs merged into one call); returns triangles drawn.
    uint64_t draw(const GpuMesh& m) const noexcept;

private:
    std::vector<GpuMesh> meshes_;
};

} // namespace renderer
