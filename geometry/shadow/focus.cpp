#include "geometry/shadow/focus.h"

#include <algorithm>
#include <cmath>

namespace geometry::shadow {

std::array<glm::vec3, 8> frustumCorners(const scene::Camera& cam, float aspect, float near, float far) noexcept {
    // The view matrix is a rotation and a translation: its inverse's axes are its rows.
    const glm::mat4 view = cam.view();
    const glm::vec3 right(view[0][0], view[1][0], view[2][0]), up(view[0][1], view[1][1], view[2][1]),
        back(view[0][2], view[1][2], view[2][2]);
    const glm::vec3 eye = cam.eye;
    const float tanPhi = std::tan(glm::radians(cam.fovYDeg) * 0.5f);
    std::array<glm::vec3, 8> c{};
    for (int i = 0; i < 8; ++i) {
        const float d = (i & 4) ? far : near;
        const float h = d * tanPhi, w = h * aspect;
        c[i] = eye - back * d + right * ((i & 1) ? w : -w) + up * ((i & 2) ? h : -h);
    }
    return c;
}

glm::vec3 exitTowardLight(const glm::vec3& p, const glm::vec3& l, const scene::Aabb& S) noexcept {
    if (!S.contains(p, 1e-4f * std::max(1.f, glm::length(S.extent())))) return p;
    const glm::vec3 dir = -l;
    float tExit = std::numeric_limits<float>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (dir[k] > 0.f) tExit = std::min(tExit, (S.hi[k] - p[k]) / dir[k]);
        else if (dir[k] < 0.f) tExit = std::min(tExit, (S.lo[k] - p[k]) / dir[k]);
    }
    if (!std::isfinite(tExit) || tExit < 0.f) return p;
    return p + tExit * dir;
}

std::vector<glm::vec3> focusBody(const std::array<glm::vec3, 8>& frustum, const scene::Aabb& S, const glm::vec3& l,
                                 std::span<const Plane> clip) {
    ConvexBody body = ConvexBody::fromCorners(frustum);
    body.clip(S);
    for (const Plane& plane : clip)
        if (!body.empty()) body.clip(plane);
    std::vector<glm::vec3> points = body.vertices();
    const size_t n = points.size();
    for (size_t i = 0; i < n; ++i) points.push_back(exitTowardLight(points[i], l, S));
    return points;
}

} // namespace geometry::shadow
