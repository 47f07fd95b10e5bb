#include "orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace ui {

OrbitCamera OrbitCamera::from(const geometry::Camera& c) noexcept {
    OrbitCamera o;
    o.target = c.target;
    const glm::vec3 d = c.eye - c.target;
    o.distance = std::max(glm::length(d), 1e-3f);
    o.pitchDeg = glm::degrees(std::asin(std::clamp(d.y / o.distance, -1.f, 1.f)));
    o.yawDeg = glm::degrees(std::atan2(d.x, d.z));
    return o;
}

void OrbitCamera::rotate(float dx, float dy) noexcept {
    yawDeg -= 0.3f * dx;
    pitchDeg = std::clamp(pitchDeg + 0.3f * dy, -89.f, 89.f);
}

void OrbitCamera::zoom(float steps) noexcept { distance = std::clamp(distance * std::pow(0.9f, steps), 0.05f, 1e5f); }

void OrbitCamera::applyTo(geometry::Camera& c) const noexcept {
    const float yaw = glm::radians(yawDeg), pitch = glm::radians(pitchDeg);
    const glm::vec3 d(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    c.target = target;
    c.eye = target + distance * d;
}

SunAngles SunAngles::from(const glm::vec3& l) noexcept {
    const glm::vec3 toSun = -glm::normalize(l);
    return {glm::degrees(std::atan2(toSun.x, toSun.z)),
            glm::degrees(std::asin(std::clamp(toSun.y, -1.f, 1.f)))};
}

glm::vec3 SunAngles::direction() const noexcept {
    const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
    return -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

} // namespace ui
