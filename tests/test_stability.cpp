// Pure stability helpers: the light turned to a chosen light-view angle, path interpolation,
// and the flicker and seam measures (geometry/scene/light_angle.h, path_interpolation.h,
// stability_metrics.h).
#include "geometry/analysis/caster_coverage.h"
#include "geometry/analysis/stability_metrics.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/light_angle.h"
#include "geometry/scene/path_interpolation.h"

#include "random_util.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::analysis;

TEST(LightAngle, KnownAngles) {
    const glm::vec3 v = glm::normalize(glm::vec3(1, -0.2f, -0.5f));
    const glm::vec3 ref(-0.5f, -1.f, -0.3f);
    const glm::vec3 l0 = lightAtViewAngle(v, ref, 0.f), l180 = lightAtViewAngle(v, ref, 180.f);
    EXPECT_NEAR(glm::length(l0 - v), 0.f, 1e-6f) << "0 degrees: light from behind the eye along the view";
    EXPECT_NEAR(glm::length(l180 + v), 0.f, 1e-6f) << "180 degrees: light facing the camera";
    const glm::vec3 l90 = lightAtViewAngle(v, ref, 90.f);
    EXPECT_NEAR(glm::dot(l90, v), 0.f, 1e-6f);
    // On the reference's side of v, in the plane of v and the reference.
    EXPECT_GT(glm::dot(l90, ref - glm::dot(ref, v) * v), 0.f);
    EXPECT_NEAR(glm::dot(glm::cross(v, ref), l90), 0.f, 1e-6f);
}

TEST(LightAngle, RoundTripsThroughViewAngleEverywhere) {
    std::mt19937 rng(7);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 v = testutil::randomUnit(rng), ref = testutil::randomUnit(rng);
        const float angle = testutil::uniform(rng, 0.f, 180.f);
        const glm::vec3 l = lightAtViewAngle(v, ref, angle);
        ASSERT_NEAR(glm::length(l), 1.f, 1e-5f);
        ASSERT_NEAR(lightViewAngleDeg(v, l), angle, 0.05f) << "angle " << angle;
        ASSERT_NEAR(gammaDeg(v, l), std::min(angle, 180.f - angle), 0.05f);
    }
}

TEST(LightAngle, KeepsTheLightWhereItWasAroundTheViewAxis) {
    // The current light's own angle gives the current light back.
    const glm::vec3 v = glm::normalize(glm::vec3(38.5f, -4.2f, -10.5f));
    const glm::vec3 ref = glm::normalize(glm::vec3(-0.55f, -0.75f, -0.35f));
    const glm::vec3 l = lightAtViewAngle(v, ref, lightViewAngleDeg(v, ref));
    EXPECT_NEAR(glm::length(l - ref), 0.f, 1e-5f);
}

TEST(LightAngle, ParallelOrBadReferenceUsesWorldDownThenWorldX) {
    const glm::vec3 v(1, 0, 0);
    for (const glm::vec3 ref : {v, -v, glm::vec3(0.f), glm::vec3(NAN, 0, 0), glm::vec3(INFINITY, 1, 0)}) {
        const glm::vec3 l = lightAtViewAngle(v, ref, 90.f);
        EXPECT_NEAR(glm::length(l - glm::vec3(0, -1, 0)), 0.f, 1e-6f) << "down: the sun shines from above";
    }
    // v vertical: down is parallel to it, so world −x.
    const glm::vec3 l = lightAtViewAngle({0, -1, 0}, {0, -1, 0}, 90.f);
    EXPECT_NEAR(glm::length(l - glm::vec3(-1, 0, 0)), 0.f, 1e-6f);
    // Stable: a reference a hair off the axis does not swing the result around.
    EXPECT_TRUE(finite(lightAtViewAngle(v, v + glm::vec3(0, 1e-9f, 0), 45.f)));
}

