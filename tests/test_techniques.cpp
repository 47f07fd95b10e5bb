// Every technique on OSMesa at small sizes: combinations render without GL errors, and each bias,
// filter, split and warp control has the effect it promises.
#include "render_test_util.h"

#include "geometry/analysis/stability_metrics.h"
#include "geometry/scene/builtin_scenes.h"
#include "renderer/context.h"
#include "renderer/inspection.h"
#include "renderer/renderer.h"

#include "render_bench_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::analysis;

namespace {

/// A scene's context and renderer that renders a plan of given settings (render_bench_util.h).
using Bench = testutil::SceneBench;

Bench& planeBench() {
    static Bench b(makePlaneScene());
    return b;
}

ShadowSettings small(int resolution = 512) {
    ShadowSettings s;
    s.resolution = resolution;
    return s;
}

/// Fraction of ground pixels (split ≥ 0) whose shadow factor is below 0.5.
double darkFraction(const std::vector<float>& mask, const std::vector<glm::vec4>& aux) {
    size_t dark = 0, ground = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (aux[i].z < 0.f) continue; // sky
        ++ground;
        dark += mask[i] < 0.5f;
    }
    return ground ? double(dark) / double(ground) : 0.0;
}

} // namespace

// Every value of the declared choices (a new warp, bias or filter is tested the day it is declared):
// no GL error, s in [0, 1], and the poles' shadows show without darkening everything.
TEST(Techniques, EveryWarpBiasAndFilterRendersWithoutGlError) {
    Bench& b = planeBench();
    const auto choices = [](std::string_view key) { return findSetting(key)->choices; };
    const auto warps = choices("warp.method"), biases = choices("bias.type"), filters = choices("filter.type");
    ASSERT_FALSE(warps.empty() || biases.empty() || filters.empty());
    for (size_t w = 0; w < warps.size(); ++w)
        for (size_t bias = 0; bias < biases.size(); ++bias)
            for (size_t f = 0; f < filters.size(); ++f) {
                ShadowSettings s = small(128);
                applySetting(s, "warp.method", warps[w]);
                applySetting(s, "bias.type", biases[bias]);
                applySetting(s, "filter.type", filters[f]);
                // Vary the switches across the combinations, so each meets both of its values.
                s.bias.linearZ = (w + bias + f) % 2 == 0;
                s.bias.tangentPlane = (w + f) % 3 == 0;
                s.filter.eyeBlurIterations = bias % 4 == 3 ? 1 : 0;
                s.splits.count = 1 + int(w + bias) % 3;
                ASSERT_TRUE(validate(s).empty());
                const std::string what =
                    std::string(warps[w]) + " / " + std::string(biases[bias]) + " / " + std::string(filters[f]);
                b.render(s, {64, 48});
                ASSERT_EQ(renderer::takeGlErrors(), "") << what;
                const auto mask = b.r->readShadowMask();
                ASSERT_TRUE(std::all_of(mask.begin(), mask.end(), [](float v) { return v >= 0.f && v <= 1.f; }))
                    << what << ": a shadow factor outside [0, 1] (or NaN)";
                // The poles' shadows show (0.2-12 % of the ground at this size, a few pixels at least),
                // and not everything is dark: a filter that returns lit or shadowed everywhere fails.
                const double dark = darkFraction(mask, b.r->readAux());
                EXPECT_GT(dark, 0.001) << what << ": no shadow";
                EXPECT_LT(dark, 0.9) << what << ": everything shadowed";
            }
}

// Grazing light on an empty stretch of ground: no bias darkens ground that geometry says is lit;
// constant, slope and second-depth bias remove it.
TEST(Techniques, BiasRemovesAcneUnderGrazingLight) {
    Scene scene = makePlaneScene();
    scene.camera.eye = {22.f, 4.f, 22.f};
    scene.camera.target = {32.f, 0.f, 32.f};           // a corner no pole shadow reaches
    scene.lights[0].direction = {-1.f, -0.2f, -0.15f}; // about 11° above the horizon, shadows go to −x
    Bench b(scene);
    const auto acne = [&](BiasType type) {
        ShadowSettings s = small(512);
        s.filter.type = FilterType::None;
        s.bias.type = type;
        s.bias.constant = 2.0f;
        s.bias.slope = 2.f;
        s.bias.units = 4.f;
        b.render(s, {160, 120});
        return darkFraction(b.r->readShadowMask(), b.r->readAux());
    };
    EXPECT_GT(acne(BiasType::None), 0.2);
    EXPECT_LT(acne(BiasType::Constant), 0.01);
    EXPECT_LT(acne(BiasType::Slope), 0.01);
    EXPECT_LT(acne(BiasType::SecondDepth), 0.01);
    EXPECT_LT(acne(BiasType::SlopeNormalOffset), 0.01);
}

