// focus.mode = samples in the planner (docs/design.md §3.7): the depth bins, the conservative prism
// they give, and plans fitted to samples: every sample and every caster between it and the light
// stays in its split's map, the fitted focus lies in V ∩ S, and a split without samples is skipped.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/shadow/focus.h"
#include "geometry/shadow/sample_bounds.h"
#include "geometry/shadow/shadow_plan.h"

#include <gtest/gtest.h>

#include <random>

#include "random_util.h"

using namespace geometry::scene;
using namespace geometry::shadow;
using testutil::randomUnit;
using testutil::uniform;
using testutil::uniform01;

namespace {

float viewDepth(const Camera& cam, const glm::vec3& p) { return -(cam.view() * glm::vec4(p, 1.f)).z; }

/// Points a camera sees on a ground plane y = 0 inside S (a stand-in for the eye's samples), with
/// their view depths, from `rays` random directions through the image.
struct Samples {
    std::vector<glm::vec3> world;
    std::vector<float> depth;
};
Samples groundSamples(const Camera& cam, const Viewport& vp, const Aabb& S, int rays, std::mt19937& rng) {
    Samples out;
    const glm::mat4 inv = glm::inverse(cam.projection(vp.aspect()) * cam.view());
    for (int i = 0; i < rays; ++i) {
        const glm::vec2 ndc(uniform(rng, -1, 1), uniform(rng, -1, 1));
        const glm::vec4 a = inv * glm::vec4(ndc, -1.f, 1.f), b = inv * glm::vec4(ndc, 1.f, 1.f);
        const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
        if (!(p0.y > 0.f && p1.y < 0.f)) continue;
        const glm::vec3 hit = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
        if (!S.contains(hit, 1e-3f)) continue;
        out.world.push_back(hit);
        out.depth.push_back(viewDepth(cam, hit));
    }
    return out;
}

/// The plane scene's camera out to 1000 m over a 4 km ground: a long view whose pixels crowd near
/// the camera.
struct WideGround {
    Scene scene = makePlaneScene();
    Camera cam = scene.camera;
    Viewport vp{320, 240};
    Aabb S = scene.bounds();
    WideGround() {
        cam.far = 1000.f;
        S.add({-2000, 0, -2000});
        S.add({2000, 5, 2000});
    }
};

const WarpMethod kMethods[] = {WarpMethod::Uniform, WarpMethod::Psm,   WarpMethod::Lispsm,
                               WarpMethod::Glispsm, WarpMethod::Gmnpr, WarpMethod::Manual};

} // namespace

TEST(SampleBounds, BinsAreLogSpacedAndCoverTheRange) {
    const double n = 0.5, f = 2000;
    EXPECT_EQ(sampleBin(n, n, f), 0);
    EXPECT_EQ(sampleBin(f, n, f), kSampleBins - 1);
    EXPECT_EQ(sampleBin(1e9, n, f), kSampleBins - 1);
    EXPECT_EQ(sampleBin(NAN, n, f), 0);
    EXPECT_NEAR(sampleBinStart(kSampleBins, n, f), f, 1e-9 * f);
    EXPECT_NEAR(sampleBinStart(kSampleBins / 2, n, f), std::sqrt(n * f), 1e-6);
    int previous = 0;
    for (double z = n; z < f; z *= 1.01) {
        const int b = sampleBin(z, n, f);
        EXPECT_GE(b, previous);
        EXPECT_LE(sampleBinStart(b, n, f), z * (1 + 1e-9));
        EXPECT_GT(sampleBinStart(b + 1, n, f), z * (1 - 1e-9));
        previous = b;
    }
}

TEST(SampleBounds, DirectionsAreUnitAndTheLastIsL) {
    const glm::vec3 l = glm::normalize(glm::vec3(0.3f, -1.f, 0.2f));
    const auto d = sampleDirections(l);
    for (int k = 0; k < kSampleDirections; ++k) EXPECT_NEAR(glm::length(d[k]), 1.f, 1e-5f);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(glm::dot(d[k], l), 0.f, 1e-5f);
    EXPECT_NEAR(glm::dot(d[0], d[1]), std::sqrt(0.5f), 1e-5f);
    EXPECT_EQ(d[4], l);
}