TEST(LightAngle, NaNSafe) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NEAR(glm::length(lightAtViewAngle({0, 0, -1}, {0, -1, 0}, nan) - glm::vec3(0, 0, -1)), 0.f, 1e-6f);
    EXPECT_TRUE(finite(lightAtViewAngle(glm::vec3(nan), glm::vec3(nan), 30.f)));
    EXPECT_TRUE(finite(lightAtViewAngle(glm::vec3(0.f), glm::vec3(0.f), 30.f)));
    EXPECT_NEAR(lightViewAngleDeg(glm::vec3(0.f, 0.f, -1.f), lightAtViewAngle(glm::vec3(0.f), {0, -1, 0}, 30.f)), 30.f,
                1e-3f)
        << "a zero v counts as (0, 0, -1)";
    // Out of range angles clamp.
    EXPECT_NEAR(lightViewAngleDeg({1, 0, 0}, lightAtViewAngle({1, 0, 0}, {0, -1, 0}, 400.f)), 180.f, 1e-3f);
    EXPECT_NEAR(lightViewAngleDeg({1, 0, 0}, lightAtViewAngle({1, 0, 0}, {0, -1, 0}, -5.f)), 0.f, 1e-3f);
    EXPECT_EQ(lightViewAngleDeg(glm::vec3(nan), {0, -1, 0}), 0.f);
    EXPECT_EQ(lightViewAngleDeg({0, 0, 0}, {0, -1, 0}), 0.f);
}

TEST(PathInterpolation, ParameterCoversThePath) {
    EXPECT_EQ(pathParameter(0, 1), 0.0);
    EXPECT_EQ(pathParameter(0, 5), 0.0);
    EXPECT_EQ(pathParameter(4, 5), 1.0);
    EXPECT_DOUBLE_EQ(pathParameter(2, 5), 0.5);
}

TEST(PathInterpolation, CameraBetweenKeys) {
    Camera a, b, c;
    a.eye = {0, 0, 0}, a.target = {0, 0, -1}, a.near = 1, a.far = 100;
    b.eye = {10, 0, 0}, b.target = {10, 0, -1}, b.near = 4, b.far = 400;
    c.eye = {10, 10, 0}, c.target = {10, 10, -1}, c.near = 4, c.far = 400;
    const std::vector<Camera> keys{a, b, c};
    EXPECT_EQ(cameraAlongPath(keys, 0).eye, a.eye);
    EXPECT_EQ(cameraAlongPath(keys, 1).eye, c.eye);
    const Camera q = cameraAlongPath(keys, 0.25); // halfway from a to b
    EXPECT_NEAR(q.eye.x, 5.f, 1e-5f);
    EXPECT_NEAR(q.near, 2.f, 1e-5f) << "geometric: √(1·4)";
    EXPECT_NEAR(q.far, 200.f, 1e-3f);
    EXPECT_NEAR(cameraAlongPath(keys, 0.75).eye.y, 5.f, 1e-5f);
    EXPECT_EQ(cameraAlongPath(keys, std::nan("")).eye, a.eye);
    EXPECT_EQ(cameraAlongPath(keys, 7.0).eye, c.eye);
    EXPECT_EQ(cameraAlongPath({b}, 0.3).eye, b.eye);
}

TEST(PathInterpolation, LightTurnsAtAConstantRate) {
    const std::vector<glm::vec3> keys{{1, 0, 0}, {0, -2, 0}, {-1, 0, 0}};
    for (int i = 0; i <= 8; ++i) {
        const glm::vec3 l = lightAlongPath(keys, i / 8.0);
        EXPECT_NEAR(glm::length(l), 1.f, 1e-6f);
        EXPECT_NEAR(lightViewAngleDeg({1, 0, 0}, l), 180.f * i / 8.f, 1e-3f) << i;
    }
    // Opposite keys still give a finite path (through world down).
    const glm::vec3 mid = lightAlongPath({{1, 0, 0}, {-1, 0, 0}}, 0.5);
    EXPECT_NEAR(glm::length(mid - glm::vec3(0, -1, 0)), 0.f, 1e-5f);
    EXPECT_EQ(lightAlongPath({}, 0.5), glm::vec3(0, -1, 0));
    EXPECT_EQ(lightAlongPath({{0, 0, 0}}, 0.5), glm::vec3(0, -1, 0));
}

// A path moves one light: its position linearly between keys, its direction as lightAlongPath; what
// has no keys (and every other member) stays.
TEST(PathInterpolation, ALightsPositionMovesLinearlyAndTheRestStays) {
    EXPECT_EQ(positionAlongPath({{0, 0, 0}, {4, 8, 0}, {4, 8, 4}}, 0.25), glm::vec3(2, 4, 0));
    EXPECT_EQ(positionAlongPath({{0, 0, 0}, {4, 8, 0}, {4, 8, 4}}, 0.75), glm::vec3(4, 8, 2));
    EXPECT_EQ(positionAlongPath({{1, 2, 3}}, 0.9), glm::vec3(1, 2, 3));
    EXPECT_EQ(positionAlongPath({{0, 0, 0}, {4, 0, 0}}, std::nan("")), glm::vec3(0, 0, 0));
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1, 2, 3};
    spot.direction = {0, -1, 0};
    spot.coneDeg = 40.f;
    const Light moved = lightAlongPath(spot, {{}, {{0, 5, 0}, {10, 5, 0}}}, 0.5);
    EXPECT_EQ(moved.position, glm::vec3(5, 5, 0));
    EXPECT_EQ(moved.direction, spot.direction);
    EXPECT_EQ(moved.coneDeg, 40.f);
    const Light turned = lightAlongPath(spot, {{{1, 0, 0}}, {}}, 0.5);
    EXPECT_EQ(turned.position, spot.position);
    EXPECT_EQ(turned.direction, glm::vec3(1, 0, 0));
}