// The PCF kernel widens the shadow-edge transition: more pixels with a partial shadow factor.
TEST(Techniques, PcfTransitionGrowsWithKernel) {
    Bench& b = planeBench();
    std::vector<int> partial;
    for (int k : {1, 3, 5, 7}) {
        ShadowSettings s = small(256);
        s.filter.type = FilterType::Pcf;
        s.filter.kernel = k;
        s.bias.tangentPlane = true; // taps compare on the receiver's plane: only real edges are partial
        b.render(s, {320, 240});
        const auto mask = b.r->readShadowMask();
        partial.push_back(int(std::count_if(mask.begin(), mask.end(), [](float v) { return v > 0.02f && v < 0.98f; })));
    }
    EXPECT_EQ(partial[0], 0);
    for (size_t i = 1; i < partial.size(); ++i) EXPECT_GT(partial[i], partial[i - 1] + 20) << "kernel index " << i;
}

TEST(Techniques, ThreeSplitsAllAppearAcrossTheView) {
    Bench& b = planeBench();
    ShadowSettings s = small(256);
    s.splits.count = 3;
    s.splits.scheme = SplitScheme::Practical; // ground is visible from 8 m to 57 m: all three splits
    b.render(s, {160, 120});
    std::set<int> seen;
    for (const auto& a : b.r->readAux())
        if (a.z >= 0.f) seen.insert(int(a.z));
    EXPECT_EQ(seen, (std::set<int>{0, 1, 2}));
    EXPECT_EQ(b.r->stats().splitTriangles.size(), 3u);
}

// LiSPSM gives near receivers more texels per pixel than uniform (measured from the rendered
// map coordinates of the bottom rows of the image).
TEST(Techniques, LispsmGivesNearReceiversMoreTexelsPerPixel) {
    Bench& b = planeBench();
    const auto texelsPerPixel = [&](WarpMethod m) {
        ShadowSettings s = small(1024);
        s.warp.method = m;
        b.render(s, {160, 120});
        const auto aux = b.r->readAux();
        double sum = 0;
        int n = 0;
        for (int y = 100; y < 118; ++y)
            for (int x = 40; x < 120; ++x) {
                const glm::vec4 a = aux[size_t(y) * 160 + x], r = aux[size_t(y) * 160 + x + 1];
                if (a.z < 0.f || r.z < 0.f) continue;
                sum += glm::length(glm::vec2(r) - glm::vec2(a));
                ++n;
            }
        return n ? sum / n : 0.0;
    };
    EXPECT_GT(texelsPerPixel(WarpMethod::Lispsm), 2.0 * texelsPerPixel(WarpMethod::Uniform));
}

// Per-split caster culling: three practical splits on the platform submit little more than one
// uniform map (docs/design.md §3.4, Barroso Table 2).
TEST(Techniques, SplitCullingKeepsShadowTrianglesNearOnePass) {
    static Bench platform(makePlatformScene());
    ShadowSettings one = small(256);
    platform.render(one, {64, 48});
    const uint64_t single = platform.r->stats().shadowTriangles;
    ShadowSettings three = one;
    three.splits.count = 3;
    three.splits.scheme = SplitScheme::Practical;
    platform.render(three, {64, 48});
    const auto& st = platform.r->stats();
    EXPECT_LE(double(st.shadowTriangles), 1.3 * double(single));
    EXPECT_LT(st.eyeTriangles, platform.scene.triangleCount()); // the eye pass culls too
    uint64_t sum = 0;
    for (auto t : st.splitTriangles) sum += t;
    EXPECT_EQ(sum, st.shadowTriangles);
}

TEST(Techniques, ResolutionFalloffUsesPartOfTheArray) {
    Bench& b = planeBench();
    ShadowSettings s = small(512);
    s.splits.count = 2;
    s.splits.resolutionFalloff = true;
    const ShadowPlan plan = b.render(s, {160, 120});
    EXPECT_EQ(plan.splits[1].resolution, 256);
    EXPECT_EQ(b.r->stats().shadowResolution, 512);
    EXPECT_EQ(renderer::takeGlErrors(), "");
    // Texel coordinates of split 1 stay inside its 256² corner (and split 1 is on screen).
    int inSplit1 = 0;
    for (const auto& a : b.r->readAux())
        if (int(a.z) == 1) {
            ++inSplit1;
            EXPECT_LE(a.x, 256.f);
            EXPECT_LE(a.y, 256.f);
        }
    EXPECT_GT(inSplit1, 100) << "no pixel uses split 1: the check above checked nothing";
}

