#pragma once
// The scene's meshes in GL buffers, drawn chunk by chunk.
#include "geometry/lod/caster_lod.h"
#include "geometry/scene/scene.h"
#include "gl/gl_api.h"

#include <cstdint>
#include <vector>

namespace renderer {

/// A mesh's simplified caster levels (geometry/lod), in their own buffers.
struct GpuLod {
    GLuint vao = 0, vbo = 0, ebo = 0;
    std::vector<std::vector<geometry::lod::LodRange>> chunkLevels; // as GpuMesh::chunks
};

struct GpuMesh {
    size_t sceneIndex = 0; // in Scene::meshes
    GLuint vao = 0, vbo = 0, ebo = 0;
    glm::mat4 transform{1.f};
    glm::vec3 color{0.7f};
    std::vector<geometry::scene::Chunk> chunks;
    uint64_t triangles = 0;
    bool twoSided = true; // casts from both faces (open surfaces)
    GpuLod lod;           // vao 0: none
};

/// Triangles a caster draw submitted, and what it would have without caster LOD.
struct DrawCount {
    uint64_t drawn = 0, full = 0;
};

class GpuScene {
public:
    explicit GpuScene(const geometry::scene::Scene& scene);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    [[nodiscard]] const std::vector<GpuMesh>& meshes() const noexcept { return meshes_; }
    /// Uploads simplified caster levels built for this scene (their meshes in Scene order); a
    /// SceneLod of another scene (other chunk counts) leaves those meshes without.
    void setCasterLod(const geometry::lod::SceneLod& lod);
    [[nodiscard]] bool hasCasterLod() const noexcept { return hasLod_; }

    /// Draws the visible chunks of `m`, each at level `level(chunk index, bounds)` of its simplified
    /// levels (−1: the original; runs of originals merged into one call as draw() does).
    template <class Visible, class Level>
    DrawCount drawLevels(const GpuMesh& m, Visible&& visible, Level&& level) const noexcept {
        DrawCount count;
        const bool lod = m.lod.vao != 0 && m.lod.chunkLevels.size() == m.chunks.size();
        std::vector<const geometry::lod::LodRange*>& simplified = simplified_; // reused: no per-pass allocation
        simplified.clear();
        count.drawn = draw(m, [&, index = size_t(0)](const geometry::scene::Aabb& bounds) mutable {
            const size_t i = index++;
            if (!visible(bounds)) return false;
            count.full += m.chunks[i].triangleCount;
            if (!lod || m.lod.chunkLevels[i].empty()) return true;
            const int k = level(i, bounds);
            if (k < 0 || k >= int(m.lod.chunkLevels[i].size())) return true;
            simplified.push_back(&m.lod.chunkLevels[i][size_t(k)]);
            return false;
        });
        if (simplified.empty()) return count;
        glBindVertexArray(m.lod.vao);
        for (const auto* r : simplified) {
            drawRun(r->firstTriangle, r->triangleCount);
            count.drawn += r->triangleCount;
        }
        return count;
    }
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
    bool hasLod_ = false;
    mutable std::vector<const geometry::lod::LodRange*> simplified_; // drawLevels' scratch list
};

} // namespace renderer
