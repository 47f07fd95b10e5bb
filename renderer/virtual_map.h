#pragma once
// technique = virtual (issue 34; docs/design.md §3.11): the virtual shadow map's GPU side. Marks the
// pages the eye's depth pre-pass asks for (page_mark.comp), lets geometry's PagePool choose what to
// keep and draw, holds the physical pages (one depth atlas) and the page table the eye pass reads
// (virtual.glsl). The renderer draws the pages it is told; no decision is made here.
#include "geometry/shadow/virtual_plan.h"
#include "program.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace renderer {

/// What metrics.json and the dashboard report of a frame's virtual map.
struct VirtualPageStats {
    bool active = false;
    uint64_t requested = 0; // pages the visible pixels asked for
    uint64_t allocated = 0; // pages in the table (after coarsening, when the pool is short)
    uint64_t drawn = 0;     // pages drawn this frame (new, or their content changed)
    uint64_t cached = 0;    // pages kept from an earlier frame without drawing
    uint64_t drawnTotal =
        0; // pages drawn since the pool was made or last invalidated (the first frame's, then each change)
    uint32_t poolPages = 0, occupied = 0;
    uint64_t memoryBytes = 0;   // the pool's depth texels and the page table
    int finestLevel = 0;        // the finest level left after coarsening
    uint64_t uncovered = 0;     // visible pixels outside every level
    uint64_t pageTriangles = 0; // triangles submitted over the pages drawn
    std::string warning;        // why levels were given up, or empty
};

class VirtualShadowMap {
public:
    VirtualShadowMap();
    ~VirtualShadowMap();
    VirtualShadowMap(const VirtualShadowMap&) = delete;
    VirtualShadowMap& operator=(const VirtualShadowMap&) = delete;

    /// The pool and atlas for `config` (made anew, empty, when the shape changes). `poolPages` may be
    /// fewer than config.poolPages (the renderer's memory budget or texture size).
    void ensure(const geometry::shadow::VirtualMapConfig& config, uint32_t poolPages, int maxTextureSize);
    /// Marks the pages the pre-pass depth (`depthTexture`, width × height, of camera `viewProj`) asks
    /// for, updates the pool and uploads the page table. Returns the pool's frame.
    const geometry::shadow::PagePool::Frame& update(const geometry::shadow::VirtualPlan& plan, GLuint depthTexture,
                                                    int width, int height, const glm::mat4& eyeViewProj);
    /// Forgets every page (the scene changed: nothing drawn before is valid).
    void invalidate();
    /// Binds physical page `physical`'s square of the atlas as the target (viewport and scissor).
    void bindPage(uint32_t physical) const noexcept;
    /// The uniforms page_mark.comp, virtual.glsl and virtual_view.frag share.
    void setUniforms(Program& program, const geometry::shadow::VirtualPlan& plan) const;

    [[nodiscard]] GLuint atlas() const noexcept { return atlas_; }
    [[nodiscard]] GLuint pageTable() const noexcept { return table_; }
    [[nodiscard]] uint32_t poolPages() const noexcept { return pool_ ? pool_->capacity() : 0; }
    [[nodiscard]] const geometry::shadow::PagePool::Frame& frame() const noexcept { return frame_; }
    [[nodiscard]] uint64_t uncovered() const noexcept { return uncovered_; }
    [[nodiscard]] uint64_t drawnTotal() const noexcept { return drawnTotal_; }
    [[nodiscard]] uint32_t occupied() const noexcept { return pool_ ? pool_->occupied() : 0; }
    /// The atlas's depths (columns·pageSize wide, bottom row first), for tests.
    [[nodiscard]] std::vector<float> readAtlas() const;
    [[nodiscard]] glm::ivec2 atlasSize() const noexcept { return {columns_ * pageSize_, rows_ * pageSize_}; }

private:
    void release() noexcept;
    Program mark_{Program::Compute{}, "page_mark.comp"};
    GLuint marks_ = 0;           // page_mark.comp's SSBO: uncovered count, then one bit per page
    GLuint atlas_ = 0, fbo_ = 0; // the physical pages, pageSize² each, row by row
    GLuint table_ = 0;           // R32UI array: (page x, page y, level) → physical + 1; 0: none
    int columns_ = 0, rows_ = 0, pageSize_ = 0, pagesPerSide_ = 0, levels_ = 0;
    geometry::shadow::VirtualMapConfig config_;
    std::unique_ptr<geometry::shadow::PagePool> pool_;
    geometry::shadow::PagePool::Frame frame_;
    uint64_t uncovered_ = 0;
    uint64_t drawnTotal_ = 0;
    std::vector<uint32_t> words_, tableWords_;
};

} // namespace renderer