// Shadow maps that exceed the memory budget are reduced, with a warning, never a failure.
TEST(Techniques, ResolutionBeyondTheBudgetIsReducedWithAWarning) {
    renderer::RendererLimits limits;
    limits.shadowMemoryBytes = 4.0 * 1024 * 1024; // 4 MiB: 1024² float depth is the most that fits
    Bench& shared = planeBench();
    shared.context->makeCurrent();
    renderer::Renderer r(shared.scene, limits);
    ShadowSettings s = small(4096);
    const ShadowPlan plan =
        planShadows(s, shared.scene.bounds(), shared.scene.camera, shared.scene.lights[0], {64, 48});
    r.render(plan, {64, 48}, 64);
    EXPECT_EQ(r.stats().shadowResolution, 1024);
    ASSERT_FALSE(r.stats().warnings.empty());
    EXPECT_NE(r.stats().warnings.front().find("resolution reduced to 1024"), std::string::npos);
    EXPECT_EQ(renderer::takeGlErrors(), "");
}

// Split boundaries: a 2×2 pixel block that straddles one takes its texel derivatives through each
// pixel's own map, so m next to the boundary continues m a few pixels inside the split. (Taking
// dFdx of the texel coordinates mixed the two maps there: m dipped or spiked along the seam.)
TEST(Techniques, SplitBoundariesDoNotDisturbM) {
    Bench& b = planeBench();
    ShadowSettings s = small(1024);
    s.splits.count = 2;
    s.splits.resolutionFalloff = true; // split 1 has half the texels: m doubles across the boundary
    const int w = 240;
    int boundary = 0, disturbed = 0;
    // The boundary is a screen row on the ground plane; four heights move it against the 2×2 pixel
    // blocks (counted from the bottom of the window) so that some put it inside a block. (With the
    // old derivatives 358 of 1897 boundary pixels were off by more than 25 %.)
    for (const int h : {180, 181, 182, 183}) {
        const ShadowPlan plan = b.render(s, {w, h});
        ASSERT_EQ(renderer::takeGlErrors(), "");
        const auto in = renderer::inspect(*b.r, plan, nullptr);
        const auto split = [&](size_t i) { return in.receiver[i] ? int(in.aux[i].z) : -1; };
        for (int y = 3; y + 4 < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * w + x, below = i + w;
                if (!(split(i) == 1 && split(below) == 0)) continue;
                // Each side of the boundary against the same split three pixels away from it.
                for (const auto& [pixel, inside] :
                     {std::pair{i, i - 3 * size_t(w)}, std::pair{below, below + 3 * size_t(w)}}) {
                    if (split(inside) != split(pixel)) continue;
                    ++boundary;
                    const double ratio = in.m[pixel] / in.m[inside];
                    disturbed += !(ratio > 0.8 && ratio < 1.25);
                }
            }
    }
    ASSERT_GT(boundary, 200) << "the split boundary is not in view";
    EXPECT_LE(disturbed, boundary / 50) << disturbed << " of " << boundary << " boundary pixels";
}

namespace {

/// Texels of `b` that differ from `a` shifted by (dx, dy) (b[x, y] against a[x + dx, y + dy]) over
/// their overlap, ignoring the outer `border` texels; and how many were compared.
std::pair<size_t, size_t> mapDifference(const std::vector<float>& a, const std::vector<float>& b, int res, int dx,
                                        int dy, int border) {
    size_t differ = 0, compared = 0;
    for (int y = border; y < res - border; ++y)
        for (int x = border; x < res - border; ++x) {
            const int ax = x + dx, ay = y + dy;
            if (ax < border || ay < border || ax >= res - border || ay >= res - border) continue;
            ++compared;
            differ += a[size_t(ay) * size_t(res) + size_t(ax)] != b[size_t(y) * size_t(res) + size_t(x)];
        }
    return {differ, compared};
}

} // namespace

