#pragma once
// Small geometric measures the level builder needs: connected parts, part thickness, the
// largest stretch of a transform. Pure functions on flat arrays. Internal to geometry/lod.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace geometry::lod::detail {

/// The connected part of each vertex, parts numbered 0.. in order of first vertex; vertices are
/// connected through the triangles (3 indices each, all < vertexCount). Unused vertices get a
/// part of their own.
[[nodiscard]] std::vector<uint32_t> connectedParts(size_t vertexCount, std::span<const uint32_t> triangles);

/// The smallest extent of the points over the three coordinate axes and their three principal
/// axes: a part's thickness (a bar's width along any direction across it, a plate's thickness).
/// 0 for fewer than two points; NaN in, NaN out.
[[nodiscard]] float smallestExtent(std::span<const glm::vec3> points) noexcept;

/// The largest factor by which the linear part of `m` stretches a length (its largest singular
/// value): an object-space distance d is at most d × this in world space.
[[nodiscard]] float largestStretch(const glm::mat4& m) noexcept;

/// Eigenvectors (columns) of a symmetric 3×3 matrix, by Jacobi rotations; eigenvalues in `values`.
[[nodiscard]] glm::dmat3 symmetricEigen(const glm::dmat3& a, glm::dvec3& values) noexcept;

} // namespace geometry::lod::detail
