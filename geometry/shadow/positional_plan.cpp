#include "geometry/shadow/positional_plan.h"

#include "geometry/shadow/convex_body.h"
#include "geometry/shadow/focus.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geometry::shadow {

namespace {
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;

/// The widest half angle a spot light's single map covers: beyond it texels stretch without bound.
constexpr double kMaxSpotHalfAngleDeg = 80.0;
/// The map's near plane never comes closer than this fraction of its far plane (depth precision).
constexpr double kMinNearFraction = 1e-3;

/// A frustum from the light: looking along `axis`, x/(−z) ∈ [x0, x1] and y/(−z) ∈ [y0, y1] in its view.
struct Pyramid {
    dvec3 apex, axis, up;
    double x0, x1, y0, y1;
    [[nodiscard]] dmat4 view() const noexcept { return glm::lookAt(apex, apex + axis, up); }
};

Plane worldPlane(const dmat4& view, const dvec3& nView, const dvec3& apex) noexcept {
    const dvec3 n = glm::transpose(glm::dmat3(view)) * nView; // view is a rotation about the apex
    return Plane{glm::vec3(n), float(-glm::dot(n, apex))};
}

/// `body` ∩ the pyramid's four sides ∩ depth along the axis in [nearDepth, farDepth].
void clipToPyramid(ConvexBody& body, const Pyramid& p, double nearDepth, double farDepth) {
    const dmat4 v = p.view();
    // In view space the light looks along −z: x ≤ x1·(−z) is x + x1·z ≤ 0, and so on.
    body.clip(worldPlane(v, {1.0, 0.0, p.x1}, p.apex));
    body.clip(worldPlane(v, {-1.0, 0.0, -p.x0}, p.apex));
    body.clip(worldPlane(v, {0.0, 1.0, p.y1}, p.apex));
    body.clip(worldPlane(v, {0.0, -1.0, -p.y0}, p.apex));
    body.clip(Plane{glm::vec3(-p.axis), float(glm::dot(p.axis, p.apex) + nearDepth)});
    body.clip(Plane{glm::vec3(p.axis), float(-glm::dot(p.axis, p.apex) - farDepth)});
}

ConvexBody boxBody(const scene::Aabb& box) { return ConvexBody::fromCorners(box.corners()); }

/// Depth along the axis of the nearest and farthest of `points`.
std::pair<double, double> depthRange(const std::vector<glm::vec3>& points, const Pyramid& p) noexcept {
    double lo = std::numeric_limits<double>::max(), hi = 0.0;
    for (const auto& q : points) {
        const double z = glm::dot(dvec3(q) - p.apex, p.axis);
        lo = std::min(lo, z);
        hi = std::max(hi, z);
    }
    return {lo, hi};
}

std::array<glm::vec3, 8> cornersInWorld(const dmat4& viewProj) noexcept {
    const dmat4 inv = glm::inverse(viewProj);
    std::array<glm::vec3, 8> out{};
    for (int i = 0; i < 8; ++i) {
        const dvec4 c = inv * dvec4((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
        out[size_t(i)] = glm::vec3(dvec3(c) / c.w);
    }
    return out;
}

/// One map over `p`: B = V ∩ S ∩ p within the light's range; near at the nearest point of S in p
/// (so every caster between the light and B is drawn), far at B's farthest. `fitToBody` narrows
/// the pyramid to B's angular extent plus `reachTexels` (a spot map; cube faces keep their partition).
SplitPlan planMap(const std::array<glm::vec3, 8>& frustum, const scene::Aabb& S, const scene::Light& light, Pyramid p,
                  bool fitToBody, int resolution, double reachTexels) {
    SplitPlan split;
    split.resolution = resolution;
    split.frustum = frustum;
    const double range = std::max(double(light.range), 1e-6);
    const double eps = range * kMinNearFraction;
    ConvexBody b = ConvexBody::fromCorners(frustum);
    b.clip(S);
    clipToPyramid(b, p, eps, range);
    std::vector<glm::vec3> body = b.vertices();
    if (body.empty()) return split;
    const dmat4 view = p.view();
    if (fitToBody) {
        double x0 = p.x1, x1 = p.x0, y0 = p.y1, y1 = p.y0;
        for (const auto& q : body) {
            const dvec3 v = dvec3(view * dvec4(dvec3(q), 1.0));
            const double z = std::max(-v.z, eps);
            x0 = std::min(x0, v.x / z), x1 = std::max(x1, v.x / z);
            y0 = std::min(y0, v.y / z), y1 = std::max(y1, v.y / z);
        }
        const double mx = (x1 - x0) * reachTexels / resolution + 1e-9, my = (y1 - y0) * reachTexels / resolution + 1e-9;
        p.x0 = std::max(p.x0, x0 - mx), p.x1 = std::min(p.x1, x1 + mx);
        p.y0 = std::max(p.y0, y0 - my), p.y1 = std::min(p.y1, y1 + my);
    }
    ConvexBody casters = boxBody(S);
    clipToPyramid(casters, p, eps, range);
    const auto [bodyNear, bodyFar] = depthRange(body, p);
    const double far = std::min(range, bodyFar * (1.0 + 1e-3) + eps);
    double near = casters.empty() ? bodyNear : depthRange(casters.vertices(), p).first;
    near = std::clamp(near * (1.0 - 1e-3), far * kMinNearFraction, far * 0.999);
    const dmat4 proj = glm::frustum(p.x0 * near, p.x1 * near, p.y0 * near, p.y1 * near, near, far);
    const dmat4 viewProj = proj * view;
    split.body = std::move(body);
    split.lightView = glm::mat4(view);
    split.lightProj = glm::mat4(proj);
    split.lightViewProj = glm::mat4(viewProj);
    split.warpDir = glm::vec3(p.up);
    split.warpCentre = glm::vec3(p.apex);
    split.mapVolume = cornersInWorld(viewProj);
    // Linear depth of a positional light is the distance from it (docs/design.md §3.10).
    const double corner = std::sqrt(1.0 + std::max(p.x0 * p.x0, p.x1 * p.x1) + std::max(p.y0 * p.y0, p.y1 * p.y1));
    split.linearDepthRange = {float(near), float(far * corner)};
    float zLo = 1.f, zHi = 0.f;
    dvec3 centre(0.0);
    for (const auto& q : split.body) {
        const dvec4 c = viewProj * dvec4(dvec3(q), 1.0);
        const float z = float(c.z / c.w * 0.5 + 0.5);
        zLo = std::min(zLo, z), zHi = std::max(zHi, z);
        centre += dvec3(q);
    }
    split.bodyDepthRange = {zLo, zHi};
    centre /= double(split.body.size());
    const dvec3 toCentre = centre - p.apex;
    const double dist = glm::length(toCentre);
    if (dist > 0.0) {
        const double step = std::max(1e-3 * dist, 1e-6);
        const auto mapDepth = [&](const dvec3& x) {
            const dvec4 c = viewProj * dvec4(x, 1.0);
            return c.z / c.w * 0.5 + 0.5;
        };
        split.depthPerUnit =
            float(std::max(0.0, (mapDepth(centre + step * toCentre / dist) - mapDepth(centre)) / step));
    }
    return split;
}

dvec3 anyUp(const dvec3& axis) noexcept { return std::abs(axis.y) < 0.99 ? dvec3(0, 1, 0) : dvec3(1, 0, 0); }

} // namespace

int cubeFace(const glm::vec3& d) noexcept {
    if (!std::isfinite(d.x + d.y + d.z)) return 0;
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.f ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.f ? 2 : 3;
    if (a.z > 0.f) return d.z >= 0.f ? 4 : 5;
    return 0; // zero
}

double cubeFaceTanHalf(int resolution, double reachTexels) noexcept {
    const double n = std::max(resolution, 16), m = std::clamp(reachTexels, 0.0, n / 4.0);
    return n / (n - 2.0 * m);
}

void planPositionalSplits(const scene::Aabb& S, const scene::Camera& camera, float aspect, const scene::Light& light,
                          int resolution, double reachTexels, ShadowPlan& plan) {
    const auto frustum = frustumCorners(camera, aspect, camera.near, camera.far);
    const dvec3 apex(light.position);
    if (light.type == scene::LightType::Spot) {
        const dvec3 axis(light.l());
        const double half = std::min(0.5 * double(light.coneDeg), kMaxSpotHalfAngleDeg);
        const double t = std::tan(glm::radians(half));
        plan.splits.push_back(
            planMap(frustum, S, light, {apex, axis, anyUp(axis), -t, t, -t, t}, true, resolution, reachTexels));
    } else {
        const double t = cubeFaceTanHalf(resolution, reachTexels);
        static const std::array<dvec3, kCubeFaces> axes{dvec3(1, 0, 0),  dvec3(-1, 0, 0), dvec3(0, 1, 0),
                                                        dvec3(0, -1, 0), dvec3(0, 0, 1),  dvec3(0, 0, -1)};
        for (const dvec3& axis : axes)
            plan.splits.push_back(
                planMap(frustum, S, light, {apex, axis, anyUp(axis), -t, t, -t, t}, false, resolution, reachTexels));
    }
    for (auto& split : plan.splits) {
        split.near = camera.near;
        split.far = camera.far;
        split.blendStart = camera.far;
    }
    // l for a point light: towards the middle of what its maps focus on (γ and the reports).
    dvec3 towards(0.0);
    for (const auto& split : plan.splits)
        for (const auto& q : split.body) towards += glm::normalize(dvec3(q) - apex + dvec3(1e-12));
    plan.l = light.type == scene::LightType::Point && glm::length(towards) > 0.0 ? glm::vec3(glm::normalize(towards))
                                                                                 : light.l();
    plan.gammaDeg = scene::gammaDeg(plan.v, plan.l);
    plan.lightViewAngleDeg = scene::lightViewAngleDeg(plan.v, plan.l);
}

std::vector<std::string> positionalLightWarnings(const ShadowSettings& s, const scene::Light& light) {
    std::vector<std::string> out;
    if (!light.positional()) return out;
    const std::string type = scene::lightTypeName(light.type);
    const std::string why = " has no effect for a " + type + " light: ";
    if (s.warp.method != WarpMethod::Uniform)
        out.push_back("warp.method = " + std::string(enumName(s.warp.method)) + why +
                      "its maps are the light's own perspective (docs/design.md §3.10)");
    if (s.splits.count > 1)
        out.push_back("splits.count = " + std::to_string(s.splits.count) + why +
                      (light.type == scene::LightType::Point ? "one map per cube face" : "one map per light"));
    if (s.focus == FocusMode::Samples) out.push_back("focus.mode = samples" + why + "its maps fit V ∩ S");
    if (s.stabilize != StabilizeMode::Off)
        out.push_back("stabilize.mode = " + std::string(enumName(s.stabilize)) + why +
                      "stabilizing positional maps is not implemented");
    if (s.casters.lod == CasterLod::Auto) out.push_back("casters.lod = auto" + why + "every triangle is drawn");
    if (light.type == scene::LightType::Spot && 0.5 * light.coneDeg > kMaxSpotHalfAngleDeg)
        out.push_back("light cone " + std::to_string(int(light.coneDeg)) +
                      "° is wider than one map covers well: its map spans " +
                      std::to_string(int(2 * kMaxSpotHalfAngleDeg)) + "° (a point light covers every direction)");
    return out;
}

} // namespace geometry::shadow
