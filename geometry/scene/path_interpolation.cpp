#include "geometry/scene/path_interpolation.h"

#include "geometry/scene/light_angle.h"

#include <algorithm>
#include <cmath>

namespace geometry::scene {

namespace {

/// Segment index i and the fraction u within [key i, key i+1] for t over `count` keys (count ≥ 2).
std::pair<size_t, float> segment(size_t count, double t) noexcept {
    t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
    const double x = t * double(count - 1);
    const size_t i = std::min(size_t(x), count - 2);
    return {i, float(x - double(i))};
}

glm::vec3 unitOr(const glm::vec3& d, const glm::vec3& fallback) noexcept {
    const float len = glm::length(d);
    return len > 0.f && std::isfinite(len) ? d / len : fallback;
}

} // namespace

double pathParameter(int index, int frames) noexcept {
    return frames > 1 ? std::clamp(double(index) / double(frames - 1), 0.0, 1.0) : 0.0;
}

Camera cameraAlongPath(const std::vector<Camera>& keys, double t) noexcept {
    if (keys.empty()) return {};
    if (keys.size() == 1) return keys.front();
    const auto [i, u] = segment(keys.size(), t);
    const Camera& a = keys[i];
    const Camera& b = keys[i + 1];
    Camera c = a;
    c.eye = glm::mix(a.eye, b.eye, u);
    c.target = glm::mix(a.target, b.target, u);
    c.up = unitOr(glm::mix(a.up, b.up, u), a.up);
    c.fovYDeg = glm::mix(a.fovYDeg, b.fovYDeg, u);
    c.near = a.near * std::pow(b.near / a.near, u);
    c.far = a.far * std::pow(b.far / a.far, u);
    if (!(c.near > 0.f) || !std::isfinite(c.near)) c.near = a.near;
    if (!(c.far > c.near) || !std::isfinite(c.far)) c.far = std::max(a.far, b.far);
    return c;
}

glm::vec3 lightAlongPath(const std::vector<glm::vec3>& keys, double t) noexcept {
    const glm::vec3 down(0.f, -1.f, 0.f);
    if (keys.empty()) return down;
    if (keys.size() == 1) return unitOr(keys.front(), down);
    const auto [i, u] = segment(keys.size(), t);
    const glm::vec3 a = unitOr(keys[i], down), b = unitOr(keys[i + 1], down);
    // Rotating a towards b in their plane by u·angle(a, b) is slerp.
    return lightAtViewAngle(a, b, u * lightViewAngleDeg(a, b));
}

glm::vec3 positionAlongPath(const std::vector<glm::vec3>& keys, double t) noexcept {
    if (keys.empty()) return glm::vec3(0.f);
    if (keys.size() == 1) return keys.front();
    const auto [i, u] = segment(keys.size(), t);
    return glm::mix(keys[i], keys[i + 1], u);
}

Light lightAlongPath(Light light, const LightPathKeys& keys, double t) noexcept {
    if (!keys.directions.empty()) light.direction = lightAlongPath(keys.directions, t);
    if (!keys.positions.empty()) light.position = positionAlongPath(keys.positions, t);
    return light;
}

} // namespace geometry::scene