TEST(FlickerStats, CountsFlipsWhereTruthStays) {
    // Pixels: 0 stable lit, stays lit · 1 stable lit, flips (flicker) · 2 truth moves (ignored)
    // 3 not a receiver in the second frame (ignored) · 4 stable shadowed, flips · 5 NaN s (ignored)
    const std::vector<float> s0{1, 1, 1, 1, 0.2f, NAN}, s1{0.9f, 0.1f, 0.f, 0.f, 0.7f, 1};
    const std::vector<uint8_t> o0{0, 0, 0, 0, 1, 0}, o1{0, 0, 1, 0, 1, 0};
    const std::vector<uint8_t> r0{1, 1, 1, 1, 1, 1}, r1{1, 1, 1, 0, 1, 1};
    const FlickerStats f = flickerStats(s0, o0, r0, s1, o1, r1);
    EXPECT_EQ(f.stable, 3u);
    EXPECT_EQ(f.flips, 2u);
    EXPECT_DOUBLE_EQ(f.rate, 2.0 / 3.0);
    // Threshold at 0.5 exactly: 0.5 counts as lit, like truthStats.
    const FlickerStats g = flickerStats(std::vector<float>{0.5f}, std::vector<uint8_t>{0}, std::vector<uint8_t>{1},
                                        std::vector<float>{0.49f}, std::vector<uint8_t>{0}, std::vector<uint8_t>{1});
    EXPECT_EQ(g.flips, 1u);
    const FlickerStats none = flickerStats({}, {}, {}, {}, {}, {});
    EXPECT_EQ(none.rate, 0.0);
    EXPECT_THROW((void)flickerStats(s0, o0, r0, s1, o1, std::vector<uint8_t>{1}), std::invalid_argument);
}

namespace {

/// An 8×3 image of the ground plane seen from (0, 10, 0): m grows by e^k per pixel along x, and
/// jumps by `step` from x = 3 (split 0) to x = 4 (split 1).
struct SeamImage {
    static constexpr int w = 8, h = 3;
    std::vector<float> m = std::vector<float>(w * h);
    std::vector<glm::vec4> aux = std::vector<glm::vec4>(w * h, glm::vec4(0.f));
    std::vector<uint8_t> receiver = std::vector<uint8_t>(w * h, 1);
    std::vector<glm::vec3> positions = std::vector<glm::vec3>(w * h);
    std::vector<glm::vec3> normals = std::vector<glm::vec3>(w * h, glm::vec3(0.f, 1.f, 0.f));
    glm::vec3 eye{0.f, 10.f, 0.f};
    SeamImage(float k, float step) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int i = y * w + x;
                m[i] = std::exp(k * float(x)) * (x >= 4 ? step : 1.f);
                aux[i].z = x >= 4 ? 1.f : 0.f;
                positions[i] = {float(x), 0.f, float(y)};
            }
    }
    SeamStats stats() const { return seamStats(m, aux, receiver, positions, normals, eye, w, h); }
};

} // namespace

TEST(SeamStats, StepAcrossTheBoundaryBeyondTheLocalSlope) {
    const SeamStats s = SeamImage(0.2f, 3.f).stats();
    EXPECT_EQ(s.pairs, 3u) << "one crossing per row; columns are too short for four pixels";
    EXPECT_NEAR(s.median, 3.0, 1e-5) << "the gradient e^0.2 per pixel is not a seam";
    EXPECT_NEAR(s.p95, 3.0, 1e-5);
    EXPECT_NEAR(s.rawMedian, 3.0 * std::exp(0.2), 1e-4) << "the raw neighbour ratio includes it";
    EXPECT_EQ(s.baselinePairs, 6u) << "x = 0..3 and 4..7 in each row";
    EXPECT_NEAR(s.baselineMedian, 1.0, 1e-6);
    // A step downwards is the same seam.
    EXPECT_NEAR(SeamImage(-0.1f, 1.f / 3.f).stats().median, 3.0, 1e-4);
    // No step: no seam, whatever the gradient.
    EXPECT_NEAR(SeamImage(0.5f, 1.f).stats().median, 1.0, 1e-5);
}

