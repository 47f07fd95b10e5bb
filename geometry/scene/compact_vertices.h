#pragma once
// A chunked mesh's vertices as the GL buffers hold them (docs/design.md §2.2 "Compact vertices"):
// every position on one grid for the whole mesh, a few float spacings fine; a chunk's vertices as
// 16-bit counts of that grid from the chunk's origin where the chunk is narrow enough, else as floats;
// normals in 32 bits; 16-bit indices per chunk. 12 bytes a vertex and 6 a triangle instead of 24 and
// 12. The scene keeps its float arrays, which the truth shares with Embree.
#include "geometry/scene/scene.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace geometry::scene {

/// Bits of each chunk-local position coordinate.
inline constexpr int kPositionBits = 16;
/// The grid's step in float spacings (ulp) at the mesh's largest coordinate: positions move by at
/// most half of it, 4 ulp, which float arithmetic on world coordinates costs anyway.
inline constexpr int kGridUlps = 8;

/// Chunk i's vertices: where they start (in CompactVertices::positions, or floatPositions where
/// `wide`), and the grid point the 16-bit counts start from (a multiple of the step).
struct CompactChunk {
    uint32_t firstVertex = 0;
    glm::vec3 origin{0.f};
    bool wide = false; // wider than 2^kPositionBits − 2 steps: float positions (on the grid all the same)
};

struct CompactVertices {
    /// The grid's spacing, a power of two: every vertex p is moved to the grid point nearest to it, so
    /// each coordinate by at most step / 2 (maxError()). Shared vertices land on the same point in every
    /// chunk (no cracks), and origin + step · q is exact in float (in a shader too).
    float step = 0.f;
    std::vector<std::array<uint16_t, 4>> positions; // narrow chunks' vertices: x, y, z, 0 (8-byte aligned)
    std::vector<uint32_t> normals;                  // theirs, packNormal()
    std::vector<glm::vec3> floatPositions;          // wide chunks' vertices, on the grid
    std::vector<uint32_t> floatNormals;             // theirs
    std::vector<uint16_t> indices;                  // as Mesh::indices, counted from the chunk's firstVertex
    std::vector<CompactChunk> chunks;               // as Mesh::chunks

    /// The largest distance along an axis between a vertex and its original.
    [[nodiscard]] float maxError() const noexcept { return 0.5f * step; }
    /// Vertex `local` of chunk `chunk`, decoded (object space).
    [[nodiscard]] glm::vec3 position(size_t chunk, size_t local) const noexcept;
};

/// The compact form of `mesh`, exact: none where it has no chunks, they do not tile its triangles, a
/// chunk names more vertices than 16-bit indices reach, or a position is not finite or not on the grid
/// (snapToGrid: chunkMesh's last step; positions moved since are drawn as floats). Deterministic.
[[nodiscard]] std::optional<CompactVertices> compactVertices(const Mesh& mesh);

/// The mesh's grid: kGridUlps float spacings (ulp) at its largest finite coordinate, a power of two.
[[nodiscard]] float gridStep(const Mesh& mesh) noexcept;
/// Moves every finite position to the nearest point of gridStep(mesh)'s grid (by at most half a step
/// along each axis; less than a step, towards zero, within half a step of float's largest value). chunkMesh does, so
/// that what GL draws from compactVertices and what the truth traces from the mesh's own arrays are the same points.
void snapToGrid(Mesh& mesh);
/// compactVertices(mesh)'s step without building it (none where compactVertices gives none).
[[nodiscard]] std::optional<float> compactStep(const Mesh& mesh);

/// A unit normal in GL_INT_2_10_10_10_REV (x in bits 0–9, y 10–19, z 20–29, signed, normalized: 511 is
/// 1); non-finite components become 0.
[[nodiscard]] uint32_t packNormal(const glm::vec3& n) noexcept;
/// What GL reads from packNormal's word: each component max(c / 511, −1).
[[nodiscard]] glm::vec3 unpackNormal(uint32_t packed) noexcept;

} // namespace geometry::scene
