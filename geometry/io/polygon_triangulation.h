#pragma once
// Triangulation of one polygon face (OBJ, OFF, PLY): ear clipping on the face's best-fit plane,
// so that concave faces and "ring" faces (an outline around a hole, joined to it by a
// zero-width bridge) keep their true area, where a fan would fill the hole and flip triangles.
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace geometry::io {

struct CleanupReport; // model_loader.h

/// What triangulation met, summed over faces (faces with more than three corners only).
struct PolygonStats {
    size_t polygons = 0;  // faces with more than three corners triangulated
    size_t nonPlanar = 0; // farther than 1e-3 × their diameter from their best-fit plane
    size_t fallbacks = 0; // ear clipping got stuck (self-intersecting or flat face): rest fanned
};

/// Triangles of the polygon whose corners are `indices` into `points`, in its winding (each
/// triangle faces the way the polygon's Newell normal does). A triangle is returned as is.
/// Repeated corners (a ring's bridge) and collinear corners are allowed.
[[nodiscard]] std::vector<std::array<uint32_t, 3>>
triangulatePolygon(std::span<const glm::vec3> points, std::span<const uint32_t> indices, PolygonStats& stats);

/// Appends the triangles of one polygon face to `indices`: a triangle as it is, a larger face
/// ear-clipped (the readers of OBJ, OFF and PLY share this).
void appendPolygon(std::span<const glm::vec3> positions, std::span<const uint32_t> corners,
                   std::vector<uint32_t>& indices, PolygonStats& stats);

/// Adds a reader's polygon counters to its report.
void addPolygonCounts(const PolygonStats& stats, CleanupReport& report);

} // namespace geometry::io
