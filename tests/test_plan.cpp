// The full shadow plan: splits, focus bodies and warps together.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/shadow/focus.h"
#include "geometry/shadow/memory_budget.h"
#include "geometry/shadow/shadow_plan.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>

#include "random_util.h"

using namespace geometry::scene;
using namespace geometry::shadow;
using testutil::randomUnit;
using testutil::uniform;
using testutil::uniform01;

namespace {

bool finite(const glm::mat4& m) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m[i][j])) return false;
    return true;
}

bool insideUnitCube(const glm::mat4& m, const glm::vec3& p) { return testutil::insideUnitCube(m, p, 2e-4f); }

const WarpMethod kMethods[] = {WarpMethod::Uniform, WarpMethod::Psm,   WarpMethod::Lispsm,
                               WarpMethod::Glispsm, WarpMethod::Gmnpr, WarpMethod::Manual};

} // namespace

// Every point of V_i ∩ S and every point of S between it and the light lands in split i's unit
// cube, for every warp, both warp directions, 1–4 splits and every stabilization mode
// (docs/design.md §3.1, §3.2).
TEST(Plan, WarpedSplitsKeepReceiversAndCastersInTheirUnitCube) {
    std::mt19937 rng(99);
    Aabb S;
    S.add({-40, 0, -60});
    S.add({50, 25, 30});
    int checked = 0;
    for (int trial = 0; trial < 240; ++trial) {
        ShadowSettings settings;
        settings.warp.method = kMethods[trial % 6];
        settings.direction = (trial / 6) % 2 ? WarpDirection::Middle : WarpDirection::Standard;
        settings.splits.count = 1 + (trial / 12) % 4;
        settings.splits.scheme = SplitScheme((trial / 48) % 5);
        settings.stabilize = trial % 7 < 2   ? StabilizeMode::Snap
                             : trial % 7 < 4 ? StabilizeMode::Quantize
                                             : StabilizeMode::Off;
        Camera cam;
        cam.eye = {uniform(rng, -60, 60), uniform(rng, -5, 40), uniform(rng, -70, 40)};
        cam.target = cam.eye + randomUnit(rng);
        cam.fovYDeg = uniform(rng, 20, 90);
        cam.near = uniform(rng, 0.1f, 2.f);
        cam.far = uniform(rng, 30.f, 300.f);
        Light light{randomUnit(rng)};
        const Viewport vp{640, 480};
        const ShadowPlan plan = planShadows(settings, S, cam, light, vp);
        ASSERT_EQ(int(plan.splits.size()), settings.splits.count);
        for (const auto& split : plan.splits) {
            ASSERT_TRUE(finite(split.lightViewProj)) << "trial " << trial;
            ASSERT_TRUE(std::isfinite(split.lambda));
            if (split.empty()) continue;
            ASSERT_NEAR(glm::dot(split.warpDir, plan.l), 0.f, 1e-4f) << "V_P ⊥ l";
            const auto corners = frustumCorners(cam, vp.aspect(), split.near, split.far);
            for (int k = 0; k < 60; ++k) {
                const float u = uniform01(rng), v = uniform01(rng), w = uniform01(rng);
                glm::vec3 p(0.f);
                for (int c = 0; c < 8; ++c)
                    p += corners[c] * (((c & 1) ? u : 1 - u) * ((c & 2) ? v : 1 - v) * ((c & 4) ? w : 1 - w));
                if (!S.contains(p)) continue;
                const glm::vec3 exit = exitTowardLight(p, plan.l, S);
                EXPECT_TRUE(insideUnitCube(split.lightViewProj, p))
                    << "receiver, trial " << trial << " " << warpMethodName(settings.warp.method);
                EXPECT_TRUE(insideUnitCube(split.lightViewProj, p + uniform01(rng) * (exit - p)))
                    << "caster, trial " << trial << " " << warpMethodName(settings.warp.method);
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 4000);
}

TEST(Plan, SplitsAreContiguousAndFollowTheScheme) {
    const Scene scene = makePlaneScene();
    ShadowSettings s;
    s.splits.count = 3;
    s.splits.scheme = SplitScheme::Log;
    const ShadowPlan plan = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], {640, 480});
    ASSERT_EQ(plan.splits.size(), 3u);
    EXPECT_FLOAT_EQ(plan.splits[0].near, scene.camera.near);
    EXPECT_FLOAT_EQ(plan.splits[2].far, scene.camera.far);
    for (int i = 1; i < 3; ++i) EXPECT_FLOAT_EQ(plan.splits[i].near, plan.splits[i - 1].far);
    EXPECT_NEAR(plan.splits[0].far, 0.5 * std::pow(200.0, 1.0 / 3.0), 1e-4);
}

