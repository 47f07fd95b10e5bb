#include "geometry/shadow/culling.h"

namespace geometry::shadow {

ClipOverlap clipOverlap(const scene::Aabb& box, const glm::mat4& viewProj) noexcept {
    if (box.empty()) return ClipOverlap::Outside;
    // Clip-space corners; a box is culled when all corners fail the same plane test. NaN corners
    // fail no test and pass none: never Inside.
    int outside[6] = {}, inside = 0;
    for (const auto& c : box.corners()) {
        const glm::vec4 p = viewProj * glm::vec4(c, 1.f);
        outside[0] += p.x < -p.w;
        outside[1] += p.x > p.w;
        outside[2] += p.y < -p.w;
        outside[3] += p.y > p.w;
        outside[4] += p.z < -p.w;
        outside[5] += p.z > p.w;
        inside += p.x >= -p.w && p.x <= p.w && p.y >= -p.w && p.y <= p.w && p.z >= -p.w && p.z <= p.w;
    }
    for (int k : outside)
        if (k == 8) return ClipOverlap::Outside;
    return inside == 8 ? ClipOverlap::Inside : ClipOverlap::Partly;
}

} // namespace geometry::shadow
