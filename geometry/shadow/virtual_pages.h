#pragma once
// Virtual shadow maps (issue 34; docs/design.md §3.11): a directional light's map as clipmap levels of
// virtualSize² texels each, cut into pages of pageSize² texels, of which only the pages that visible
// samples ask for get one of the pool's physical pages. This is the plan's half: the levels' frames,
// the level a sample's footprint asks for, the pages requested, and the pool (allocation, caching
// across frames, coarser levels when it is full). Pure values; the renderer marks and draws.
#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace geometry::shadow {

struct VirtualMapConfig {
    uint32_t virtualSize = 16384; // texels along each side of a level
    uint32_t pageSize = 128;      // texels along each side of a page
    int levels = 8;               // clipmap levels, each twice as wide as the one before
    uint32_t poolPages = 1024;    // physical pages (1024 pages of 128² = one 4096² texture)
    double side0 = 16.0;          // world-space side of level 0, the finest
    [[nodiscard]] uint32_t pagesPerSide() const noexcept { return virtualSize / pageSize; }
    /// Why the configuration cannot be used (sizes not powers of two, a page larger than a level,
    /// no level or no page, a side that is not a positive finite number), or nothing.
    [[nodiscard]] std::optional<std::string> invalid() const;
};

/// The light's plane: two unit vectors across l (a basis that depends on l alone) and l.
struct LightFrame {
    glm::dvec3 right{1, 0, 0}, up{0, 0, 1}, l{0, -1, 0};
    [[nodiscard]] glm::dvec2 project(const glm::dvec3& p) const noexcept {
        return {glm::dot(p, right), glm::dot(p, up)};
    }
};
[[nodiscard]] LightFrame lightFrame(const glm::vec3& l) noexcept;

/// Level k covers a square of side side0·2^k in the light's plane around the eye, its corner on a
/// whole page of that level: the texels of a page stay where they are while the eye moves, which is
/// what lets a page be kept from one frame to the next.
struct ClipLevel {
    int64_t firstPageX = 0, firstPageY = 0; // the square's first page, in pages of this level from the plane's origin
    double pageWorld = 0;                   // a page's side, world units
    double texelWorld = 0;                  // a texel's side, world units
};
[[nodiscard]] std::vector<ClipLevel> clipLevels(const LightFrame& frame, const glm::dvec3& eye,
                                                const VirtualMapConfig& config);

/// A page of one level, named by its place in the light's plane (not by the square it is in), so
/// that it keeps its name while the squares follow the eye.
struct PageKey {
    int32_t level = 0;
    int64_t x = 0, y = 0;
    [[nodiscard]] auto operator<=>(const PageKey&) const = default;
};

/// The page holding light-plane point s at level k, or nothing when s lies outside level k's square.
[[nodiscard]] std::optional<PageKey> pageAt(const glm::dvec2& s, int k, const std::vector<ClipLevel>& levels,
                                            const VirtualMapConfig& config) noexcept;

/// The finest level whose texels are no larger than `footprint` (a pixel's size where it lands, in
/// world units across the light), so that a texel covers between half a pixel and one: m in (0.5, 1].
/// Footprints finer than level 0's texels get level 0; coarser than the last level's, the last.
[[nodiscard]] int levelFor(double footprint, const std::vector<ClipLevel>& levels) noexcept;

/// A visible sample: where it is and its pixel's footprint across the light.
struct VirtualSample {
    glm::dvec3 position{0.0};
    double footprint = 0;
};

struct PageRequests {
    std::vector<PageKey> pages; // sorted, distinct
    uint64_t uncovered = 0;     // samples outside every level's square (or not finite)
};
/// The pages the samples ask for: each at the level its footprint asks, or the first coarser level
/// whose square holds it.
[[nodiscard]] PageRequests requestPages(std::span<const VirtualSample> samples, const LightFrame& frame,
                                        const std::vector<ClipLevel>& levels, const VirtualMapConfig& config);

/// The key of the page at level `coarser` that holds page `k` (levels nest: a page's side doubles).
[[nodiscard]] PageKey ancestor(const PageKey& k, int coarser) noexcept;

/// The physical pages and what they hold. update() is one frame: it keeps the pages that still
/// hold what is asked (cached), gives the others free or least recently used pages, and says which
/// must be drawn. When more pages are asked than the pool has, the finest levels are given up for
/// their coarser ancestors until the request fits (a warning says so): a sample then reads a
/// coarser page, never a page holding something else.
class PagePool {
public:
    explicit PagePool(uint32_t capacity);

    struct Entry {
        PageKey key;
        uint32_t physical = 0;
    };
    struct Frame {
        std::vector<Entry> table;    // what the eye pass looks pages up in, sorted by key
        std::vector<uint32_t> drawn; // physical pages to draw this frame (new, or their content changed)
        uint64_t requested = 0;      // pages asked for, before any coarsening
        uint64_t cached = 0;         // pages kept from an earlier frame without drawing
        int finestLevel = 0;         // the finest level left after coarsening
        std::string warning;         // why levels were given up, or empty
        /// The physical page and level that serve page `k`: its own, else its nearest allocated
        /// ancestor; nothing when neither is allocated.
        [[nodiscard]] std::optional<Entry> resolve(const PageKey& k, int levels) const;
    };
    /// `content` names what the pages show (the light's direction and the casters): a page drawn
    /// for another content is drawn again.
    Frame update(std::vector<PageKey> requests, uint64_t content, int levels);

    [[nodiscard]] uint32_t capacity() const noexcept { return uint32_t(slots_.size()); }
    [[nodiscard]] uint32_t occupied() const noexcept;

private:
    struct Slot {
        PageKey key;
        bool used = false;
        uint64_t content = 0;
        uint64_t lastUsed = 0; // the frame that last asked for it
    };
    std::vector<Slot> slots_;
    uint64_t frame_ = 0;
};

} // namespace geometry::shadow
