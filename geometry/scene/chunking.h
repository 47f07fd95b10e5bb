#pragma once
#include "geometry/scene/scene.h"

namespace geometry::scene {

inline constexpr uint32_t kMaxChunkTriangles = 4096;
/// Parts of a chunk: small enough that a chunk straddling a split's map edge draws little of
/// what lies outside (platform `deck`, pssm3 fitted to the samples: 389k → 298k shadow triangles).
inline constexpr uint32_t kMaxPartTriangles = 256;

/// Reorders the mesh's triangles into spatially coherent runs of at most `maxTriangles`
/// (recursive median split along the longest axis) and fills mesh.chunks with their
/// world-space bounds, so culling against a light frustum rejects whole runs. The same split
/// goes on inside each chunk down to runs of at most `maxPartTriangles`: mesh.parts. Moves the
/// positions onto the mesh's grid (snapToGrid: at most 4 float spacings at the largest coordinate).
/// Leaves the positions spare capacity for one vertex (reserveSpareVertex).
void chunkMesh(Mesh& mesh, uint32_t maxTriangles = kMaxChunkTriangles, uint32_t maxPartTriangles = kMaxPartTriangles);

/// Recomputes every chunk's and part's world bounds from its own triangles under mesh.transform
/// (after the transform changed); exact, and keeps the triangle order.
void reboundRuns(Mesh& mesh);

/// Gives the positions spare capacity for one more vertex where they have none: Embree's 16-byte
/// loads read 4 bytes past the last vertex of an array the truth shares (GroundTruth::borrowing). A
/// copied vector has no spare capacity, so a copied scene needs this again.
void reserveSpareVertex(Mesh& mesh);

} // namespace geometry::scene
