#include "geometry/shadow/overlays.h"

#include <algorithm>
#include <cmath>

namespace geometry::shadow {

namespace {

/// The 12 edges of a hexahedron whose corners are indexed by bits (as frustumCorners gives them).
void addBoxEdges(std::vector<OverlaySegment>& out, const std::array<glm::vec3, 8>& c, OverlayKind kind) {
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) out.push_back({c[i], c[i | bit], kind, false});
}

std::array<glm::vec3, 8> corners(const scene::Aabb& b) { return b.corners(); }

/// An outline in a map: the hull of `points` projected by `viewProj` (points behind the projection
/// centre are skipped).
std::vector<glm::vec2> outline(const std::vector<glm::vec3>& points, const glm::mat4& viewProj) {
    std::vector<glm::vec2> pts;
    for (const auto& p : points) {
        const glm::vec4 c = viewProj * glm::vec4(p, 1.f);
        if (c.w > 0.f) pts.emplace_back(c.x / c.w, c.y / c.w);
    }
    return convexHull2D(std::move(pts));
}

void addOutline(std::vector<OverlaySegment>& out, const std::vector<glm::vec2>& hull, OverlayKind kind) {
    for (size_t i = 0; i < hull.size(); ++i) {
        const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        out.push_back({{a, 0.f}, {b, 0.f}, kind, true});
    }
}

/// B_i's outline, and the samples' within it, as `viewProj` sees them.
void addBodyOutlines(std::vector<OverlaySegment>& out, const SplitPlan& s, const glm::mat4& viewProj) {
    addOutline(out, outline(s.body, viewProj), OverlayKind::FocusBody);
    if (!s.sampleRegion.empty()) addOutline(out, outline(s.sampleRegion, viewProj), OverlayKind::SampleBounds);
}

/// A spot's cone (rim at the range, four apex lines) or a point light's eight cube diagonals.
void addLightVolume(std::vector<OverlaySegment>& out, const scene::Light& light) {
    if (!light.positional() || !(light.range > 0.f)) return;
    const glm::vec3 p = light.position;
    const float R = light.range;
    if (light.type == scene::LightType::Point) {
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 d = glm::normalize(glm::vec3(i & 1 ? 1.f : -1.f, i & 2 ? 1.f : -1.f, i & 4 ? 1.f : -1.f));
            out.push_back({p + kLightVolumeStart * R * d, p + R * d, OverlayKind::LightVolume, false});
        }
        return;
    }
    const glm::vec3 axis = light.l();
    const glm::vec3 e1 =
        glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 e2 = glm::cross(axis, e1);
    const float half = glm::radians(0.5f * light.coneDeg);
    // The rim: where the cone's surface reaches the range (slant length R).
    const auto rim = [&](int k) {
        const float a = 6.28318530718f * float(k) / float(kConeRimSegments);
        const glm::vec3 d = std::cos(half) * axis + std::sin(half) * (std::cos(a) * e1 + std::sin(a) * e2);
        return d;
    };
    for (int k = 0; k < kConeRimSegments; ++k)
        out.push_back({p + R * rim(k), p + R * rim(k + 1), OverlayKind::LightVolume, false});
    for (int k = 0; k < kConeRimSegments; k += kConeRimSegments / 4)
        out.push_back({p + kLightVolumeStart * R * rim(k), p + R * rim(k), OverlayKind::LightVolume, false});
}

} // namespace

std::vector<glm::vec2> convexHull2D(std::vector<glm::vec2> p) {
    // Andrew's monotone chain.
    std::sort(p.begin(), p.end(),
              [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    const auto cross = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::vec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0.f) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0.f) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

std::vector<OverlaySegment> warpedViewOverlays(const ShadowPlan& plan, int split) {
    std::vector<OverlaySegment> out;
    if (split < 0 || split >= int(plan.splits.size())) return out;
    const SplitPlan& s = plan.splits[split];
    addBoxEdges(out, corners(plan.sceneBounds), OverlayKind::SceneBounds);
    addBoxEdges(out, plan.viewFrustum, OverlayKind::ViewFrustum);
    addBoxEdges(out, s.frustum, OverlayKind::SplitFrustum);
    if (!s.empty()) {
        addBodyOutlines(out, s, s.lightViewProj);
        addBoxEdges(out, s.mapVolume, OverlayKind::WarpFrustum);
    }
    addLightVolume(out, plan.light);
    return out;
}

std::vector<OverlaySegment> unwarpedViewOverlays(const ShadowPlan& plan) {
    std::vector<OverlaySegment> out;
    addBoxEdges(out, corners(plan.sceneBounds), OverlayKind::SceneBounds);
    addBoxEdges(out, plan.viewFrustum, OverlayKind::ViewFrustum);
    for (const auto& s : plan.splits) {
        addBoxEdges(out, s.frustum, OverlayKind::SplitFrustum);
        if (s.empty()) continue;
        addBodyOutlines(out, s, plan.unwarpedViewProj);
        addBoxEdges(out, s.mapVolume, OverlayKind::WarpFrustum);
    }
    addLightVolume(out, plan.light);
    return out;
}

} // namespace geometry::shadow
