#pragma once
// The scene's meshes in GL buffers, drawn chunk by chunk.
#include "geometry/lod/caster_lod.h"
#include "geometry/scene/compact_vertices.h"
#include "geometry/scene/scene.h"
#include "geometry/shadow/culling.h"
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
    /// An instanced mesh (Mesh::instances): each placement's world box, in placement order; its
    /// matrices sit in instanceVbo (vertex attribute aModel, one per instance). Empty otherwise.
    std::vector<geometry::scene::Aabb> placementBounds;
    GLuint instanceVbo = 0;
    glm::vec3 color{0.7f};
    std::vector<geometry::scene::Chunk> chunks;
    std::vector<geometry::scene::TriangleRun> parts; // as Mesh::parts
    /// Compact vertices (geometry::scene::compactVertices): 16-bit chunk-local positions on a grid of
    /// `step` in vao, the wide chunks' float positions in wideVao (same index buffer), 16-bit indices
    /// drawn from each chunk's first vertex. Empty: float positions and 32-bit indices in vao
    /// (instanced and unchunked meshes).
    std::vector<geometry::scene::CompactChunk> compact;
    float step = 0.f;
    GLuint wideVao = 0, wideVbo = 0;
    uint64_t triangles = 0;
    bool twoSided = true; // casts from both faces (open surfaces)
    GpuLod lod;           // vao 0: none (instanced meshes draw their original triangles)
    [[nodiscard]] bool instanced() const noexcept { return !placementBounds.empty(); }
};

/// Triangles a caster draw submitted, and what it would have without caster LOD.
struct DrawCount {
    uint64_t drawn = 0, full = 0;
};

class GpuScene {
public:
    /// The vertex attribute of the model matrix (a mat4: this location and the next three), as
    /// eye.vert and depth.vert declare it.
    static constexpr GLuint kModelAttribute = 2;
    /// The vertex attribute aDecode (origin, step): a vertex's position is origin + step · aPosition;
    /// (0, 0, 0, 1) for float positions.
    static constexpr GLuint kDecodeAttribute = 6;

    explicit GpuScene(const geometry::scene::Scene& scene);
    ~GpuScene();
    GpuScene(const GpuScene&) = delete;
    GpuScene& operator=(const GpuScene&) = delete;

    [[nodiscard]] const std::vector<GpuMesh>& meshes() const noexcept { return meshes_; }
    /// Uploads simplified caster levels built for this scene (their meshes in Scene order); a
    /// SceneLod of another scene (other chunk counts) leaves those meshes without.
    void setCasterLod(const geometry::lod::SceneLod& lod);
    [[nodiscard]] bool hasCasterLod() const noexcept { return hasLod_; }

