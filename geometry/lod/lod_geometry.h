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

/// How thin a part is, from its points: the smallest extent over the three coordinate axes and
/// the three principal axes (a bar's width across it, a plate's thickness). A flat part, an open
/// sheet, can only vanish by narrowing, so its thickness is its width in its plane: the extent
/// along the middle principal axis. 0 for fewer than two points; NaN in, NaN out.
[[nodiscard]] float partThickness(std::span<const glm::vec3> points) noexcept;

/// The largest factor by which the linear part of `m` stretches a length (its largest singular
/// value): an object-space distance d is at most d × this in world space.
[[nodiscard]] float largestStretch(const glm::mat4& m) noexcept;

/// Eigenvectors (columns) of a symmetric 3×3 matrix, by Jacobi rotations; eigenvalues in `values`.
[[nodiscard]] glm::dmat3 symmetricEigen(const glm::dmat3& a, glm::dvec3& values) noexcept;

} // namespace geometry::lod::detail