// With the light exactly parallel or anti-parallel to the view, every method falls back to
// uniform and the plan stays finite.
TEST(Plan, DuelingFrustaFallBackToUniform) {
    const Scene scene = makePlaneScene();
    for (auto method : kMethods)
        for (float sign : {1.f, -1.f}) {
            ShadowSettings s;
            s.warp.method = method;
            s.splits.count = 2;
            Light light{sign * scene.camera.viewDir()};
            const ShadowPlan plan = planShadows(s, scene.bounds(), scene.camera, light, {320, 240});
            EXPECT_NEAR(plan.gammaDeg, 0.f, 0.05f);
            for (const auto& split : plan.splits) {
                EXPECT_FALSE(split.warped()) << warpMethodName(method);
                EXPECT_TRUE(finite(split.lightViewProj));
            }
        }
}

// LiSPSM gives receivers near the eye more of the map than uniform does (the point of warping).
TEST(Plan, LispsmGivesNearReceiversMoreTexels) {
    const Scene scene = makePlaneScene();
    const auto texelsAcross = [&](WarpMethod method, float viewDistance) {
        ShadowSettings s;
        s.warp.method = method;
        const ShadowPlan plan = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], {640, 480});
        const glm::vec3 p = scene.camera.eye + scene.camera.viewDir() * viewDistance;
        const glm::vec3 ground(p.x, 0.f, p.z);
        const auto uv = [&](glm::vec3 q) {
            const glm::vec4 c = plan.splits[0].lightViewProj * glm::vec4(q, 1.f);
            return glm::vec2(c) / c.w * 0.5f * float(s.resolution);
        };
        // Texels covered by a 1 m step along the ground, both ground axes.
        return glm::length(uv(ground + glm::vec3(1, 0, 0)) - uv(ground)) +
               glm::length(uv(ground + glm::vec3(0, 0, 1)) - uv(ground));
    };
    EXPECT_GT(texelsAcross(WarpMethod::Lispsm, 9.f), 2.f * texelsAcross(WarpMethod::Uniform, 9.f));
}

TEST(Plan, EmptyWhenTheViewMissesTheScene) {
    Aabb S;
    S.add({100, 100, 100});
    S.add({110, 110, 110});
    Camera cam;
    cam.eye = {0, 0, 0};
    cam.target = {0, 0, -1};
    for (auto method : kMethods) {
        ShadowSettings s;
        s.warp.method = method;
        s.splits.count = 4;
        const ShadowPlan plan = planShadows(s, S, cam, Light{}, {320, 240});
        for (const auto& split : plan.splits) {
            EXPECT_TRUE(split.empty());
            EXPECT_TRUE(finite(split.lightViewProj));
        }
    }
}

