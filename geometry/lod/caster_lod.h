#pragma once
// Simplified levels of each chunk for the shadow passes: a pass draws the coarsest level whose
// geometric error is below a few texels of its map at the chunk. Curved CAD surfaces (pipes,
// elbows, flanges) decimate well; thin parts are kept exact, so they never vanish or shrink.
#include "geometry/scene/scene.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace geometry::lod {

/// One level of one chunk: a run of triangles in MeshLod::indices.
struct LodRange {
    uint32_t firstTriangle = 0;
    uint32_t triangleCount = 0;
    /// Bound on the deviation from the original chunk, world units: every vertex and every edge
    /// midpoint of the original lies within `error` of this level's surface, and every vertex of
    /// this level is a vertex of the original (caster_lod.cpp, "What the error bounds").
    float error = 0.f;
};

struct MeshLod {
    std::vector<glm::vec3> positions; // object space, for all levels of all chunks
    std::vector<glm::vec3> normals;   // object space, smooth, one per position
    std::vector<uint32_t> indices;    // triangles of every level, into positions
    /// [chunk, as Mesh::chunks][k]: levels finer → coarser (error ascending, triangles
    /// descending), the original excluded; empty when nothing was worth simplifying.
    std::vector<std::vector<LodRange>> chunkLevels;
};

struct SceneLod {
    std::vector<MeshLod> meshes;  // as Scene::meshes
    uint64_t sourceTriangles = 0; // in every chunk of every mesh
    uint64_t lodTriangles = 0;    // in every level of every chunk
};

struct LodOptions {
    /// One level each, × the chunk's world AABB diagonal; non-positive or non-finite ones are
    /// ignored, the rest sorted.
    std::vector<float> relativeErrors{1.f / 512, 1.f / 128, 1.f / 32};
    /// A connected part thinner than thinFactor × a level's error is kept exact in that level.
    float thinFactor = 4.f;
    /// A level that removes less than this fraction of the previous level's triangles (or the
    /// original's) is dropped: not worth a draw.
    float minReduction = 0.1f;
    /// Worker threads; 0: one per hardware thread.
    unsigned threads = 0;
};

/// Builds the levels of every chunk of every mesh. progress(done fraction 0..1) is called now
/// and then from the calling thread; returning false cancels, and then the result is empty.
/// Degenerate input (empty meshes, degenerate triangles, NaN positions, bad indices) throws
/// nothing: those chunks just get no levels.
[[nodiscard]] SceneLod buildCasterLod(const scene::Scene& scene, const LodOptions& options = {},
                                      const std::function<bool(float)>& progress = {});

/// The coarsest level of `levels` whose error ≤ allowed, or -1 for the original. NaN allowed: -1.
[[nodiscard]] int coarsestLevelWithin(const std::vector<LodRange>& levels, float allowed) noexcept;

} // namespace geometry::lod