TEST(SeamStats, OnlyPixelsOnOneSurfaceCount) {
    SeamImage img(0.f, 4.f);
    img.positions[4].y = -40.f;           // row 0: b is the sea seen through a grating hole
    img.normals[8 + 5] = {1.f, 0.f, 0.f}; // row 1: e is on a wall
    img.receiver[16 + 2] = 0;             // row 2: c is no receiver
    SeamStats s = img.stats();
    EXPECT_EQ(s.pairs, 0u);
    EXPECT_EQ(s.median, 0.0);
    img = SeamImage(0.f, 4.f);
    img.aux[3].z = -1.f; // sky
    img.m[8 + 3] = NAN;
    img.m[16 + 4] = 0.f;
    EXPECT_EQ(img.stats().pairs, 0u);
    img = SeamImage(0.f, 4.f);
    img.m[3] = 1e10f; // the eye shader's cap for a singular J
    EXPECT_EQ(img.stats().pairs, 2u);
    EXPECT_THROW((void)seamStats(img.m, img.aux, img.receiver, img.positions, img.normals, img.eye, 3, 2),
                 std::invalid_argument);
    EXPECT_THROW((void)seamStats(img.m, img.aux, img.receiver, img.positions, img.normals, img.eye, -8, -3),
                 std::invalid_argument);
}

TEST(SeamStats, RandomImagesGiveSeamsAtLeastOne) {
    std::mt19937 rng(3);
    const int w = 16, h = 9;
    std::vector<float> m(w * h);
    std::vector<glm::vec4> aux(w * h);
    std::vector<glm::vec3> positions(w * h), normals(w * h, glm::vec3(0, 0, 1));
    for (int i = 0; i < w * h; ++i) {
        m[i] = testutil::uniform(rng, 0.01f, 100.f);
        aux[i].z = float((i % w) / 4);
        positions[i] = {float(i % w), float(i / w), 0.f};
    }
    const std::vector<uint8_t> r(w * h, 1);
    const SeamStats s = seamStats(m, aux, r, positions, normals, {0, 0, 20}, w, h);
    EXPECT_EQ(s.pairs, size_t(3 * h));
    EXPECT_GE(s.median, 1.0);
    EXPECT_GE(s.p95, s.median);
    EXPECT_GE(s.rawMedian, 1.0);
    EXPECT_GE(s.baselineMedian, 1.0);
}

namespace {

/// Ground points of the plane scene that the camera sees, with the split the eye pass would pick.
struct GroundView {
    Scene scene = makePlaneScene();
    ShadowPlan plan;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec4> aux;
    explicit GroundView(WarpMethod method) {
        ShadowSettings s;
        s.warp.method = method;
        s.splits.count = 3;
        plan = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], {160, 120});
        const glm::mat4 viewProj = plan.eyeProj * plan.eyeView;
        for (float x = -39.5f; x < 40.f; x += 1.f)
            for (float z = -39.5f; z < 40.f; z += 1.f) {
                const glm::vec3 p(x, 0.f, z);
                const glm::vec4 c = viewProj * glm::vec4(p, 1.f);
                if (!(c.w > 0.f) || std::abs(c.x) > c.w || std::abs(c.y) > c.w || std::abs(c.z) > c.w) continue;
                const float depth = glm::dot(p - plan.eye, plan.v);
                int split = 0;
                while (split + 1 < int(plan.splits.size()) && depth > plan.splits[split].far) ++split;
                positions.push_back(p);
                aux.push_back({0.f, 0.f, float(split), 0.f});
            }
    }
};

} // namespace

TEST(CasterCoverage, ACorrectPlanKeepsEveryCasterPathInsideTheMap) {
    for (const WarpMethod m : {WarpMethod::Uniform, WarpMethod::Lispsm, WarpMethod::Glispsm, WarpMethod::Psm}) {
        const GroundView g(m);
        ASSERT_GT(g.positions.size(), 500u);
        const std::vector<uint8_t> receiver(g.positions.size(), 1);
        const CasterCoverage c = casterCoverage(g.plan, g.positions, g.aux, receiver);
        EXPECT_EQ(c.count, g.positions.size());
        EXPECT_EQ(c.clippedCount, 0u) << warpMethodName(m);
        EXPECT_EQ(c.falseLitClipped, 0.0);
    }
}

