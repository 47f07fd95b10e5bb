#pragma once
// The levels of one chunk: its welded triangles in, decimated levels out. Internal to geometry/lod.
#include "geometry/lod/caster_lod.h"

#include <atomic>
#include <span>

namespace geometry::lod::detail {

/// A chunk's triangles over welded vertices (one per distinct position); triangles that repeat
/// a vertex are left out.
struct ChunkTriangles {
    std::vector<glm::vec3> positions; // object space, finite
    std::vector<uint8_t> locked;      // per position: also used by another chunk of the mesh
    std::vector<uint32_t> triangles;  // 3 per triangle, into positions
};

struct LevelSettings {
    glm::mat4 transform{1.f};     // object → world
    float stretch = 1.f;          // largestStretch(transform)
    std::vector<float> errors;    // one per level, world units, ascending
    float thinFactor = 4.f;       // LodOptions::thinFactor
    float minReduction = 0.1f;    // LodOptions::minReduction
    uint32_t sourceTriangles = 0; // the chunk's, degenerate ones included: what the first level must beat
};

struct ChunkLevels {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices; // into positions
    std::vector<LodRange> levels;  // firstTriangle into indices
};

/// Decimates the chunk level by level; empty when cancelled or when no level is worth keeping.
[[nodiscard]] ChunkLevels buildChunkLevels(const ChunkTriangles& chunk, const LevelSettings& settings,
                                           const std::atomic<bool>& cancel);

/// Angle-weighted vertex normals, unit; (0, 0, 1) where no triangle with area meets a vertex.
[[nodiscard]] std::vector<glm::vec3> smoothNormals(std::span<const glm::vec3> positions,
                                                   std::span<const uint32_t> triangles);

} // namespace geometry::lod::detail