    /// Draws the chunks of `m` that `overlap(bounds)` (a geometry::shadow::ClipOverlap) does not put
    /// Outside, each at level `level(chunk index, bounds)` of its simplified levels (−1: the
    /// original) when that level has fewer triangles than the chunk's original parts in view.
    template <class Overlap, class Level>
    DrawCount drawLevels(const GpuMesh& m, Overlap&& overlap, Level&& level) const noexcept {
        if (m.instanced()) {
            const uint64_t n = drawInstances(m, overlap);
            return {n, n};
        }
        DrawCount count;
        const bool lod = m.lod.vao != 0 && m.lod.chunkLevels.size() == m.chunks.size();
        std::vector<const geometry::lod::LodRange*>& simplified = simplified_; // reused: no per-pass allocation
        simplified.clear();
        bind(m);
        RunMerger runs(m);
        for (size_t i = 0; i < m.chunks.size(); ++i) {
            const geometry::scene::Chunk& c = m.chunks[i];
            const geometry::shadow::ClipOverlap o = overlap(c.bounds);
            if (o == geometry::shadow::ClipOverlap::Outside) continue;
            const uint32_t original = visibleRuns(m, c, o, overlap);
            count.full += original;
            if (lod && !m.lod.chunkLevels[i].empty()) {
                const int k = level(i, c.bounds);
                if (k >= 0 && k < int(m.lod.chunkLevels[i].size()) &&
                    m.lod.chunkLevels[i][size_t(k)].triangleCount < original) {
                    simplified.push_back(&m.lod.chunkLevels[i][size_t(k)]);
                    continue;
                }
            }
            runs.chunk(i);
            for (const geometry::scene::TriangleRun& r : visible_) runs.add(r.firstTriangle, r.triangleCount);
        }
        count.drawn = runs.finish();
        if (simplified.empty()) return count;
        glBindVertexArray(m.lod.vao);
        glVertexAttrib4f(kDecodeAttribute, 0.f, 0.f, 0.f, 1.f); // the levels' positions are floats
        for (const auto* r : simplified) {
            drawRun(r->firstTriangle, r->triangleCount);
            count.drawn += r->triangleCount;
        }
        return count;
    }
    /// Draws the original triangles of `m` that `overlap(bounds)` does not put Outside: whole
    /// chunks, and the parts in view of chunks only Partly inside; contiguous runs merge into one
    /// call. An instanced mesh is culled placement by placement instead. Returns the triangles
    /// submitted.
    template <class Overlap> uint64_t draw(const GpuMesh& m, Overlap&& overlap) const noexcept {
        if (m.instanced()) return drawInstances(m, overlap);
        bind(m);
        RunMerger runs(m);
        for (size_t i = 0; i < m.chunks.size(); ++i) {
            const geometry::scene::Chunk& c = m.chunks[i];
            const geometry::shadow::ClipOverlap o = overlap(c.bounds);
            if (o == geometry::shadow::ClipOverlap::Outside) continue;
            visibleRuns(m, c, o, overlap);
            runs.chunk(i);
            for (const geometry::scene::TriangleRun& r : visible_) runs.add(r.firstTriangle, r.triangleCount);
        }
        return runs.finish();
    }

private:
    /// Binds the mesh's vertex array; a mesh that is not instanced gets its one model matrix as
    /// aModel's current value (context state, not the VAO's: set per mesh), and float positions
    /// until a compact mesh's chunk says otherwise (RunMerger::chunk).
    static void bind(const GpuMesh& m) noexcept {
        glBindVertexArray(m.vao);
        for (GLuint c = 0; c < 4; ++c) glVertexAttrib4fv(kModelAttribute + c, &m.transform[int(c)][0]);
        glVertexAttrib4f(kDecodeAttribute, 0.f, 0.f, 0.f, 1.f);
    }
    /// Every triangle of `m` once per placement that `overlap(box)` does not put Outside:
    /// consecutive placements in view share one instanced call.
    template <class Overlap> uint64_t drawInstances(const GpuMesh& m, Overlap& overlap) const noexcept {
        glBindVertexArray(m.vao);
        glVertexAttrib4f(kDecodeAttribute, 0.f, 0.f, 0.f, 1.f);
        const auto count = GLsizei(m.triangles * 3);
        uint64_t placed = 0;
        size_t first = 0, run = 0;
        const auto flush = [&] {
            if (run > 0)
                glDrawElementsInstancedBaseInstance(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr, GLsizei(run),
                                                    GLuint(first));
            placed += run;
            run = 0;
        };
        for (size_t i = 0; i < m.placementBounds.size(); ++i) {
            if (overlap(m.placementBounds[i]) == geometry::shadow::ClipOverlap::Outside) {
                flush();
                continue;
            }
            if (run == 0) first = i;
            ++run;
        }
        flush();
        return placed * m.triangles;
    }
    static void drawRun(uint32_t firstTriangle, uint32_t triangles) noexcept {
        if (triangles == 0) return;
        glDrawElements(GL_TRIANGLES, GLsizei(triangles * 3), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(uintptr_t(firstTriangle) * 3 * sizeof(uint32_t)));
    }
    /// Collects runs of consecutive triangles and draws each maximal run with one call; a compact
    /// mesh's runs do not cross chunks (each chunk has its own origin and first vertex).
    class RunMerger {
    public:
        explicit RunMerger(const GpuMesh& m) noexcept : mesh_(m) {}
        /// The runs that follow are chunk i's: its vertex array, and its grid where it is narrow.
        void chunk(size_t i) noexcept {
            if (mesh_.compact.empty() || i == chunk_) return;
            flush();
            chunk_ = i;
            const geometry::scene::CompactChunk& c = mesh_.compact[i];
            if (c.wide != wide_) glBindVertexArray(c.wide ? mesh_.wideVao : mesh_.vao);
            wide_ = c.wide;
            if (c.wide) glVertexAttrib4f(kDecodeAttribute, 0.f, 0.f, 0.f, 1.f);
            else glVertexAttrib4f(kDecodeAttribute, c.origin.x, c.origin.y, c.origin.z, mesh_.step);
        }
        void add(uint32_t first, uint32_t count) noexcept {
            if (count_ > 0 && first == first_ + count_) {
                count_ += count;
                return;
            }
            flush();
            first_ = first;
            count_ = count;
        }
        /// Draws what is pending; returns the triangles drawn in all.
        uint64_t finish() noexcept {
            flush();
            return drawn_;
        }

    private:
        void flush() noexcept {
            if (mesh_.compact.empty()) drawRun(first_, count_);
            else if (count_ > 0)
                glDrawElementsBaseVertex(GL_TRIANGLES, GLsizei(count_ * 3), GL_UNSIGNED_SHORT,
                                         reinterpret_cast<const void*>(uintptr_t(first_) * 3 * sizeof(uint16_t)),
                                         GLint(mesh_.compact[chunk_].firstVertex));
            drawn_ += count_;
            count_ = 0;
        }
        const GpuMesh& mesh_;
        size_t chunk_ = SIZE_MAX;
        bool wide_ = false; // bind() bound vao
        uint32_t first_ = 0, count_ = 0;
        uint64_t drawn_ = 0;
    };
    /// Fills visible_ with what of chunk `c` (overlap `o`, not Outside) to draw: the chunk, or,
    /// when it is only Partly inside and has parts, its parts that are not Outside. Returns their
    /// triangles.
    template <class Overlap>
    uint32_t visibleRuns(const GpuMesh& m, const geometry::scene::Chunk& c, geometry::shadow::ClipOverlap o,
                         Overlap& overlap) const noexcept {
        visible_.clear();
        if (o == geometry::shadow::ClipOverlap::Inside || c.partCount == 0 ||
            size_t(c.firstPart) + c.partCount > m.parts.size()) {
            visible_.push_back(c);
            return c.triangleCount;
        }
        uint32_t triangles = 0;
        for (uint32_t k = c.firstPart; k < c.firstPart + c.partCount; ++k)
            if (overlap(m.parts[k].bounds) != geometry::shadow::ClipOverlap::Outside) {
                visible_.push_back(m.parts[k]);
                triangles += m.parts[k].triangleCount;
            }
        return triangles;
    }
    std::vector<GpuMesh> meshes_;
    bool hasLod_ = false;
    mutable std::vector<const geometry::lod::LodRange*> simplified_; // drawLevels' scratch list
    mutable std::vector<geometry::scene::TriangleRun> visible_;      // visibleRuns' scratch list
};

} // namespace renderer