// The plan says which biases the renderer applies: a polygon offset for the slope types, a normal
// offset for the normal types, both for slope_normal_offset, a receiver offset for constant only.
TEST(Plan, BiasTypesBecomeTheOffsetsTheRendererApplies) {
    const Scene scene = makePlaneScene();
    ShadowSettings s;
    s.bias.constant = 0.07f;
    s.bias.slope = 2.f;
    s.bias.units = 3.f;
    s.bias.normalOffset = 1.5f;
    const auto plan = [&](BiasType type) {
        s.bias.type = type;
        return planShadows(s, scene.bounds(), scene.camera, scene.lights[0], {320, 240});
    };
    const ShadowPlan constant = plan(BiasType::Constant), slope = plan(BiasType::Slope),
                     normal = plan(BiasType::NormalOffset), both = plan(BiasType::SlopeNormalOffset);
    EXPECT_EQ(constant.receiverOffset, 0.07f);
    EXPECT_EQ(constant.polygonOffset, glm::vec2(0.f));
    EXPECT_EQ(constant.normalOffsetTexels, 0.f);
    EXPECT_EQ(slope.polygonOffset, glm::vec2(2.f, 3.f));
    EXPECT_EQ(slope.normalOffsetTexels, 0.f);
    EXPECT_EQ(normal.polygonOffset, glm::vec2(0.f));
    EXPECT_EQ(normal.normalOffsetTexels, 1.5f);
    EXPECT_EQ(both.polygonOffset, glm::vec2(2.f, 3.f));
    EXPECT_EQ(both.normalOffsetTexels, 1.5f);
    EXPECT_EQ(both.receiverOffset, 0.f);
}

namespace {

/// Where a world point lands in split 0's map, in texels.
glm::dvec3 texelOf(const ShadowPlan& plan, const glm::vec3& p, int res) {
    const glm::dvec4 c = glm::dmat4(plan.splits[0].lightViewProj) * glm::dvec4(glm::dvec3(p), 1.0);
    return {(c.x / c.w * 0.5 + 0.5) * res, (c.y / c.w * 0.5 + 0.5) * res, c.z / c.w};
}

} // namespace

// stabilize.mode = snap: a camera that moves by a fraction of a texel, or turns, leaves the uniform
// map's texel grid where it was in the world (whole-texel shifts only, same scale, same depth);
// without snap the grid slides by fractions of a texel.
TEST(Plan, SnapHoldsTheUniformMapsTexelGridStill) {
    const Scene scene = makePlaneScene();
    ShadowSettings s;
    s.resolution = 1024;
    s.splits.count = 3;
    const Viewport vp{320, 240};
    const std::vector<glm::vec3> probes{{0, 0, 0}, {5, 0, -3}, {-7, 2, 4}, {12, 0, 9}};
    const auto shifts = [&](const Camera& a, const Camera& b) {
        const ShadowPlan pa = planShadows(s, scene.bounds(), a, scene.lights[0], vp);
        const ShadowPlan pb = planShadows(s, scene.bounds(), b, scene.lights[0], vp);
        std::vector<glm::dvec3> out;
        for (const auto& p : probes) out.push_back(texelOf(pb, p, s.resolution) - texelOf(pa, p, s.resolution));
        return out;
    };
    Camera moved = scene.camera;
    moved.eye += glm::vec3(0.013f, 0.004f, -0.021f); // a fraction of a 2–3 cm texel
    moved.target += glm::vec3(0.013f, 0.004f, -0.021f);
    Camera turned = scene.camera;
    turned.target = glm::vec3(glm::rotate(glm::mat4(1.f), glm::radians(3.f), glm::vec3(0, 1, 0)) *
                              glm::vec4(turned.target - turned.eye, 0.f)) +
                    turned.eye;
    s.stabilize = StabilizeMode::Snap;
    for (const Camera& other : {moved, turned}) {
        const auto d = shifts(scene.camera, other);
        for (const auto& v : d) {
            EXPECT_NEAR(v.x, std::round(v.x), 1e-3) << "whole texels";
            EXPECT_NEAR(v.y, std::round(v.y), 1e-3);
            EXPECT_NEAR(v.x, d[0].x, 1e-3) << "one shift for every point: same scale";
            EXPECT_NEAR(v.y, d[0].y, 1e-3);
            EXPECT_NEAR(v.z, 0.0, 1e-6) << "depth does not move";
        }
    }
    s.stabilize = StabilizeMode::Off;
    double fraction = 0;
    for (const auto& v : shifts(scene.camera, moved)) fraction = std::max(fraction, std::abs(v.x - std::round(v.x)));
    EXPECT_GT(fraction, 0.01) << "unsnapped, the grid slides by fractions of a texel";
    // Warped splits are left alone by snap (their frame follows the warp).
    s.warp.method = WarpMethod::Lispsm;
    const ShadowPlan off = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], vp);
    s.stabilize = StabilizeMode::Snap;
    const ShadowPlan on = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], vp);
    for (size_t i = 0; i < on.splits.size(); ++i) {
        if (!on.splits[i].warped()) continue;
        EXPECT_EQ(on.splits[i].lightViewProj, off.splits[i].lightViewProj) << i;
    }
}

