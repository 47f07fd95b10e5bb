#pragma once
// A convex polyhedron as a list of planar faces, just enough to clip a view frustum by the
// scene bounds (docs/design.md §3.1). The same approach as Wimmer's LiSPSM reference code.
#include "geometry/scene/aabb.h"

#include <array>
#include <vector>

namespace geometry::shadow {

/// Plane n·x + d = 0; points with n·x + d ≤ 0 are inside.
struct Plane {
    glm::vec3 n{0.f, 1.f, 0.f};
    float d = 0.f;
    [[nodiscard]] float distance(const glm::vec3& p) const noexcept { return glm::dot(n, p) + d; }
};

class ConvexBody {
public:
    using Polygon = std::vector<glm::vec3>;

    ConvexBody() = default;
    /// Hexahedron from 8 corners indexed by bits (x: 1, y: 2, z: 4), e.g. frustum corners
    /// (left/right, bottom/top, near/far).
    static ConvexBody fromCorners(const std::array<glm::vec3, 8>& c);

    /// Keeps the part inside `plane`, closing the cut with a cap face.
    void clip(const Plane& plane);
    void clip(const scene::Aabb& box);

    [[nodiscard]] bool empty() const noexcept { return faces_.empty(); }
    [[nodiscard]] const std::vector<Polygon>& faces() const noexcept { return faces_; }
    /// Distinct vertices (merged within a tolerance relative to the body's size).
    [[nodiscard]] std::vector<glm::vec3> vertices() const;

private:
    std::vector<Polygon> faces_;
};

} // namespace geometry::shadow
