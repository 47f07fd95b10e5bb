#include "geometry/shadow/convex_body.h"

#include <algorithm>
#include <cmath>

namespace geometry::shadow {

ConvexBody ConvexBody::fromCorners(const std::array<glm::vec3, 8>& c) {
    ConvexBody b;
    b.faces_ = {
        {c[0], c[4], c[6], c[2]}, {c[1], c[3], c[7], c[5]}, {c[0], c[1], c[5], c[4]},
        {c[2], c[6], c[7], c[3]}, {c[0], c[2], c[3], c[1]}, {c[4], c[5], c[7], c[6]},
    };
    return b;
}

static float scaleOf(const std::vector<glm::vec3>& pts) {
    scene::Aabb b;
    for (const auto& p : pts) b.add(p);
    const glm::vec3 e = b.extent();
    return std::max({e.x, e.y, e.z, 1e-6f});
}

static void addUnique(std::vector<glm::vec3>& pts, const glm::vec3& p, float eps) {
    for (const auto& q : pts)
        if (glm::all(glm::lessThanEqual(glm::abs(q - p), glm::vec3(eps)))) return;
    pts.push_back(p);
}

void ConvexBody::clip(const Plane& plane) {
    // Most planes cut nothing (a frustum well inside the scene): skip them without allocating.
    bool cuts = false;
    for (const auto& face : faces_)
        for (const auto& p : face) cuts = cuts || plane.distance(p) > 0.f;
    if (!cuts) return;
    std::vector<Polygon> out;
    out.reserve(faces_.size() + 1);
    std::vector<glm::vec3> cut; // points on the plane: the cap's vertices
    cut.reserve(2 * faces_.size());
    for (const auto& face : faces_) {
        Polygon kept;
        kept.reserve(face.size() + 1);
        const size_t n = face.size();
        for (size_t i = 0; i < n; ++i) {
            const glm::vec3& a = face[i];
            const glm::vec3& b = face[(i + 1) % n];
            const float da = plane.distance(a), db = plane.distance(b);
            if (da <= 0.f) kept.push_back(a);
            if (da == 0.f) cut.push_back(a);
            if ((da < 0.f && db > 0.f) || (da > 0.f && db < 0.f)) {
                const glm::vec3 p = a + (b - a) * (da / (da - db));
                kept.push_back(p);
                cut.push_back(p);
            }
        }
        if (kept.size() >= 3) out.push_back(std::move(kept));
    }
    if (!out.empty() && cut.size() >= 3) {
        // Order the cap's points around their centroid, counter-clockwise about the outward normal.
        std::vector<glm::vec3> cap;
        const float eps = 1e-5f * scaleOf(cut);
        for (const auto& p : cut) addUnique(cap, p, eps);
        if (cap.size() >= 3) {
            glm::vec3 centre(0.f);
            for (const auto& p : cap) centre += p;
            centre /= static_cast<float>(cap.size());
            const glm::vec3 nrm = glm::normalize(plane.n);
            const glm::vec3 helper = std::abs(nrm.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
            const glm::vec3 u = glm::normalize(glm::cross(nrm, helper));
            const glm::vec3 v = glm::cross(nrm, u);
            std::sort(cap.begin(), cap.end(), [&](const glm::vec3& p, const glm::vec3& q) {
                return std::atan2(glm::dot(p - centre, v), glm::dot(p - centre, u)) <
                       std::atan2(glm::dot(q - centre, v), glm::dot(q - centre, u));
            });
            out.push_back(std::move(cap));
        }
    }
    faces_ = std::move(out);
}

void ConvexBody::clip(const scene::Aabb& box) {
    if (box.empty()) {
        faces_.clear();
        return;
    }
    clip(Plane{{-1, 0, 0}, box.lo.x});
    clip(Plane{{1, 0, 0}, -box.hi.x});
    clip(Plane{{0, -1, 0}, box.lo.y});
    clip(Plane{{0, 1, 0}, -box.hi.y});
    clip(Plane{{0, 0, -1}, box.lo.z});
    clip(Plane{{0, 0, 1}, -box.hi.z});
}

std::vector<glm::vec3> ConvexBody::vertices() const {
    std::vector<glm::vec3> all;
    for (const auto& f : faces_) all.insert(all.end(), f.begin(), f.end());
    std::vector<glm::vec3> unique;
    if (all.empty()) return unique;
    const float eps = 1e-5f * scaleOf(all);
    for (const auto& p : all) addUnique(unique, p, eps);
    return unique;
}

} // namespace geometry::shadow
