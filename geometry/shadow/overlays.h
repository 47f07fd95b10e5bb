#pragma once
// Line overlays for the light views: what the plan did, drawn in the map's own (warped) space
// or in the unwarped light view. Segments are world space unless `inMapNdc`; colours are the
// renderer's business, chosen by kind.
#include "geometry/shadow/shadow_plan.h"

#include <vector>

namespace geometry::shadow {

/// SampleBounds: focus.mode = samples, where the visible samples are (V_i ∩ S ∩ their prism).
/// LightVolume: what a positional light covers (docs/design.md §3.10): a spot's cone (its rim at the
/// range and four lines from the apex), a point light's cube-face boundaries (the eight rays along
/// the cube's diagonals, where three faces meet).
enum class OverlayKind {
    SceneBounds,
    ViewFrustum,
    SplitFrustum,
    FocusBody,
    WarpFrustum,
    SampleBounds,
    LightVolume,
    Count
};

/// Segments of the spot's rim circle; the apex lines start this fraction of the range from the
/// light (a segment through the projection centre has no image).
inline constexpr int kConeRimSegments = 32;
inline constexpr float kLightVolumeStart = 0.01f;

struct OverlaySegment {
    glm::vec3 a{0.f}, b{0.f};
    OverlayKind kind = OverlayKind::SceneBounds;
    bool inMapNdc = false; // a, b are the split map's normalized device coordinates (x, y)
};

/// Overlays for split `split`'s warped map: S, V, V_i, the outline of B_i as the map sees it (2D
/// convex hull of its points in map coordinates), the samples' outline when fitted to them, P
/// (the map volume) and a positional light's volume (cone or faces). World segments are to be
/// drawn through the split's lightViewProj with depth clamping; GL clips what lies outside.
[[nodiscard]] std::vector<OverlaySegment> warpedViewOverlays(const ShadowPlan& plan, int split);

/// Overlays for the unwarped light view: S, V, every split's V_i, B_i outline and P, and a
/// positional light's volume.
[[nodiscard]] std::vector<OverlaySegment> unwarpedViewOverlays(const ShadowPlan& plan);

/// 2D convex hull (counter-clockwise) of points; collinear points dropped.
[[nodiscard]] std::vector<glm::vec2> convexHull2D(std::vector<glm::vec2> points);

} // namespace geometry::shadow
