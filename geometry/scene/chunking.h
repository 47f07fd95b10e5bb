#pragma once
#include "geometry/scene/scene.h"

namespace geometry::scene {

inline constexpr uint32_t kMaxChunkTriangles = 4096;

/// Reorders the mesh's triangles into spatially coherent runs of at most `maxTriangles`
/// (recursive median split along the longest axis) and fills mesh.chunks with their
/// world-space bounds, so culling against a light frustum rejects whole runs.
void chunkMesh(Mesh& mesh, uint32_t maxTriangles = kMaxChunkTriangles);

} // namespace geometry::scene
