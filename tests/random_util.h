#pragma once
// Deterministic random cameras and lights for property tests (same numbers on every platform:
// no std::uniform_real_distribution).
#include <glm/glm.hpp>

#include <cmath>
#include <random>

namespace testutil {

inline float uniform01(std::mt19937& rng) { return float(rng() >> 8) * (1.f / 16777216.f); }
inline float uniform(std::mt19937& rng, float a, float b) { return a + (b - a) * uniform01(rng); }

inline glm::vec3 randomUnit(std::mt19937& rng) {
    for (;;) {
        const glm::vec3 v(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
        const float len = glm::length(v);
        if (len > 0.1f && len <= 1.f) return v / len;
    }
}

/// p lands in clip space's unit cube under m (in front of the projection centre), within eps.
inline bool insideUnitCube(const glm::mat4& m, const glm::vec3& p, float eps) {
    const glm::vec4 c = m * glm::vec4(p, 1.f);
    if (!(c.w > 0.f)) return false;
    const glm::vec3 ndc = glm::vec3(c) / c.w;
    return std::abs(ndc.x) <= 1.f + eps && std::abs(ndc.y) <= 1.f + eps && std::abs(ndc.z) <= 1.f + eps;
}

} // namespace testutil
