#pragma once
// Camera rig for the eye view: orbit (drag), pan, dolly (scroll), fly (look around the eye, move
// with WASD/QE) and fit (double-click); azimuth/elevation light control. Pure math on plain values.
#include "geometry/scene/scene.h"

namespace ui {

struct OrbitCamera {
    glm::vec3 target{0.f};
    float yawDeg = 0.f, pitchDeg = 20.f, distance = 10.f;

    static OrbitCamera from(const geometry::scene::Camera& c) noexcept;
    /// Turns about the target.
    void rotate(float dxPixels, float dyPixels) noexcept;
    void zoom(float wheelSteps) noexcept;
    /// Moves eye and target across the view, in pixels of a view `viewHeightPixels` tall with
    /// vertical field of view `fovYDeg`, so the point under the cursor follows it at the target.
    void pan(float dxPixels, float dyPixels, float viewHeightPixels, float fovYDeg) noexcept;
    /// Turns about the eye (fly mode's mouse look): the eye stays, the target moves.
    void look(float dxPixels, float dyPixels) noexcept;
    /// Moves eye and target along the view (forward), across it (right) and world up, in scene
    /// units.
    void fly(float forward, float right, float up) noexcept;
    /// Keeps the direction, looks at the centre of `box` from where its bounding sphere just fits a
    /// view of vertical field of view `fovYDeg` and `aspect` (width / height): the eye view's
    /// double-click. An empty box changes nothing.
    void fit(const geometry::scene::Aabb& box, float fovYDeg, float aspect) noexcept;
    [[nodiscard]] glm::vec3 eye() const noexcept;
    /// Writes eye and target into `c`, keeping its lens settings.
    void applyTo(geometry::scene::Camera& c) const noexcept;
};

/// What fitting frames: every mesh placement but flat ones (a ground or sea plane, thinner than
/// 1/1000 of its width, would shrink the model to a speck), or the whole scene when that leaves nothing.
[[nodiscard]] geometry::scene::Aabb fitBounds(const geometry::scene::Scene& scene) noexcept;

struct SunAngles {
    float azimuthDeg = 0.f, elevationDeg = 45.f;
    static SunAngles from(const glm::vec3& l) noexcept;
    [[nodiscard]] glm::vec3 direction() const noexcept; // l, from the light into the scene
    [[nodiscard]] bool operator==(const SunAngles&) const = default;
};

} // namespace ui
