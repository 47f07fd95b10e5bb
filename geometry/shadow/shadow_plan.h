#pragma once
// The shadow plan: everything the renderer needs to draw shadows, decided here and nowhere
// else (docs/design.md §2). A plain value: rendering, overlays, charts and tests use the same plan.
#include "geometry/scene/scene.h"
#include "geometry/shadow/sample_bounds.h"
#include "geometry/shadow/settings.h"
#include "geometry/shadow/virtual_plan.h"

#include <array>
#include <string>
#include <vector>

namespace geometry::shadow {

struct Viewport {
    int width = 1280;
    int height = 720;
    [[nodiscard]] float aspect() const noexcept { return height > 0 ? float(width) / float(height) : 1.f; }
    [[nodiscard]] bool operator==(const Viewport&) const = default;
};

struct SplitPlan {
    float near = 0.f, far = 0.f; // [n_i, f_i], view distance
    std::vector<glm::vec3> body; // focus body B_i (world space); empty when V_i misses S
    glm::mat4 lightView{1.f};    // world → light space (rotation looking along l, +y = V_P)
    glm::mat4 lightProj{1.f};    // light space → shadow clip space: warp P, then fit to the unit cube
    glm::mat4 lightViewProj{1.f};
    int resolution = 0;
    double nPrime = kUniform;             // n'_i; +∞ = uniform (no warp)
    double lambda = 0.0;                  // Zhang's λ_i = n'_i / (f'−n'); 0 for uniform
    glm::vec3 warpDir{0.f, 0.f, -1.f};    // V_P, ⊥ l
    glm::vec3 warpCentre{0.f};            // projection centre c of P (world), when warped
    float warpDepth = 0.f;                // d: extent of B_i along V_P
    std::array<glm::vec3, 8> frustum{};   // V_i's corners (bits x: right, y: top, z: far)
    std::array<glm::vec3, 8> mapVolume{}; // world corners of the map's unit cube (the warp frustum P as fitted)
    glm::vec2 bodyDepthRange{0.f, 1.f};   // depth of B_i in this map, for display
    glm::vec2 linearDepthRange{0.f, 1.f}; // [lo, hi] of l·x over B_i and the casters up to S (linear z)
    float linearDepthScale = 1.f;         // 1/(hi − lo): linear depth = (l·x − lo)·scale (Scherzer §4.2)
    float depthPerUnit = 0.f;             // map depth per scene unit along l, at B_i's centre
    float dualDepthCap = 0.f;             // bias.z_max in this map's depth units (dual depth's cap)
    float blendStart = 0.f;               // view depth where this split's shadow starts fading into the next
                                          // split's (splits.blend); = far: no band
    glm::vec2 lookupShift{0.f};           // texels the eye pass shifts its lookups by: 0, except where a
                                          // test plants a misplaced map
    // focus.mode = samples: the visible samples in [near, far] (as the depth bins tell), and where
    // they are: V_i ∩ S ∩ their prism (B_i is this, extruded towards the light). A split without
    // samples is skipped: empty body, no pass.
    uint64_t samples = 0;
    bool skipped = false;
    std::vector<glm::vec3> sampleRegion;
    [[nodiscard]] bool empty() const noexcept { return body.empty(); }
    [[nodiscard]] bool warped() const noexcept { return nPrime < kUniform; }
};

struct ShadowPlan {
    /// The light planned for: a directional light's splits are view-depth ranges; a spot light has one
    /// map, a point light six cube faces (+X, −X, +Y, −Y, +Z, −Z; positional_plan.h).
    scene::Light light;
    glm::vec3 l{0.f, -1.f, 0.f};   // light direction, unit (a spot light's axis; a point light: towards its focus)
    glm::vec3 v{0.f, 0.f, -1.f};   // view direction, unit
    float gammaDeg = 0.f;          // γ = acos(|v·l|)
    float lightViewAngleDeg = 0.f; // acos(v·l): 0 light behind the eye, 180 facing it
    glm::mat4 eyeView{1.f}, eyeProj{1.f};
    std::array<glm::vec3, 8> viewFrustum{}; // V's corners, near to far
    scene::Aabb sceneBounds;                // S
    glm::vec3 eye{0.f};
    float cameraNear = 0.f, cameraFar = 0.f; // the camera's n and f (the splits may cover less)
    /// Fitted to the eye's samples (focus.mode = samples with sample bounds given), their view-depth range.
    bool fittedToSamples = false;
    glm::vec2 sampleDepthRange{0.f};
    uint64_t sampleCount = 0;
    /// An orthographic view from the light framing every B_i, the eye and P's projection centres,
    /// for the unwarped light view (what the warp does, seen without it).
    glm::mat4 unwarpedViewProj{1.f};
    /// Constant bias: receivers are tested as if moved this far towards the light (scene units),
    /// which is the same offset in every split whatever its warp.
    float receiverOffset = 0.f;
    glm::vec2 polygonOffset{0.f};   // (factor, units) while drawing the maps; zero: none (slope biases)
    float normalOffsetTexels = 0.f; // receivers move along their normal by this many world texels; 0: none
    /// casters.lod = auto: the error a chunk's level may have, in texels of the split's map at the
    /// chunk (caster_detail.h); 0: every pass draws every triangle.
    float casterLodTexels = 0.f;
    /// The settings as asked for: the renderer applies the bias, filter and sun from here, and the
    /// shaders read every declared value (renderer/settings_block.h).
    ShadowSettings settings;
    /// The maps the eye pass reads hold linear light depth: bias.linear_z, the moment filters (their
    /// moments are of linear depth) and PCSS (its penumbra needs blocker distances in scene units).
    bool linearDepth = false;
    std::vector<SplitPlan> splits;
    /// technique = virtual (a directional light): the virtual map's levels and pages; the splits are
    /// then the fitted map the light view frames, and not drawn.
    VirtualPlan virtualMap;
    /// What the settings asked for but this plan does not do: maps drawn smaller to fit the memory
    /// budget (memory_budget.h), settings without effect (setting_relevance.h). For metrics.json
    /// and the dashboard.
    std::vector<std::string> warnings;
};

/// Plans the shadow maps for one frame. Pure; never returns NaN matrices (an empty focus body
/// gives an empty split, which the renderer treats as "nothing casts a shadow"). Settings are
/// assumed valid (validateOrThrow); the camera's n > 0 and f > n. With focus.mode = samples and
/// `samples` given (this frame's, for this camera and light), splits and focus bodies are fitted
/// to them (docs/design.md §3.7); without, the plan is the geometric one. The light's own
/// `settings` overrides (validated when loaded) apply over `settings`; plan.settings holds the result.
[[nodiscard]] ShadowPlan planShadows(const ShadowSettings& settings, const scene::Aabb& S, const scene::Camera& camera,
                                     const scene::Light& light, const Viewport& viewport,
                                     const SampleBounds* samples = nullptr);

/// The warp direction V_P ⊥ l: the view direction projected onto the light's plane ("standard"), or
/// Scherzer's middle vector over `body` seen from `eye`. Zero when degenerate (v ∥ l).
[[nodiscard]] glm::dvec3 warpDirection(WarpDirection mode, const glm::dvec3& l, const glm::dvec3& v,
                                       const glm::dvec3& eye, const std::vector<glm::vec3>& body) noexcept;

} // namespace geometry::shadow
