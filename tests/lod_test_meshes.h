#pragma once
// Tessellated solids for the caster LOD tests and benchmark: tubes along their length too, as
// CAD exports them, and thin bars.
#include "geometry/scene/scene.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace testutil {

/// Appends an open tube (no caps) of `segments` sides and `rings` rows of quads, from `base`
/// along the unit `axis`, with smooth normals. seamCopies: the vertices at angle 0 are stored
/// twice (a UV seam, as CAD exports have), so only welding by position connects the seam.
inline void addTube(geometry::scene::Mesh& m, const glm::vec3& base, const glm::vec3& axis, float radius, float length,
                    int segments, int rings, bool seamCopies = false) {
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(helper, axis)), v = glm::cross(axis, u);
    const int columns = segments + (seamCopies ? 1 : 0);
    const auto first = static_cast<uint32_t>(m.positions.size());
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < columns; ++s) {
            const float t = glm::two_pi<float>() * float(s % segments) / float(segments);
            const glm::vec3 n = std::cos(t) * u + std::sin(t) * v;
            m.positions.push_back(base + axis * (length * float(r) / float(rings)) + radius * n);
            m.normals.push_back(n);
        }
    auto at = [&](int r, int s) {
        const int column = seamCopies ? s : s % segments;
        return first + uint32_t(r * columns + column);
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = at(r, s), b = at(r, s + 1), c = at(r + 1, s + 1), d = at(r + 1, s);
            m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
}

/// Appends a closed box bar of square cross-section `width` from a along the unit `axis`,
/// split into `segments` along its length, corners shared (welded).
inline void addBar(geometry::scene::Mesh& m, const glm::vec3& a, const glm::vec3& axis, float width, float length,
                   int segments) {
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 u = glm::normalize(glm::cross(helper, axis)) * (0.5f * width);
    const glm::vec3 v = glm::normalize(glm::cross(axis, u)) * (0.5f * width);
    const glm::vec3 corner[4] = {-u - v, u - v, u + v, -u + v}; // counter-clockwise about axis
    const auto first = static_cast<uint32_t>(m.positions.size());
    for (int i = 0; i <= segments; ++i)
        for (const glm::vec3& c : corner) {
            m.positions.push_back(a + axis * (length * float(i) / float(segments)) + c);
            m.normals.push_back(glm::normalize(c));
        }
    for (int i = 0; i < segments; ++i)
        for (uint32_t k = 0; k < 4; ++k) {
            const uint32_t p = first + uint32_t(4 * i) + k, q = first + uint32_t(4 * i) + (k + 1) % 4;
            m.indices.insert(m.indices.end(), {p, q, q + 4, p, q + 4, p + 4});
        }
    const uint32_t last = first + uint32_t(4 * segments);
    m.indices.insert(m.indices.end(), {first, first + 3, first + 2, first, first + 2, first + 1});
    m.indices.insert(m.indices.end(), {last, last + 1, last + 2, last, last + 2, last + 3});
}

} // namespace testutil