// stabilize.mode = snap, rendered: a camera moved by less than a texel gives a uniform map whose raw
// depth equals the previous frame's up to a whole-texel shift (readShadowMap, what `render --views
// shadow_map` writes); without snap no whole-texel shift matches it.
TEST(Techniques, SnappedMapsMatchAcrossASubTexelCameraMove) {
    Bench& b = planeBench();
    const Camera original = b.scene.camera;
    ShadowSettings s = small(512);
    const Viewport vp{160, 120};
    const auto maps = [&](StabilizeMode mode) {
        s.stabilize = mode;
        std::array<std::vector<float>, 2> out;
        for (int frame = 0; frame < 2; ++frame) {
            b.scene.camera = original;
            if (frame == 1) {
                b.scene.camera.eye += glm::vec3(0.031f, 0.f, -0.017f);
                b.scene.camera.target += glm::vec3(0.031f, 0.f, -0.017f);
            }
            (void)b.render(s, vp);
            out[size_t(frame)] = b.r->readShadowMap(0, s.resolution);
        }
        b.scene.camera = original;
        return out;
    };
    // The best whole-texel shift within ±3 texels: fewest differing texels.
    const auto bestShift = [](const std::array<std::vector<float>, 2>& m, int res) {
        size_t best = SIZE_MAX, compared = 0;
        for (int dy = -3; dy <= 3; ++dy)
            for (int dx = -3; dx <= 3; ++dx) {
                const auto [differ, n] = mapDifference(m[0], m[1], res, dx, dy, 4);
                if (differ < best) best = differ, compared = n;
            }
        return std::pair{best, compared};
    };
    const auto snapped = maps(StabilizeMode::Snap);
    ASSERT_EQ(snapped[0].size(), size_t(512 * 512));
    const auto [snapDiffer, snapCompared] = bestShift(snapped, 512);
    EXPECT_GT(snapCompared, size_t(200000));
    EXPECT_EQ(snapDiffer, 0u) << "of " << snapCompared;
    const auto loose = maps(StabilizeMode::Off);
    const auto [looseDiffer, looseCompared] = bestShift(loose, 512);
    EXPECT_GT(looseDiffer, looseCompared / 100) << "unsnapped maps slide by fractions of a texel";
    EXPECT_EQ(renderer::takeGlErrors(), "");
}

// splits.blend: in the band before a split's far end the shadow (and m) fades into the next split's,
// so the m jump at the boundary — the seam measure — falls; the shadow factor stays in [0, 1] and the
// band's receivers still see the poles' shadows.
TEST(Techniques, BlendBandsLowerTheSeam) {
    Bench& b = planeBench();
    ShadowSettings s = small(512);
    s.splits.count = 3;
    const Viewport vp{320, 240};
    const auto seam = [&](double blend) {
        s.splits.blend = blend;
        const ShadowPlan plan = b.render(s, vp);
        if (blend > 0) {
            EXPECT_LT(plan.splits[0].blendStart, plan.splits[0].far);
            EXPECT_EQ(plan.splits[2].blendStart, plan.splits[2].far) << "the last split has no band";
        }
        const auto in = renderer::inspect(*b.r, plan, nullptr);
        for (float v : in.shadow) EXPECT_TRUE(v >= 0.f && v <= 1.f);
        return geometry::analysis::seamStats(in.m, in.aux, in.receiver, in.positions, in.normals, plan.eye, in.width,
                                             in.height);
    };
    const auto hard = seam(0.0), soft = seam(0.2);
    ASSERT_GT(hard.pairs, 50u);
    ASSERT_GT(soft.pairs, 50u);
    EXPECT_GT(hard.median, 1.2) << "a hard seam";
    EXPECT_LT(soft.median, hard.median * 0.9) << "hard " << hard.median << ", blended " << soft.median;
    EXPECT_EQ(renderer::takeGlErrors(), "");
}

// World-space flicker on a dolly: with snap the uniform map holds every world point's state, so at
// most a tenth of the unsnapped flicker remains (issue 15's acceptance, on the plane scene; the
// platform's deck_dolly figures are in docs/stability.md).
TEST(Techniques, SnapCutsWorldSpaceFlickerOnADolly) {
    Bench& b = planeBench();
    const Camera original = b.scene.camera;
    ShadowSettings s = small(256);
    s.filter.type = FilterType::Pcf;
    const Viewport vp{320, 240};
    const auto flicker = [&](StabilizeMode mode) {
        s.stabilize = mode;
        std::optional<geometry::analysis::Inspection> previous;
        glm::mat4 previousViewProj(1.f);
        size_t flips = 0, stable = 0;
        for (int frame = 0; frame < 8; ++frame) {
            b.scene.camera = original;
            const glm::vec3 step = glm::vec3(0.011f, 0.f, -0.007f) * float(frame);
            b.scene.camera.eye += step;
            b.scene.camera.target += step;
            const ShadowPlan plan = b.render(s, vp);
            geometry::analysis::Inspection in = renderer::inspect(*b.r, plan, nullptr);
            if (previous) {
                const auto f = geometry::analysis::worldFlickerStats(*previous, previousViewProj, in);
                flips += f.flips;
                stable += f.stable;
            }
            previous = std::move(in);
            previousViewProj = plan.eyeProj * plan.eyeView;
        }
        b.scene.camera = original;
        EXPECT_GT(stable, 50000u);
        return double(flips) / double(std::max<size_t>(stable, 1));
    };
    const double off = flicker(StabilizeMode::Off), snap = flicker(StabilizeMode::Snap);
    EXPECT_GT(off, 1e-4) << "an unsnapped map shimmers";
    EXPECT_LE(snap, off / 10) << "off " << off << ", snap " << snap;
}
