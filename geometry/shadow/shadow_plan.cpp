// Index
//   helpers ........... perpendicular, fitUnitCube, depthRangeInMap, linearDepthRange, unwarpedView
//   one split's map ... SplitFrame, frameForSplit (warped or uniform), stableFrame (stabilize.mode = snap)
//   warpDirection ..... V_P: standard or Scherzer's middle vector
//   planShadows ....... the plan: planFrame (l, v, γ, offsets), the budget and warnings,
//                       splitBoundaries, per split focusSplit (B_i) and frameSplit (V_P, n', P), finishPlan

#include "geometry/shadow/shadow_plan.h"

#include "geometry/shadow/focus.h"
#include "geometry/shadow/memory_budget.h"
#include "geometry/shadow/positional_plan.h"
#include "geometry/shadow/setting_relevance.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace geometry::shadow {

namespace {

using dvec3 = glm::dvec3;
using dvec4 = glm::dvec4;
using dmat4 = glm::dmat4;

/// Beyond n' = kUniformRatio·(d + 1) a warp differs from uniform by less than float precision: use uniform.
constexpr double kUniformRatio = 1e5;

/// Any unit vector ⊥ l.
dvec3 perpendicular(const dvec3& l) noexcept {
    const dvec3 helper = std::abs(l.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0);
    return glm::normalize(glm::cross(l, helper));
}

struct Box {
    dvec3 lo{std::numeric_limits<double>::max()}, hi{std::numeric_limits<double>::lowest()};
    void add(const dvec3& p) noexcept {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
};

/// Maps `box` onto the cube [−1, 1]³, with a small margin so boundary points stay inside.
dmat4 fitUnitCube(Box box) noexcept {
    const dvec3 margin = glm::max((box.hi - box.lo) * 1e-5, dvec3(1e-7));
    box.lo -= margin;
    box.hi += margin;
    dmat4 m(1.0);
    for (int k = 0; k < 3; ++k) {
        m[k][k] = 2.0 / (box.hi[k] - box.lo[k]);
        m[3][k] = -(box.hi[k] + box.lo[k]) / (box.hi[k] - box.lo[k]);
    }
    return m;
}

dvec3 project(const dmat4& m, const dvec3& p) noexcept {
    const dvec4 c = m * dvec4(p, 1.0);
    return dvec3(c) / c.w;
}

/// Window depth [0, 1] of p under m.
double depth01(const dmat4& m, const dvec3& p) noexcept { return project(m, p).z * 0.5 + 0.5; }

glm::vec2 depthRangeInMap(const dmat4& m, const std::vector<glm::vec3>& points) noexcept {
    glm::vec2 r{1.f, 0.f};
    for (const auto& p : points) {
        const float d = std::clamp(float(depth01(m, dvec3(p))), 0.f, 1.f);
        r = {std::min(r.x, d), std::max(r.y, d)};
    }
    return r.x <= r.y ? r : glm::vec2(0.f, 1.f);
}

/// [lo, hi] of l·x: casters up to S's light-facing side, receivers down to B's far side.
glm::vec2 linearDepthRange(const std::vector<glm::vec3>& body, const dvec3& l, const scene::Aabb& S) noexcept {
    double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
    for (const auto& p : body) hi = std::max(hi, glm::dot(dvec3(p), l)), lo = std::min(lo, glm::dot(dvec3(p), l));
    for (const auto& c : S.corners()) lo = std::min(lo, glm::dot(dvec3(c), l));
    const double pad = std::max(1e-4 * (hi - lo), 1e-6);
    return {float(lo - pad), float(hi + pad)};
}

/// World corners of clip space's unit cube under `viewProj` (bits x, y, z: −1 or +1).
std::array<glm::vec3, 8> unitCubeInWorld(const dmat4& viewProj) noexcept {
    const dmat4 inv = glm::inverse(viewProj);
    std::array<glm::vec3, 8> out{};
    for (int i = 0; i < 8; ++i) {
        const dvec4 w = inv * dvec4((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
        out[i] = glm::vec3(std::abs(w.w) > 1e-300 ? dvec3(w) / w.w : dvec3(0.0));
    }
    return out;
}

/// Orthographic light view over every B_i, the eye and the warp centres, a little larger.
glm::mat4 unwarpedView(const ShadowPlan& plan) noexcept {
    const dmat4 view =
        glm::lookAt(dvec3(0.0), dvec3(plan.l), std::abs(plan.l.y) < 0.9f ? dvec3(0, 1, 0) : dvec3(1, 0, 0));
    Box box;
    const auto add = [&](const glm::vec3& p) { box.add(dvec3(view * dvec4(dvec3(p), 1.0))); };
    add(plan.eye);
    if (plan.light.positional()) add(plan.light.position);
    for (const auto& s : plan.splits) {
        for (const auto& p : s.body) add(p);
        if (s.warped()) add(s.warpCentre);
    }
    for (const auto& c : plan.sceneBounds.corners())
        box.lo.z = std::min(box.lo.z, dvec3(view * dvec4(dvec3(c), 1.0)).z),
        box.hi.z = std::max(box.hi.z, dvec3(view * dvec4(dvec3(c), 1.0)).z);
    // Square, centred, 10 % margin, so the picture is not stretched.
    const glm::dvec2 centre = 0.5 * (glm::dvec2(box.lo) + glm::dvec2(box.hi));
    const double half = 0.55 * std::max({box.hi.x - box.lo.x, box.hi.y - box.lo.y, 1e-3});
    box.lo = dvec3(centre.x - half, centre.y - half, box.lo.z);
    box.hi = dvec3(centre.x + half, centre.y + half, box.hi.z);
    dmat4 flipZ(1.0);
    flipZ[2][2] = -1.0;
    std::swap(box.lo.z, box.hi.z);
    box.lo.z = -box.lo.z;
    box.hi.z = -box.hi.z;
    return glm::mat4(fitUnitCube(box) * flipZ * view);
}

struct SplitFrame {
    dmat4 lightView;  // world → light space L
    dmat4 lightProj;  // L → shadow clip space
    dvec3 warpCentre; // world
    double nPrime;
    double d;
};

/// Builds L and the projection after it for B (Wimmer's LiSPSM construction, docs/design.md §3.2).
/// B's points pulled back to S's light-facing boundary are fitted too, so every caster between
/// B and the light stays in the map.
/// v rounded up to a 1/64 octave: a size that float noise and small camera moves leave alone.
double octaveStep(double v) noexcept { return std::exp2(std::ceil(std::log2(std::max(v, 1e-12)) * 64.0) / 64.0); }

/// stabilize.mode = quantize for a warped split: what moves the warp, held to steps (the map
/// resolution sets the step sizes).
struct WarpQuantization {
    bool on = false;
    int resolution = 0;
};

SplitFrame frameForSplit(const std::vector<glm::vec3>& body, const dvec3& l, const dvec3& vp, const dvec3& eye,
                         const scene::Aabb& S, double nPrime, const WarpQuantization& q = {}) {
    SplitFrame out{};
    out.lightView = glm::lookAt(dvec3(0.0), l, vp); // −z along l, +y along V_P
    std::vector<dvec3> pts;
    pts.reserve(body.size() * 2);
    double zTop = std::numeric_limits<double>::lowest(); // light space +z points towards the light
    for (const auto& c : S.corners()) zTop = std::max(zTop, dvec3(out.lightView * dvec4(dvec3(c), 1.0)).z);
    Box bodyBox;
    for (const auto& p : body) {
        const dvec3 q = dvec3(out.lightView * dvec4(dvec3(p), 1.0));
        bodyBox.add(q);
        pts.push_back(q);
        pts.push_back({q.x, q.y, std::max(q.z, zTop)});
    }
    out.d = bodyBox.hi.y - bodyBox.lo.y; // extent of B along V_P
    const dvec3 eyeL = dvec3(out.lightView * dvec4(eye, 1.0));
    out.nPrime = nPrime;
    if (!(nPrime < kUniformRatio * (out.d + 1.0))) {
        out.nPrime = kUniform;
        Box box;
        for (const auto& q : pts) box.add({q.x, q.y, -q.z}); // depth grows away from the light
        dmat4 flipZ(1.0);
        flipZ[2][2] = -1.0;
        out.lightProj = fitUnitCube(box) * flipZ;
        out.warpCentre = eye;
        return out;
    }
    // P looks along +y of L from c, which sits n' before B's near boundary along V_P.
    dvec3 c(eyeL.x, bodyBox.lo.y - nPrime, 0.5 * (bodyBox.lo.z + std::max(bodyBox.hi.z, zTop)));
    double depth = std::max(out.d, 1e-9);
    double step = 0.0;
    if (q.on) { // c on a grid of d/res, d in 1/64 octaves; c moves back (floor) so B stays ≥ n' ahead
        depth = octaveStep(depth);
        step = depth / double(std::max(q.resolution, 1));
        c = {std::round(c.x / step) * step, std::floor(c.y / step) * step, std::round(c.z / step) * step};
        depth += step;
    }
    dmat4 toP(0.0); // L → P's eye space: x = x_L, y = z_L (towards the light), z = −y_L (looks along +y_L)
    toP[0][0] = 1.0;
    toP[2][1] = 1.0;
    toP[1][2] = -1.0;
    toP[3] = dvec4(-c.x, -c.z, c.y, 1.0);
    const dmat4 P = glm::frustum(-1.0, 1.0, -1.0, 1.0, nPrime, nPrime + depth);
    dmat4 swizzle(0.0); // (X, Y, Z) → (X, Z, −Y): image plane (lateral, warp axis), depth away from light
    swizzle[0][0] = 1.0;
    swizzle[2][1] = 1.0;
    swizzle[1][2] = -1.0;
    swizzle[3][3] = 1.0;
    const dmat4 warp = swizzle * P * toP;
    Box box;
    for (const auto& p : pts) box.add(project(warp, p));
    if (q.on) // the map's extents (and depth range) in 1/64 octaves, its corner on that texel grid
        for (int k = 0; k < 3; ++k) {
            const double size = octaveStep(box.hi[k] - box.lo[k]), texel = size / double(std::max(q.resolution, 1));
            box.lo[k] = std::floor(box.lo[k] / texel) * texel;
            box.hi[k] = box.lo[k] + size + texel;
        }
    out.lightProj = fitUnitCube(box) * warp;
    out.warpCentre = dvec3(glm::inverse(out.lightView) * dvec4(c, 1.0));
    return out;
}

/// A held-still frame for an unwarped split (stabilize.mode = snap): the light looks along l with
/// an up vector that depends on l alone; the map's square covers the bounding sphere of the split's
/// view frustum V_i (its size does not change as the camera turns: the sphere of a fixed frustum
/// shape), with the radius rounded up to 1/64 of an octave so float noise cannot change it; its
/// centre is snapped to whole texels in light space, so a camera translation moves the map's
/// content by whole texels; depth spans S, which does not move with the camera.
SplitFrame stableFrame(const std::array<glm::vec3, 8>& frustum, const dvec3& l, const dvec3& eye, const scene::Aabb& S,
                       int resolution) {
    SplitFrame out{};
    out.lightView = glm::lookAt(dvec3(0.0), l, perpendicular(l));
    dvec3 centre(0.0);
    for (const auto& c : frustum) centre += dvec3(c);
    centre /= double(frustum.size());
    double r = 0.0;
    for (const auto& c : frustum) r = std::max(r, glm::length(dvec3(c) - centre));
    r = std::exp2(std::ceil(std::log2(std::max(r, 1e-9)) * 64.0) / 64.0);
    const double texel = 2.0 * r / double(std::max(resolution, 1));
    const dvec3 cL = dvec3(out.lightView * dvec4(centre, 1.0));
    const double cx = std::round(cL.x / texel) * texel, cy = std::round(cL.y / texel) * texel;
    Box depth; // depth grows away from the light (−z in L)
    for (const auto& c : S.corners()) depth.add(dvec3(0.0, 0.0, -dvec3(out.lightView * dvec4(dvec3(c), 1.0)).z));
    const double margin = std::max((depth.hi.z - depth.lo.z) * 1e-5, 1e-7);
    const double zLo = depth.lo.z - margin, zHi = depth.hi.z + margin;
    dmat4 proj(1.0); // L → [−1, 1]³: x, y by the snapped square (no margin: whole texels), z by S
    proj[0][0] = 1.0 / r;
    proj[3][0] = -cx / r;
    proj[1][1] = 1.0 / r;
    proj[3][1] = -cy / r;
    proj[2][2] = -2.0 / (zHi - zLo); // flips z: L's +z points to the light
    proj[3][2] = -(zHi + zLo) / (zHi - zLo);
    out.lightProj = proj;
    out.warpCentre = eye; // as every unwarped frame
    out.nPrime = kUniform;
    out.d = 2.0 * r;
    return out;
}

} // namespace

dvec3 warpDirection(WarpDirection mode, const dvec3& l, const dvec3& v, const dvec3& eye,
                    const std::vector<glm::vec3>& body) noexcept {
    const auto projectOnPlane = [&](const dvec3& x) { return x - glm::dot(x, l) * l; };
    if (mode == WarpDirection::Middle && !body.empty()) {
        // Scherzer's middle vector: the sum of eye → B vectors, projected onto the light's plane.
        dvec3 sum(0.0);
        double scale = 0.0;
        for (const auto& p : body) {
            const dvec3 e = dvec3(p) - eye;
            const double len = glm::length(e);
            if (len > 0.0) sum += e / len, scale += 1.0;
        }
        const dvec3 m = projectOnPlane(sum);
        if (scale > 0.0 && glm::length(m) > 1e-6 * scale) return glm::normalize(m);
    }
    const dvec3 s = projectOnPlane(v); // = (l × v) × l
    return glm::length(s) > 1e-9 ? glm::normalize(s) : dvec3(0.0);
}

namespace {

/// What every split of one plan is planned from.
struct SplitContext {
    const ShadowSettings& settings;
    const scene::Aabb& S;
    const scene::Camera& camera;
    float aspect;
    dvec3 l, v, eye;
    double gamma, phi;
    const SampleBounds* samples; // non-null: fitted to the samples (focus.mode = samples)
    int resolution;              // the first split's, after the memory budget
    double reachTexels;          // how far lookups reach past their sample (filter taps, normal offset)
};

/// The plan's values that do not depend on the splits: l, v, γ, the eye's matrices, the offsets.
ShadowPlan planFrame(const ShadowSettings& settings, const scene::Aabb& S, const scene::Camera& camera,
                     const scene::Light& light, const Viewport& viewport) {
    ShadowPlan plan;
    plan.light = light;
    plan.l = light.l();
    plan.v = camera.viewDir();
    plan.gammaDeg = scene::gammaDeg(plan.v, plan.l);
    plan.lightViewAngleDeg = scene::lightViewAngleDeg(plan.v, plan.l);
    plan.eyeView = camera.view();
    plan.eyeProj = camera.projection(viewport.aspect());
    const BiasType bias = settings.bias.type;
    plan.receiverOffset = bias == BiasType::Constant ? settings.bias.constant : 0.f;
    if (bias == BiasType::Slope || bias == BiasType::SlopeNormalOffset)
        plan.polygonOffset = {settings.bias.slope, settings.bias.units};
    if (bias == BiasType::NormalOffset || bias == BiasType::SlopeNormalOffset)
        plan.normalOffsetTexels = settings.bias.normalOffset;
    plan.settings = settings;
    plan.casterLodTexels = settings.casters.lod == CasterLod::Auto ? settings.casters.lodTexels : 0.f;
    plan.viewFrustum = frustumCorners(camera, viewport.aspect(), camera.near, camera.far);
    plan.sceneBounds = S;
    plan.eye = camera.eye;
    plan.cameraNear = camera.near;
    plan.cameraFar = camera.far;
    return plan;
}

/// The split boundaries c_0 = n … c_k = f; with samples, over the samples' depth range instead (a
/// sliver beyond it, so float noise cannot leave the nearest or farthest pixel out), and the
/// practical scheme blends the log split with the samples' quantiles.
std::vector<double> splitBoundaries(const SplitContext& k, ShadowPlan& plan) {
    const ShadowSettings& settings = k.settings;
    std::vector<double> c = splitDistances(settings.splits, k.camera.near, k.camera.far, k.gamma);
    if (!k.samples) return c;
    const SampleBounds& samples = *k.samples;
    plan.sampleCount = samples.count;
    plan.sampleDepthRange = {samples.zMin, samples.zMax};
    if (samples.empty()) return c;
    const double zLo = std::max(double(k.camera.near), samples.zMin * (1.0 - 1e-3));
    const double zHi = std::min(double(k.camera.far), std::max(samples.zMax * (1.0 + 1e-3), zLo * (1.0 + 1e-3)));
    c = splitDistances(settings.splits, zLo, zHi, k.gamma);
    if (settings.splits.scheme == SplitScheme::Practical && c.size() > 2) {
        SplitParams log = settings.splits;
        log.scheme = SplitScheme::Log;
        const std::vector<double> cLog = splitDistances(log, zLo, zHi, k.gamma);
        const std::vector<double> q = sampleQuantiles(samples, zLo, zHi, int(c.size()) - 1);
        if (q.size() + 2 == c.size())
            for (size_t i = 1; i + 1 < c.size(); ++i)
                c[i] = settings.splits.lambda * cLog[i] + (1.0 - settings.splits.lambda) * q[i - 1];
    }
    return c;
}

/// Split i's depth range, resolution, blend band and focus body B_i; returns the view sub-frustum B_i
/// was fitted to (it reaches back over the previous split's blend band).
std::array<glm::vec3, 8> focusSplit(const SplitContext& k, const std::vector<double>& c, int i, SplitPlan& split) {
    split.near = float(c[i]);
    split.far = float(c[i + 1]);
    split.resolution = splitResolution(k.settings.splits, k.resolution, i);
    split.frustum = frustumCorners(k.camera, k.aspect, split.near, split.far);
    // splits.blend: the last `blend` of this split's depth range fades into the next split, so
    // the next split's map must also cover that band: its focus starts the band's width early.
    const double blend = k.settings.splits.blend;
    const bool last = i + 2 >= int(c.size());
    split.blendStart = float(last ? c[i + 1] : c[i + 1] - blend * (c[i + 1] - c[i]));
    const double focusNear = i > 0 ? std::max(k.camera.near, float(c[i] - blend * (c[i] - c[i - 1]))) : c[i];
    const auto focusFrustum =
        focusNear < c[i] ? frustumCorners(k.camera, k.aspect, float(focusNear), split.far) : split.frustum;
    if (k.samples) {
        const SampleSlab slab =
            samplesWithin(*k.samples, focusNear, c[i + 1], k.reachTexels / std::max(split.resolution, 1));
        split.samples = slab.count;
        split.skipped = slab.count == 0;
        if (!split.skipped) {
            split.body = focusBody(focusFrustum, k.S, glm::vec3(k.l), slab.planes);
            split.sampleRegion.assign(split.body.begin(), split.body.begin() + std::ptrdiff_t(split.body.size() / 2));
        }
    } else if (c[i + 1] > c[i]) {
        split.body = focusBody(focusFrustum, k.S, glm::vec3(k.l));
    }
    return focusFrustum;
}

/// Split i's warp and map: V_P, n' (Barroso eqs 13–18 and the other methods, warp.h), stabilization,
/// and the matrices and depth ranges the passes need. `split.body` is not empty.
void frameSplit(const SplitContext& k, const std::vector<double>& c, int i,
                const std::array<glm::vec3, 8>& focusFrustum, SplitPlan& split) {
    const ShadowSettings& settings = k.settings;
    // warp.direction orients warped maps only (its row's `when`): an unwarped map keeps V_P.
    const WarpDirection direction =
        settingMatters(settings, "warp.direction") ? settings.direction : ShadowSettings{}.direction;
    dvec3 vp = warpDirection(direction, k.l, k.v, k.eye, split.body);
    const bool degenerate = glm::length(vp) == 0.0;
    if (degenerate) vp = perpendicular(k.l); // light ∥ view: any orientation, and no warp
    // d for the n' formulas is B's extent along V_P (LiSPSM); compute it before choosing n'.
    double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
    for (const auto& p : split.body) {
        const double t = glm::dot(dvec3(p), vp);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    // The warp's n' from the fitted range, except that the first split's n sits between the
    // camera's n and the nearest sample (n^(2/3)·z_min^(1/3)): the fitted z_min alone weakens
    // the warp too much where a few near samples see a long frustum (deck: p95 m 3.21 → 4.39),
    // the camera's n keeps it too strong for a far-off focus (overview); docs/performance.md
    // "How n' is computed for fitted splits" has the variants measured.
    const double n = k.camera.near;
    const double nI = k.samples && i == 0 ? std::cbrt(n * n * c[0]) : c[i], fI = c[i + 1];
    double nPrime = degenerate ? kUniform : warpNPrime(settings.warp, nI, fI, k.phi, k.gamma, hi - lo);
    const bool quantize = settings.stabilize == StabilizeMode::Quantize;
    if (quantize && !degenerate) { // V_P in 1° steps about l, n' in 1/16 octaves
        const dvec3 e1 = perpendicular(k.l), e2 = glm::cross(k.l, e1);
        const double angle = std::round(glm::degrees(std::atan2(glm::dot(vp, e2), glm::dot(vp, e1))));
        vp = std::cos(glm::radians(angle)) * e1 + std::sin(glm::radians(angle)) * e2;
        if (std::isfinite(nPrime) && nPrime > 0.0 && nPrime < kUniform)
            nPrime = std::exp2(std::round(std::log2(nPrime) * 16.0) / 16.0);
    }
    SplitFrame frame = frameForSplit(split.body, k.l, vp, k.eye, k.S, nPrime, {quantize, split.resolution});
    if (settings.stabilize != StabilizeMode::Off && frame.nPrime == kUniform)
        frame = stableFrame(focusFrustum, k.l, k.eye, k.S, split.resolution);
    const dmat4 viewProj = frame.lightProj * frame.lightView;
    split.lightView = glm::mat4(frame.lightView);
    split.lightProj = glm::mat4(frame.lightProj);
    split.lightViewProj = glm::mat4(viewProj);
    split.nPrime = frame.nPrime;
    split.lambda = lambdaFromNPrime(frame.nPrime, nI, fI, k.phi, k.gamma);
    split.warpDir = glm::vec3(vp);
    split.warpCentre = glm::vec3(frame.warpCentre);
    split.warpDepth = float(frame.d);
    split.bodyDepthRange = depthRangeInMap(viewProj, split.body);
    split.mapVolume = unitCubeInWorld(viewProj);
    split.linearDepthRange = linearDepthRange(split.body, k.l, k.S);
    dvec3 centre(0.0);
    for (const auto& p : split.body) centre += dvec3(p);
    centre /= double(split.body.size());
    const double step = std::max(1e-3 * frame.d, 1e-3);
    split.depthPerUnit =
        float(std::max(0.0, (depth01(viewProj, centre + step * k.l) - depth01(viewProj, centre)) / step));
}

/// What the passes derive from the whole plan, computed once here: linear depth and its scale, the
/// dual-depth cap in map units, the unwarped light view, and the snap warning.
void finishPlan(const ShadowSettings& settings, ShadowPlan& plan) {
    plan.linearDepth =
        settings.bias.linearZ || isMomentFilter(settings.filter.type) || settings.filter.type == FilterType::Pcss;
    for (auto& split : plan.splits) {
        split.linearDepthScale = 1.f / std::max(split.linearDepthRange.y - split.linearDepthRange.x, 1e-6f);
        split.dualDepthCap = settings.bias.zMax * (settings.bias.linearZ ? split.linearDepthScale : split.depthPerUnit);
    }
    plan.unwarpedViewProj = unwarpedView(plan);
    // Snap holds unwarped maps only (quantize holds warped ones): with every split warped it does nothing.
    const bool anyUniform = std::any_of(plan.splits.begin(), plan.splits.end(),
                                        [](const SplitPlan& sp) { return !sp.empty() && !sp.warped(); });
    if (settings.stabilize == StabilizeMode::Snap && !anyUniform && !plan.splits.empty())
        plan.warnings.push_back("stabilize.mode = snap has no effect: every split is warped (snap moves unwarped "
                                "maps in whole texels; quantize holds warped ones)");
}

/// How far lookups reach past the sample they are for (filter taps, normal offset), in texels: a
/// margin of that many texels keeps them on the map. A value that does not apply (a disk radius
/// under pcf) counts at its default, so that changing it moves no map (its row's `when`).
double lookupReachTexels(const ShadowSettings& settings) noexcept {
    static const ShadowSettings defaults{};
    const auto used = [&](std::string_view key, auto member) {
        return double(settingMatters(settings, key) ? member(settings) : member(defaults));
    };
    return int(used("filter.kernel", [](const ShadowSettings& s) { return s.filter.kernel; })) / 2 +
           used("filter.radius", [](const ShadowSettings& s) { return s.filter.radius; }) +
           used("bias.normal_offset", [](const ShadowSettings& s) { return s.bias.normalOffset; }) + 2.0;
}

/// technique = virtual: the settings the virtual map is drawn with. The fitted maps' own settings go
/// back to their defaults (the planner still frames a map from them, for the overlays and the light
/// view's frame, and they must not move it); the biases and filters a paged map cannot do become
/// the nearest it can, each with a warning saying why.
ShadowSettings settingsForVirtual(const ShadowSettings& asked, std::vector<std::string>& warnings) {
    static const ShadowSettings defaults{};
    ShadowSettings s = asked;
    for (const SettingInfo& info : settingsDeclaration())
        if (info.mapsOnly) info.set(s, info.get(defaults));
    if (s.bias.type == BiasType::Midpoint || s.bias.type == BiasType::DualDepth) {
        warnings.push_back("technique = virtual: bias.type = " + std::string(enumName(s.bias.type)) +
                           " needs a second depth layer of every page (twice the pool); drawn with constant");
        s.bias.type = BiasType::Constant;
    }
    if (isMomentFilter(s.filter.type) || s.filter.type == FilterType::Pcss) {
        warnings.push_back("technique = virtual: filter.type = " + std::string(enumName(s.filter.type)) +
                           (s.filter.type == FilterType::Pcss
                                ? " searches blockers over many texels of one level, which pages of several levels "
                                  "do not give"
                                : " blurs its moments across page borders, where the neighbour page may be of "
                                  "another level or absent") +
                           "; drawn with hw2x2");
        s.filter.type = FilterType::Hw2x2;
    }
    return s;
}

/// A spot or point light's plan (docs/design.md §3.10): its maps, what it does not apply, and the
/// values every plan derives.
ShadowPlan planPositional(const ShadowSettings& settings, const scene::Aabb& S, const scene::Camera& camera,
                          const scene::Light& light, const Viewport& viewport, ShadowPlan plan) {
    plan.casterLodTexels = 0.f;
    ShadowSettings maps = settings; // the budget counts the maps this light draws
    maps.splits.count = light.type == scene::LightType::Point ? kCubeFaces : 1;
    const int resolution = budgetedResolution(maps);
    if (resolution < settings.resolution)
        plan.warnings.push_back("shadow_map.resolution " + std::to_string(settings.resolution) + " x " +
                                std::to_string(maps.splits.count) + " maps is over the " +
                                std::to_string(int(kShadowMemoryBudgetBytes / (1 << 20))) +
                                " MiB shadow-memory budget: drawn at " + std::to_string(resolution));
    for (std::string& w : inertSettingWarnings(settings)) plan.warnings.push_back(std::move(w));
    for (std::string& w : positionalLightWarnings(settings, light)) plan.warnings.push_back(std::move(w));
    planPositionalSplits(S, camera, viewport.aspect(), light, resolution, lookupReachTexels(settings), plan);
    finishPlan(settings, plan);
    return plan;
}

} // namespace

ShadowPlan planShadows(const ShadowSettings& shared, const scene::Aabb& S, const scene::Camera& camera,
                       const scene::Light& light, const Viewport& viewport, const SampleBounds* samples) {
    // A light's own overrides (docs/design.md §3.10 "Settings per light"): its plan, and so its
    // passes and shader block, carry them.
    ShadowSettings own;
    if (!light.settings.empty()) {
        own = shared;
        for (const std::string& a : light.settings) applyAssignment(own, a);
    }
    const ShadowSettings& asked = light.settings.empty() ? shared : own;
    std::vector<std::string> virtualWarnings;
    const ShadowSettings virtualSettings = asked.technique == Technique::Virtual && !light.positional()
                                               ? settingsForVirtual(asked, virtualWarnings)
                                               : asked;
    const ShadowSettings& settings = asked.technique == Technique::Virtual ? virtualSettings : asked;
    ShadowPlan plan = planFrame(settings, S, camera, light, viewport);
    if (asked.technique == Technique::Virtual && light.positional())
        plan.warnings.push_back("technique = virtual takes a directional light: this " +
                                std::string(light.type == scene::LightType::Spot ? "spot" : "point") +
                                " light uses fitted maps");
    if (asked.technique == Technique::Virtual && !light.positional()) {
        plan.virtualMap = planVirtual(settings.virtualMap, S, camera.eye, plan.l);
        // Second depth draws back faces, the slope biases offset polygons: a page drawn otherwise is redrawn.
        plan.virtualMap.content ^=
            std::hash<std::string>{}(std::to_string(int(settings.bias.type)) + ' ' +
                                     std::to_string(plan.polygonOffset.x) + ' ' + std::to_string(plan.polygonOffset.y));
        for (std::string& w : virtualWarnings) plan.warnings.push_back(std::move(w));
    }
    if (light.positional()) return planPositional(settings, S, camera, light, viewport, std::move(plan));
    const bool fit = settings.focus == FocusMode::Samples && samples != nullptr;
    plan.fittedToSamples = fit;
    // Beyond the memory budget the maps are drawn smaller, and the plan says so (splits[i].resolution).
    const int resolution = budgetedResolution(settings);
    if (resolution < settings.resolution)
        plan.warnings.push_back("shadow_map.resolution " + std::to_string(settings.resolution) + " x " +
                                std::to_string(settings.splits.count) + " splits needs " +
                                std::to_string(int(shadowMapBytes(settings, settings.resolution) / (1 << 20))) +
                                " MiB, over the " + std::to_string(int(kShadowMemoryBudgetBytes / (1 << 20))) +
                                " MiB shadow-memory budget: drawn at " + std::to_string(resolution));
    for (std::string& w : inertSettingWarnings(asked)) plan.warnings.push_back(std::move(w));
    // Lookups reach past the sample they are for: filter taps, normal offset; a margin of that many
    // texels (as a fraction of the map) keeps them on the map.
    const double reachTexels = lookupReachTexels(settings);
    const SplitContext k{settings,
                         S,
                         camera,
                         viewport.aspect(),
                         dvec3(plan.l),
                         dvec3(plan.v),
                         dvec3(camera.eye),
                         glm::radians(double(plan.gammaDeg)),
                         glm::radians(double(camera.fovYDeg)) * 0.5,
                         fit ? samples : nullptr,
                         resolution,
                         reachTexels};
    const std::vector<double> c = splitBoundaries(k, plan);
    for (int i = 0; i + 1 < int(c.size()); ++i) {
        SplitPlan split;
        const auto focusFrustum = focusSplit(k, c, i, split);
        if (!split.empty()) frameSplit(k, c, i, focusFrustum, split);
        plan.splits.push_back(std::move(split));
    }
    finishPlan(settings, plan);
    return plan;
}

} // namespace geometry::shadow