// The prism of the bins a depth range touches holds every sample in that range, and counts them.
TEST(SampleBounds, TheSlabOfARangeHoldsEverySampleInIt) {
    std::mt19937 rng(5);
    std::vector<glm::vec3> world;
    std::vector<float> depth;
    for (int i = 0; i < 5000; ++i) {
        world.emplace_back(uniform(rng, -500, 500), uniform(rng, 0, 60), uniform(rng, -500, 500));
        depth.push_back(std::exp(uniform(rng, std::log(1.f), std::log(900.f))));
    }
    depth[7] = NAN; // ignored, not poison
    const glm::vec3 l = glm::normalize(glm::vec3(0.6f, -0.75f, 0.15f));
    const SampleBounds bounds = reduceSamples(world, depth, 0.5f, 1000.f, l);
    EXPECT_EQ(bounds.count, 4999u);
    for (const auto& [a, b] : {std::pair{1.0, 900.0}, std::pair{3.0, 40.0}, std::pair{200.0, 201.0}}) {
        const SampleSlab slab = samplesWithin(bounds, a, b, 0.0);
        uint64_t inside = 0;
        for (size_t i = 0; i < world.size(); ++i) {
            if (!(depth[i] >= a && depth[i] <= b)) continue;
            ++inside;
            for (const Plane& plane : slab.planes) EXPECT_LE(plane.distance(world[i]), 0.f);
        }
        EXPECT_GE(slab.count, inside);
        EXPECT_EQ(slab.planes.size(), inside > 0 ? size_t(2 * kSampleDirections) : slab.planes.size());
    }
    EXPECT_EQ(samplesWithin(bounds, 0.5, 0.9, 0.0).count, 0u);
    EXPECT_TRUE(samplesWithin(bounds, 0.5, 0.9, 0.0).planes.empty());
}

