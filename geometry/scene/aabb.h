#pragma once
// Axis-aligned bounding box; empty() until a point is added.
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

namespace geometry::scene {

/// Every coordinate finite (not NaN, not ±inf).
[[nodiscard]] inline bool finite(const glm::vec3& p) noexcept {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

struct Aabb {
    glm::vec3 lo{std::numeric_limits<float>::max()};
    glm::vec3 hi{std::numeric_limits<float>::lowest()};

    [[nodiscard]] bool empty() const noexcept { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
    /// glm::min and glm::max component by component (a NaN coordinate leaves the box as it was), written
    /// out: glm's vector forms call through a function pointer per component, the loaders' hot path.
    void add(const glm::vec3& p) noexcept {
        lo.x = p.x < lo.x ? p.x : lo.x;
        lo.y = p.y < lo.y ? p.y : lo.y;
        lo.z = p.z < lo.z ? p.z : lo.z;
        hi.x = hi.x < p.x ? p.x : hi.x;
        hi.y = hi.y < p.y ? p.y : hi.y;
        hi.z = hi.z < p.z ? p.z : hi.z;
    }
    void add(const Aabb& b) noexcept {
        if (!b.empty()) {
            add(b.lo);
            add(b.hi);
        }
    }
    [[nodiscard]] glm::vec3 center() const noexcept { return 0.5f * (lo + hi); }
    [[nodiscard]] glm::vec3 extent() const noexcept { return empty() ? glm::vec3(0.f) : hi - lo; }
    [[nodiscard]] bool contains(const glm::vec3& p, float eps = 0.f) const noexcept {
        return p.x >= lo.x - eps && p.y >= lo.y - eps && p.z >= lo.z - eps && p.x <= hi.x + eps && p.y <= hi.y + eps &&
               p.z <= hi.z + eps;
    }
    [[nodiscard]] std::array<glm::vec3, 8> corners() const noexcept {
        std::array<glm::vec3, 8> c{};
        for (int i = 0; i < 8; ++i) c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        return c;
    }
    /// Bounds of this box after an affine transform.
    [[nodiscard]] Aabb transformed(const glm::mat4& m) const noexcept {
        Aabb r;
        if (empty()) return r;
        for (const auto& c : corners()) r.add(glm::vec3(m * glm::vec4(c, 1.f)));
        return r;
    }
};

} // namespace geometry::scene