// stabilize.mode = quantize: a warped split's frame (V_P, n', projection centre, extent) is held to
// steps, so a camera move far below a step leaves it exactly as it was; without it the warp drifts.
TEST(Plan, QuantizeHoldsAWarpedFrameForSmallMoves) {
    const Scene scene = makePlaneScene();
    ShadowSettings s;
    s.resolution = 1024;
    s.warp.method = WarpMethod::Lispsm;
    const Viewport vp{320, 240};
    Camera moved = scene.camera;
    moved.eye += glm::vec3(2e-4f, 0.f, -1e-4f);
    moved.target += glm::vec3(2e-4f, 0.f, -1e-4f);
    const auto same = [&](StabilizeMode mode) {
        s.stabilize = mode;
        const ShadowPlan a = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], vp);
        const ShadowPlan b = planShadows(s, scene.bounds(), moved, scene.lights[0], vp);
        EXPECT_TRUE(a.splits[0].warped());
        return a.splits[0].lightViewProj == b.splits[0].lightViewProj;
    };
    EXPECT_TRUE(same(StabilizeMode::Quantize));
    EXPECT_FALSE(same(StabilizeMode::Off));
}

// The memory budget is the plan's: beyond it the maps are planned smaller, splits[i].resolution
// says what is drawn and a warning says why; half the resolution (tune's screening) follows the
// same rule. Settings without effect and snap with warped splits are warned about.
TEST(Plan, MapsBeyondTheMemoryBudgetArePlannedSmallerWithAWarning) {
    const Scene scene = makePlaneScene();
    ShadowSettings s;
    s.splits.count = 8;
    s.splits.scheme = SplitScheme::Log;
    s.resolution = 8192; // 8 × 8192² × 4 B = 2 GiB
    const auto plan = [&](const ShadowSettings& x) {
        return planShadows(x, scene.bounds(), scene.camera, scene.lights[0], {320, 240});
    };
    const ShadowPlan big = plan(s);
    ASSERT_EQ(big.splits.size(), 8u);
    for (const SplitPlan& sp : big.splits) EXPECT_EQ(sp.resolution, 4096);
    ASSERT_FALSE(big.warnings.empty());
    EXPECT_NE(big.warnings.front().find("1536 MiB"), std::string::npos) << big.warnings.front();
    EXPECT_NE(big.warnings.front().find("drawn at 4096"), std::string::npos) << big.warnings.front();
    EXPECT_EQ(budgetedResolution(s), 4096);
    ShadowSettings moments = s;
    moments.splits.count = 4;
    moments.resolution = 4096;
    moments.filter.type = FilterType::Evsm4; // 36 B per texel: 2.25 GiB
    EXPECT_EQ(budgetedResolution(moments), 2048);
    moments.resolution = 2048; // the screening size of 4096 fits as it is
    EXPECT_EQ(budgetedResolution(moments), 2048);
    s.resolution = 2048;
    EXPECT_TRUE(plan(s).warnings.empty());

    ShadowSettings inert;
    inert.bias.type = BiasType::Slope;
    inert.bias.constant = 0.3f;
    const ShadowPlan p = plan(inert);
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_EQ(p.warnings[0], "bias.constant = 0.3 has no effect (bias.type = slope)");
    ShadowSettings snap;
    snap.warp.method = WarpMethod::Lispsm;
    snap.stabilize = StabilizeMode::Snap;
    const ShadowPlan snapped = plan(snap);
    ASSERT_EQ(snapped.warnings.size(), 1u);
    EXPECT_NE(snapped.warnings[0].find("stabilize.mode = snap has no effect"), std::string::npos);
    snap.warp.method = WarpMethod::Uniform;
    EXPECT_TRUE(plan(snap).warnings.empty());
}