TEST(CasterCoverage, AMapThatMissesCastersIsCaught) {
    GroundView g(WarpMethod::Glispsm);
    const size_t n = g.positions.size();
    std::vector<uint8_t> receiver(n, 1), occluded(n, 1);
    std::vector<float> lit(n, 1.f);
    // A light frustum half as wide (map coordinates doubled) drops the outer casters.
    for (auto& split : g.plan.splits)
        split.lightViewProj =
            glm::mat4(glm::vec4(2, 0, 0, 0), glm::vec4(0, 2, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 0, 1)) *
            split.lightViewProj;
    CasterCoverage c = casterCoverage(g.plan, g.positions, g.aux, receiver, occluded, lit);
    EXPECT_GT(c.clipped, 0.2);
    EXPECT_EQ(c.falseLitClipped, c.clipped) << "all truth-shadowed and rendered lit";
    // Rendered shadowed, or lit by the truth: not a false-lit pixel.
    std::fill(lit.begin(), lit.end(), 0.f);
    EXPECT_EQ(casterCoverage(g.plan, g.positions, g.aux, receiver, occluded, lit).falseLitClippedCount, 0u);
    // Casters above the map's near side (towards the light) are lost as well.
    g = GroundView(WarpMethod::Uniform);
    for (auto& split : g.plan.splits)
        split.lightViewProj =
            glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, -1.2f, 1)) *
            split.lightViewProj; // z − 1.2·w: the near side moves in
    receiver.assign(g.positions.size(), 1);
    EXPECT_GT(casterCoverage(g.plan, g.positions, g.aux, receiver).clipped, 0.2);
    // Sky, non-receivers and bad positions are not counted; sizes must agree.
    g.aux[0].z = -1.f;
    receiver[1] = 0;
    g.positions[2] = glm::vec3(NAN);
    EXPECT_EQ(casterCoverage(g.plan, g.positions, g.aux, receiver).count, g.positions.size() - 3);
    EXPECT_THROW((void)casterCoverage(g.plan, g.positions, g.aux, std::vector<uint8_t>{1}), std::invalid_argument);
    EXPECT_THROW((void)casterCoverage(g.plan, g.positions, g.aux, receiver, occluded, std::vector<float>{}),
                 std::invalid_argument);
}

// World-space flicker follows the point: a camera that pans by exactly one pixel sees the same
// states one pixel over, which screen-space flicker counts along every edge and the world-space
// measure does not; a state that changes at a point (inside a region) counts.
TEST(Flicker, WorldSpaceFollowsThePointNotThePixel) {
    constexpr int W = 40, H = 30;
    const glm::mat4 proj = glm::ortho(0.f, float(W), 0.f, float(H), -10.f, 10.f);
    // An orthographic eye over the plane z = 0 (pixel (x, y) sees the world point (x + 0.5, H − y − 0.5)),
    // w = 1 everywhere: the view depth test compares the same values.
    const auto frame = [&](float shiftX, float edgeX) {
        Inspection in;
        in.width = W;
        in.height = H;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const glm::vec3 p(float(x) + 0.5f + shiftX, float(H - y) - 0.5f, 0.f);
                in.positions.push_back(p);
                in.shadow.push_back(p.x < edgeX ? 0.f : 1.f);
                in.receiver.push_back(1);
            }
        return in;
    };
    const Inspection before = frame(0.f, 20.f), after = frame(1.f, 20.f);
    const FlickerStats screen = flickerStats(before.shadow, std::vector<uint8_t>(W * H, 0), before.receiver,
                                             after.shadow, std::vector<uint8_t>(W * H, 0), after.receiver);
    EXPECT_GT(screen.flips, 0u) << "the edge slides one pixel across the screen";
    const FlickerStats world = worldFlickerStats(before, proj, after);
    EXPECT_EQ(world.flips, 0u) << "every point keeps its state";
    EXPECT_GT(world.stable, size_t(W * H / 2));
    // The edge itself moving by 5 world units flips the points it passes, inside both regions.
    const FlickerStats moved = worldFlickerStats(before, proj, frame(1.f, 25.f));
    EXPECT_GE(moved.flips, size_t(3 * H));
    Inspection bad = frame(0.f, 20.f);
    bad.shadow.pop_back();
    EXPECT_THROW((void)worldFlickerStats(bad, proj, after), std::invalid_argument);
}
