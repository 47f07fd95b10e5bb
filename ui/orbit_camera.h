#pragma once
// Orbit camera (drag to turn, scroll to zoom) and azimuth/elevation light control.
#include "geometry/scene.h"

namespace ui {

struct OrbitCamera {
    glm::vec3 target{0.f};
    float yawDeg = 0.f, pitchDeg = 20.f, distance = 10.f;

    static OrbitCamera from(const geometry::Camera& c) noexcept;
    void rotate(float dxPixels, float dyPixels) noexcept;
    void zoom(float wheelSteps) noexcept;
    /// Writes eye and target into `c`, keeping its lens settings.
    void applyTo(geometry::Camera& c) const noexcept;
};

struct SunAngles {
    float azimuthDeg = 0.f, elevationDeg = 45.f;
    static SunAngles from(const glm::vec3& l) noexcept;
    [[nodiscard]] glm::vec3 direction() const noexcept; // l, from the light into the scene
};

} // namespace ui