// Fitted to samples, every sample of split i and every point between it and the light lands in
// split i's map, for every warp, random cameras and lights (the geometric plan's property,
// Plan.WarpedSplitsKeepReceiversAndCastersInTheirUnitCube, kept); and the samples' region lies in
// V ∩ S, inside the geometric focus.
TEST(SampleFocus, SamplesAndTheirCastersStayInTheirSplitsMap) {
    std::mt19937 rng(17);
    Aabb S;
    S.add({-300, 0, -300});
    S.add({300, 40, 300});
    int checked = 0, regions = 0;
    for (int trial = 0; trial < 120; ++trial) {
        ShadowSettings settings;
        settings.focus = FocusMode::Samples;
        settings.warp.method = kMethods[trial % 6];
        settings.splits.count = 1 + (trial / 6) % 4;
        settings.splits.scheme = SplitScheme((trial / 24) % 5);
        settings.splits.blend = trial % 3 == 0 ? 0.2 : 0.0;
        Camera cam;
        cam.eye = {uniform(rng, -100, 100), uniform(rng, 2, 60), uniform(rng, -100, 100)};
        cam.target = {uniform(rng, -150, 150), 0.f, uniform(rng, -150, 150)};
        cam.near = uniform(rng, 0.1f, 2.f);
        cam.far = uniform(rng, 300.f, 3000.f);
        Light light{randomUnit(rng)};
        if (light.direction.y > -0.05f) light.direction.y = -light.direction.y - 0.1f; // the sun is up
        const Viewport vp{640, 360};
        const Samples samples = groundSamples(cam, vp, S, 3000, rng);
        const SampleBounds bounds = reduceSamples(samples.world, samples.depth, cam.near, cam.far, light.l());
        const ShadowPlan plan = planShadows(settings, S, cam, light, vp, &bounds);
        ASSERT_TRUE(plan.fittedToSamples);
        ASSERT_EQ(int(plan.splits.size()), settings.splits.count);
        if (bounds.count == 0) continue;
        EXPECT_LE(plan.splits.front().near, bounds.zMin);
        EXPECT_GE(plan.splits.back().far, bounds.zMax);
        const glm::mat4 eyeViewProj = plan.eyeProj * plan.eyeView;
        for (size_t i = 0; i < plan.splits.size(); ++i) {
            const SplitPlan& split = plan.splits[i];
            for (const glm::vec3& p : split.sampleRegion) {
                EXPECT_TRUE(S.contains(p, 1e-2f)) << "trial " << trial;
                EXPECT_TRUE(testutil::insideUnitCube(eyeViewProj, p, 1e-3f)) << "trial " << trial;
                ++regions;
            }
            for (size_t k = 0; k < samples.world.size(); ++k) {
                if (!(samples.depth[k] >= split.near && samples.depth[k] <= split.far)) continue;
                ASSERT_FALSE(split.skipped) << "trial " << trial << " split " << i;
                const glm::vec3 p = samples.world[k], exit = exitTowardLight(p, plan.l, S);
                EXPECT_TRUE(testutil::insideUnitCube(split.lightViewProj, p, 1e-4f))
                    << "receiver, trial " << trial << " " << warpMethodName(settings.warp.method);
                EXPECT_TRUE(testutil::insideUnitCube(split.lightViewProj, p + uniform01(rng) * (exit - p), 1e-4f))
                    << "caster, trial " << trial << " " << warpMethodName(settings.warp.method);
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 50000);
    EXPECT_GT(regions, 1000);
}

// Samples in two clusters, near and far, with three uniform splits over them: the middle split
// has none and is skipped (no body, so no pass); the others are not.
TEST(SampleFocus, ASplitWithoutSamplesIsSkipped) {
    const WideGround g;
    const auto& [scene, cam, vp, S] = g;
    std::mt19937 rng(3);
    Samples all = groundSamples(cam, vp, S, 20000, rng), clustered;
    for (size_t i = 0; i < all.world.size(); ++i)
        if (all.depth[i] < 30.f || all.depth[i] > 700.f)
            clustered.world.push_back(all.world[i]), clustered.depth.push_back(all.depth[i]);
    ASSERT_GT(clustered.world.size(), 100u);
    const SampleBounds bounds = reduceSamples(clustered.world, clustered.depth, cam.near, cam.far, scene.lights[0].l());
    ShadowSettings settings;
    settings.focus = FocusMode::Samples;
    settings.splits.count = 3;
    settings.splits.scheme = SplitScheme::Uniform;
    const ShadowPlan plan = planShadows(settings, S, cam, scene.lights[0], vp, &bounds);
    ASSERT_EQ(plan.splits.size(), 3u);
    EXPECT_FALSE(plan.splits[0].skipped);
    EXPECT_GT(plan.splits[0].samples, 0u);
    EXPECT_TRUE(plan.splits[1].skipped) << plan.splits[1].near << "–" << plan.splits[1].far;
    EXPECT_EQ(plan.splits[1].samples, 0u);
    EXPECT_TRUE(plan.splits[1].empty());
    EXPECT_FALSE(plan.splits[2].skipped);
    EXPECT_EQ(plan.splits[0].samples + plan.splits[2].samples, clustered.world.size());
}

// Without samples, or with focus.mode = geometry, the plan is the geometric one.
TEST(SampleFocus, GeometryModeIgnoresSamples) {
    const Scene scene = makePlaneScene();
    std::mt19937 rng(4);
    const Viewport vp{320, 240};
    const Samples s = groundSamples(scene.camera, vp, scene.bounds(), 2000, rng);
    const SampleBounds bounds =
        reduceSamples(s.world, s.depth, scene.camera.near, scene.camera.far, scene.lights[0].l());
    ShadowSettings settings;
    settings.splits.count = 2;
    const ShadowPlan a = planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], vp);
    const ShadowPlan b = planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], vp, &bounds);
    EXPECT_FALSE(b.fittedToSamples);
    for (size_t i = 0; i < a.splits.size(); ++i) {
        EXPECT_EQ(a.splits[i].lightViewProj, b.splits[i].lightViewProj);
        EXPECT_EQ(a.splits[i].far, b.splits[i].far);
    }
    settings.focus = FocusMode::Samples;
    const ShadowPlan c = planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], vp, &bounds);
    EXPECT_TRUE(c.fittedToSamples);
    EXPECT_GT(c.splits.front().near, a.splits.front().near); // the nearest ground point is beyond n
}

