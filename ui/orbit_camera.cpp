#include "orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
constexpr float kDegreesPerPixel = 0.3f;
float finiteOr(float v, float fallback) noexcept { return std::isfinite(v) ? v : fallback; }
glm::vec3 offsetDirection(float yawDeg, float pitchDeg) noexcept { // from target to eye
    const float yaw = glm::radians(yawDeg), pitch = glm::radians(pitchDeg);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}
} // namespace

OrbitCamera OrbitCamera::from(const geometry::scene::Camera& c) noexcept {
    OrbitCamera o;
    o.target = c.target;
    const glm::vec3 d = c.eye - c.target;
    o.distance = std::max(glm::length(d), 1e-3f);
    o.pitchDeg = glm::degrees(std::asin(std::clamp(d.y / o.distance, -1.f, 1.f)));
    o.yawDeg = glm::degrees(std::atan2(d.x, d.z));
    if (!std::isfinite(o.distance) || !std::isfinite(o.pitchDeg) || !std::isfinite(o.yawDeg)) o = OrbitCamera{};
    return o;
}

void OrbitCamera::rotate(float dx, float dy) noexcept {
    yawDeg -= kDegreesPerPixel * finiteOr(dx, 0.f);
    pitchDeg = std::clamp(pitchDeg + kDegreesPerPixel * finiteOr(dy, 0.f), -89.f, 89.f);
}

void OrbitCamera::zoom(float steps) noexcept {
    distance = std::clamp(distance * std::pow(0.9f, finiteOr(steps, 0.f)), 1e-3f, 1e6f);
}

void OrbitCamera::pan(float dx, float dy, float viewHeightPixels, float fovYDeg) noexcept {
    if (!(viewHeightPixels > 0.f) || !(fovYDeg > 0.f)) return;
    const glm::vec3 back = offsetDirection(yawDeg, pitchDeg);
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), back));
    const glm::vec3 up = glm::cross(back, right);
    // Scene units per pixel at the target's distance.
    const float unitsPerPixel = 2.f * distance * std::tan(glm::radians(fovYDeg) * 0.5f) / viewHeightPixels;
    target += unitsPerPixel * (-finiteOr(dx, 0.f) * right + finiteOr(dy, 0.f) * up);
}

void OrbitCamera::look(float dx, float dy) noexcept {
    const glm::vec3 e = eye();
    yawDeg -= kDegreesPerPixel * finiteOr(dx, 0.f);
    pitchDeg = std::clamp(pitchDeg - kDegreesPerPixel * finiteOr(dy, 0.f), -89.f, 89.f);
    target = e - distance * offsetDirection(yawDeg, pitchDeg);
}

void OrbitCamera::fly(float forward, float right, float up) noexcept {
    const glm::vec3 back = offsetDirection(yawDeg, pitchDeg);
    const glm::vec3 r = glm::normalize(glm::cross(glm::vec3(0, 1, 0), back));
    target += -finiteOr(forward, 0.f) * back + finiteOr(right, 0.f) * r + finiteOr(up, 0.f) * glm::vec3(0, 1, 0);
}

void OrbitCamera::fit(const geometry::scene::Aabb& box, float fovYDeg, float aspect) noexcept {
    if (box.empty()) return;
    const glm::vec3 centre = (box.lo + box.hi) * 0.5f;
    const float radius = std::max(0.5f * glm::length(box.hi - box.lo), 1e-3f);
    const float halfY = glm::radians(std::clamp(finiteOr(fovYDeg, 60.f), 1.f, 179.f)) * 0.5f;
    const float a = std::isfinite(aspect) && aspect > 0.f ? aspect : 1.f;
    const float half = std::min(halfY, std::atan(std::tan(halfY) * a)); // the narrower of the two
    if (!std::isfinite(centre.x + centre.y + centre.z + radius)) return;
    target = centre;
    distance = std::clamp(radius / std::sin(half), 1e-3f, 1e6f);
}

geometry::scene::Aabb fitBounds(const geometry::scene::Scene& scene) noexcept {
    geometry::scene::Aabb solid;
    for (const geometry::scene::Mesh& m : scene.meshes)
        for (size_t i = 0; i < m.placementCount(); ++i) {
            const geometry::scene::Aabb b = m.placementBounds(i);
            if (b.empty()) continue;
            const glm::vec3 e = b.hi - b.lo;
            const float smallest = std::min({e.x, e.y, e.z}), largest = std::max({e.x, e.y, e.z});
            if (smallest > 1e-3f * largest) solid.add(b);
        }
    return solid.empty() ? scene.bounds() : solid;
}

glm::vec3 OrbitCamera::eye() const noexcept { return target + distance * offsetDirection(yawDeg, pitchDeg); }

void OrbitCamera::applyTo(geometry::scene::Camera& c) const noexcept {
    c.target = target;
    c.eye = eye();
}

SunAngles SunAngles::from(const glm::vec3& l) noexcept {
    const float len = glm::length(l);
    if (!(len > 0.f) || !std::isfinite(len)) return {};
    const glm::vec3 toSun = -l / len;
    return {glm::degrees(std::atan2(toSun.x, toSun.z)), glm::degrees(std::asin(std::clamp(toSun.y, -1.f, 1.f)))};
}

glm::vec3 SunAngles::direction() const noexcept {
    const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
    return -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

} // namespace ui
