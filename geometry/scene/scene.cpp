#include "geometry/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace geometry::scene {

Aabb Mesh::worldBounds() const noexcept {
    // The box of the transformed vertices, not the transformed local box: under a rotation the
    // latter is loose (up to sqrt(3) times wider), which wastes shadow-map texels.
    Aabb world;
    const glm::mat3 linear(transform);
    const glm::vec3 offset(transform[3]);
    for (const auto& p : positions) world.add(linear * p + offset);
    return world;
}

Aabb Mesh::placementBounds(size_t i) const noexcept {
    if (!instanced()) {
        if (chunks.empty()) return worldBounds();
        Aabb b;
        for (const auto& c : chunks) b.add(c.bounds);
        return b;
    }
    const glm::mat4& m = instances[i];
    if (chunks.empty()) return worldBounds().transformed(m);
    Aabb b;
    for (const auto& c : chunks) b.add(c.bounds.transformed(m));
    return b;
}

size_t Mesh::firstPlacementBeyondFloat() const noexcept {
    for (size_t i = 0; i < placementCount(); ++i)
        if (const Aabb b = placementBounds(i); !b.empty() && !(finite(b.lo) && finite(b.hi))) return i;
    return placementCount();
}

glm::vec3 Camera::viewDir() const noexcept {
    const glm::vec3 d = target - eye;
    const float len = glm::length(d);
    return len > 0.f && std::isfinite(len) ? d / len : glm::vec3(0.f, 0.f, -1.f);
}

glm::mat4 Camera::view() const noexcept {
    const glm::vec3 v = viewDir();
    // Keep lookAt well defined when looking straight along `up`.
    glm::vec3 u = up;
    if (std::abs(glm::dot(glm::normalize(u), v)) > 0.999f)
        u = std::abs(v.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    return glm::lookAt(eye, eye + v, u);
}

glm::mat4 Camera::projection(float aspect) const noexcept {
    return glm::perspective(glm::radians(fovYDeg), aspect > 0.f ? aspect : 1.f, near, far);
}

glm::vec3 Light::l() const noexcept {
    const float len = glm::length(direction);
    return len > 0.f && std::isfinite(len) ? direction / len : glm::vec3(0.f, -1.f, 0.f);
}

glm::vec3 Light::lAt(const glm::vec3& x) const noexcept {
    if (!positional()) return l();
    const glm::vec3 d = x - position;
    const float len = glm::length(d);
    return len > 0.f && std::isfinite(len) ? d / len : l();
}

const char* lightTypeName(LightType t) noexcept {
    switch (t) {
    case LightType::Spot: return "spot";
    case LightType::Point: return "point";
    default: return "directional";
    }
}

Aabb Scene::bounds() const noexcept {
    Aabb b;
    for (const auto& m : meshes)
        for (size_t i = 0; i < m.placementCount(); ++i) b.add(m.placementBounds(i));
    return b;
}

size_t Scene::triangleCount() const noexcept {
    size_t n = 0;
    for (const auto& m : meshes) n += m.triangleCount();
    return n;
}

uint64_t Scene::placedTriangleCount() const noexcept {
    uint64_t n = 0;
    for (const auto& m : meshes) n += m.placedTriangleCount();
    return n;
}

static float acosDeg(float c) noexcept {
    if (!std::isfinite(c)) return 0.f;
    return glm::degrees(std::acos(std::clamp(c, -1.f, 1.f)));
}

float gammaDeg(const glm::vec3& v, const glm::vec3& l) noexcept {
    const float d = glm::length(v) * glm::length(l);
    return d > 0.f ? acosDeg(std::abs(glm::dot(v, l)) / d) : 0.f;
}

float lightViewAngleDeg(const glm::vec3& v, const glm::vec3& l) noexcept {
    const float d = glm::length(v) * glm::length(l);
    return d > 0.f ? acosDeg(glm::dot(v, l) / d) : 0.f;
}

} // namespace geometry::scene