// The samples' depth quantiles: with the samples spread evenly over the bins of [a, b] in log depth,
// the i/k quantile is the log-spaced point a·(b/a)^(i/k) (to a bin's width); all samples in one bin
// put every quantile inside it; no samples, none.
TEST(SampleFocus, QuantilesSplitTheSamplesEvenly) {
    std::vector<glm::vec3> world;
    std::vector<float> depth;
    const float n = 1.f, f = 1000.f;
    for (int i = 0; i < 10000; ++i) {
        depth.push_back(n * std::pow(f / n, (float(i) + 0.5f) / 10000.f));
        world.emplace_back(0.f, 0.f, -depth.back());
    }
    const SampleBounds even = reduceSamples(world, depth, n, f, {0.f, -1.f, 0.f});
    const auto q = sampleQuantiles(even, n, f, 4);
    ASSERT_EQ(q.size(), 3u);
    for (int i = 1; i <= 3; ++i)
        EXPECT_NEAR(std::log(q[size_t(i - 1)]), std::log(n * std::pow(f / n, i / 4.0)), std::log(f / n) / kSampleBins)
            << i;
    const std::vector<float> one(100, 50.f);
    const SampleBounds clustered =
        reduceSamples(std::vector<glm::vec3>(100, glm::vec3(0.f, 0.f, -50.f)), one, n, f, {0.f, -1.f, 0.f});
    for (const double v : sampleQuantiles(clustered, n, f, 3)) {
        EXPECT_GE(v, sampleBinStart(sampleBin(50.0, n, f), n, f));
        EXPECT_LE(v, sampleBinStart(sampleBin(50.0, n, f) + 1, n, f));
    }
    EXPECT_TRUE(sampleQuantiles(SampleBounds{}, n, f, 3).empty());
}

// With samples, the practical scheme blends the log boundaries over the samples' depth range with
// the boundaries that give each split an equal share of the samples (instead of equal depth): most of
// a view's pixels near the camera put the splits near the camera.
TEST(SampleFocus, PracticalSplitsFollowTheSamples) {
    const WideGround g;
    const auto& [scene, cam, vp, S] = g;
    std::mt19937 rng(5);
    const Samples s = groundSamples(cam, vp, S, 20000, rng);
    const SampleBounds bounds = reduceSamples(s.world, s.depth, cam.near, cam.far, scene.lights[0].l());
    ShadowSettings settings;
    settings.focus = FocusMode::Samples;
    settings.splits.count = 3;
    settings.splits.lambda = 0.5;
    const ShadowPlan plan = planShadows(settings, S, cam, scene.lights[0], vp, &bounds);
    ASSERT_EQ(plan.splits.size(), 3u);
    const double zLo = plan.splits.front().near, zHi = plan.splits.back().far;
    const auto q = sampleQuantiles(bounds, zLo, zHi, 3);
    ASSERT_EQ(q.size(), 2u);
    for (int i = 1; i < 3; ++i) {
        const double log = zLo * std::pow(zHi / zLo, i / 3.0);
        EXPECT_NEAR(plan.splits[size_t(i)].near, 0.5 * log + 0.5 * q[size_t(i - 1)], 1e-3 * zHi) << i;
    }
    // λ = 0: the boundaries are the quantiles alone, so each split holds about a third of the samples.
    settings.splits.lambda = 0.0;
    const ShadowPlan even = planShadows(settings, S, cam, scene.lights[0], vp, &bounds);
    for (const auto& split : even.splits) {
        EXPECT_GT(double(split.samples), 0.25 * double(s.world.size())) << split.near;
        EXPECT_LT(double(split.samples), 0.42 * double(s.world.size())) << split.near;
    }
}
