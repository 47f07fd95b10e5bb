#include "geometry/scene/light_angle.h"

#include "geometry/scene/scene.h"

#include <algorithm>
#include <cmath>

namespace geometry::scene {

namespace {

bool finite(const glm::dvec3& x) noexcept { return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z); }

/// x made ⊥ to unit v and normalized; zero when x is (nearly) parallel to v or not finite.
glm::dvec3 perpendicularPart(const glm::dvec3& x, const glm::dvec3& v) noexcept {
    if (!finite(x)) return glm::dvec3(0.0);
    const double len = glm::length(x);
    if (!(len > 0.0)) return glm::dvec3(0.0);
    const glm::dvec3 p = x / len - glm::dot(x / len, v) * v;
    const double plen = glm::length(p);
    // Below ~1e-6 rad off the axis, the reference's side of v is float noise, not a choice.
    return plen > 1e-6 ? p / plen : glm::dvec3(0.0);
}

} // namespace

glm::vec3 lightAtViewAngle(const glm::vec3& vIn, const glm::vec3& reference, float angleDeg) noexcept {
    glm::dvec3 v(vIn);
    const double vlen = glm::length(v);
    v = finite(v) && vlen > 0.0 ? v / vlen : glm::dvec3(0.0, 0.0, -1.0);
    glm::dvec3 u = perpendicularPart(glm::dvec3(reference), v);
    if (u == glm::dvec3(0.0)) u = perpendicularPart({0.0, -1.0, 0.0}, v);
    if (u == glm::dvec3(0.0)) u = perpendicularPart({-1.0, 0.0, 0.0}, v); // v vertical
    const double a = glm::radians(std::isnan(angleDeg) ? 0.0 : std::clamp(double(angleDeg), 0.0, 180.0));
    return glm::vec3(glm::normalize(std::cos(a) * v + std::sin(a) * u));
}

} // namespace geometry::scene
