// The filters of issue 20 on OSMesa at small sizes (docs/filters.md): every filter with every warp
// and split count, light bleeding of the moment filters on a planted overlap, and the receiver-plane
// bias against acne.
#include "geometry/analysis/ground_truth.h"
#include "geometry/io/scene_file.h"
#include "geometry/scene/builtin_scenes.h"
#include "renderer/context.h"
#include "renderer/inspection.h"
#include "renderer/renderer.h"

#include "render_bench_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace geometry::scene;
using namespace geometry::shadow;

namespace {

struct Bench : testutil::SceneBench {
    using SceneBench::SceneBench;

    /// Mean shadow factor over the pixels whose world position passes `where`, and how many.
    std::pair<double, size_t> meanLit(const std::function<bool(const glm::vec3&)>& where) const {
        const auto mask = r->readShadowMask();
        const auto positions = r->readPositions();
        const auto aux = r->readAux();
        double sum = 0;
        size_t n = 0;
        for (size_t i = 0; i < mask.size(); ++i) {
            if (aux[i].z < 0.f || !where(glm::vec3(positions[i]))) continue;
            sum += mask[i];
            ++n;
        }
        return {n ? sum / double(n) : NAN, n};
    }
};

} // namespace

// Every filter with every warp and split count: no GL error, every shadow factor in [0, 1] (no
// NaN), and the poles' shadows still there (a filter that returned "lit" everywhere would fail).
TEST(Filters, EveryFilterRendersWithEveryWarpAndSplitCount) {
    static Bench b(makePlaneScene());
    const auto& filters = findSetting("filter.type")->choices;
    const auto& warps = findSetting("warp.method")->choices;
    for (const auto filter : filters)
        for (const auto warp : warps)
            for (int count = 1; count <= kMaxSplits; ++count) {
                ShadowSettings s;
                s.resolution = 256;
                applySetting(s, "filter.type", filter);
                applySetting(s, "warp.method", warp);
                s.splits.count = count;
                s.light.angularDiameterDeg = 2.f; // PCSS's penumbra; the others ignore it
                ASSERT_TRUE(validate(s).empty());
                const std::string what =
                    std::string(filter) + " / " + std::string(warp) + " / " + std::to_string(count) + " splits";
                b.render(s, {128, 96});
                ASSERT_EQ(renderer::takeGlErrors(), "") << what;
                const auto mask = b.r->readShadowMask();
                ASSERT_TRUE(std::all_of(mask.begin(), mask.end(), [](float v) { return v >= 0.f && v <= 1.f; }))
                    << what << ": a shadow factor outside [0, 1] (or NaN)";
                const auto dark = std::count_if(mask.begin(), mask.end(), [](float v) { return v < 0.5f; });
                EXPECT_GT(dark, 30) << what << ": (almost) no shadow";
            }
}

// The moment filters on the overlap scene (two plates A below B over the ground): light in A's umbra where B's edge
// crosses it. EVSM4 and MSM bleed less than VSM; the test checks that VSM does bleed here, so the case is a real one.
TEST(Filters, Evsm4AndMsmBleedLessThanVsmWhereCastersOverlap) {
    Bench b(makeOverlapScene());
    const auto bleeding = [&](FilterType type, float bleedReduction) {
        ShadowSettings s;
        s.resolution = 256;
        s.filter.type = type;
        s.filter.kernel = 7;
        s.filter.bleedReduction = bleedReduction;
        b.render(s, {240, 180});
        EXPECT_EQ(renderer::takeGlErrors(), "");
        // Ground under A, away from A's own edges, within 1 m of B's edge (x = 0).
        const auto [lit, n] =
            b.meanLit([](const glm::vec3& p) { return p.y < 0.01f && std::abs(p.x) < 1.f && std::abs(p.z) < 3.f; });
        EXPECT_GT(n, 500u);
        return lit;
    };
    for (const float reduction : {0.f, 0.2f}) {
        const double vsm = bleeding(FilterType::Vsm, reduction);
        const double evsm4 = bleeding(FilterType::Evsm4, reduction);
        const double msm = bleeding(FilterType::Msm, reduction);
        const double evsm2 = bleeding(FilterType::Evsm2, reduction);
        const double esm = bleeding(FilterType::Esm, reduction);
        std::printf("bleed_reduction %.1f: light in the umbra: vsm %.4f evsm2 %.4f evsm4 %.4f msm %.4f esm %.4f\n",
                    reduction, vsm, evsm2, evsm4, msm, esm);
        EXPECT_GT(vsm, 0.02) << "the planted overlap should make VSM bleed";
        EXPECT_LT(evsm4, vsm) << "bleed_reduction " << reduction;
        EXPECT_LT(msm, vsm) << "bleed_reduction " << reduction;
    }
}

// Grazing light on an empty stretch of ground (as Techniques.BiasRemovesAcneUnderGrazingLight):
// without bias the PCF family shows acne; the receiver-plane bias removes it for every one of them.
TEST(Filters, ReceiverPlaneBiasRemovesAcneForThePcfFamily) {
    Scene scene = makePlaneScene();
    scene.camera.eye = {22.f, 4.f, 22.f};
    scene.camera.target = {32.f, 0.f, 32.f};           // a corner no pole shadow reaches
    scene.lights[0].direction = {-1.f, -0.2f, -0.15f}; // about 11° above the horizon
    Bench b(scene);
    const auto dark = [&](FilterType filter, BiasType bias) {
        ShadowSettings s;
        s.resolution = 512;
        s.filter.type = filter;
        s.filter.kernel = 5;
        s.bias.type = bias;
        s.light.angularDiameterDeg = 0.53f;
        b.render(s, {160, 120});
        return 1.0 - b.meanLit([](const glm::vec3& p) { return p.y < 0.01f; }).first;
    };
    for (const FilterType filter : {FilterType::None, FilterType::Hw2x2, FilterType::Pcf, FilterType::Disk}) {
        EXPECT_GT(dark(filter, BiasType::None), 0.1) << int(filter);
        EXPECT_LT(dark(filter, BiasType::ReceiverPlane), 0.01) << int(filter);
    }
    EXPECT_LT(dark(FilterType::Pcss, BiasType::ReceiverPlane), 0.01); // PCSS always works on the plane
}

// Pole over plane (resources/scenes/penumbra.json: the plane scene's pole 0 close up, its silhouette
// as the occluder edge) under a 2° sun: PCSS's penumbra at the ground is within 20 % of the sun
// disk's, whose full width is the occluder's distance × tan 2° (truth.penumbra_width_error), and its
// mean |s − v| against the ray-traced sun is below 5×5 PCF's.
TEST(Filters, PcssPenumbraMatchesTheSunAndBeatsPcf) {
    const auto file =
        geometry::io::resolveScene(std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/scenes/penumbra.json");
    Scene scene = file.scene;
    scene.camera = file.views.at("closeup").camera;
    scene.lights[0] = file.views.at("closeup").light;
    ASSERT_TRUE(scene.occluderEdge.has_value());
    Bench b(scene);
    const geometry::analysis::GroundTruth truth(scene);
    const auto measure = [&](FilterType type) {
        ShadowSettings s;
        s.filter.type = type;
        s.filter.kernel = 5;
        s.light.angularDiameterDeg = 2.f;
        const ShadowPlan plan = b.render(s, {480, 270});
        const auto in = renderer::inspect(*b.r, plan, &truth);
        EXPECT_TRUE(in.softTruth.has_value());
        return *in.softTruth;
    };
    const auto pcss = measure(FilterType::Pcss), pcf = measure(FilterType::Pcf);
    std::printf("pcss: width error %.3f (truth's own %.3f), soft_mean_abs %.4f; pcf 5x5: width error %.3f, "
                "soft_mean_abs %.4f\n",
                pcss.penumbraWidthError.value_or(NAN), pcss.penumbraWidthErrorTruth.value_or(NAN), pcss.meanAbs,
                pcf.penumbraWidthError.value_or(NAN), pcf.meanAbs);
    ASSERT_TRUE(pcss.penumbraWidthErrorTruth && std::abs(*pcss.penumbraWidthErrorTruth) < 0.05)
        << "the view resolves the penumbra, so the measurement itself is exact to 5 %";
    ASSERT_TRUE(pcss.penumbraWidthError.has_value());
    EXPECT_LT(std::abs(*pcss.penumbraWidthError), 0.2);
    EXPECT_LT(pcss.meanAbs, pcf.meanAbs);
    EXPECT_LT(*pcf.penumbraWidthError, -0.5)
        << "5x5 PCF's fixed kernel is far narrower here: the case tells them apart";
}

// filter.rotate_taps: the disk's pattern turned per pixel makes neighbouring penumbra pixels along
// the edge differ (noise); one pattern everywhere gives them the same taps, so s holds still along
// the edge and steps across it (bands). Looking down at plate A's shadow edge on the ground (it runs
// up the screen), 128×96, 128² map, receiver-plane bias, 16 taps of radius 8 texels: mean
// |s(x, y+1) − s(x, y)| over vertically adjacent penumbra pixels (0 < s < 1): 0.045 turned, 0.013 not.
TEST(Filters, RotatedTapsTradeBandsForNoise) {
    static Bench b([] {
        Scene scene = makeOverlapScene(); // looking down at the edge of plate A's shadow on the ground
        scene.camera.eye = {5.f, 3.f, 1.5f};
        scene.camera.target = {5.f, 0.f, 0.f};
        return scene;
    }());
    const auto roughness = [&](bool rotate) {
        ShadowSettings s;
        s.resolution = 128;
        s.bias.type = BiasType::ReceiverPlane; // no acne in the lit parts
        s.filter.radius = 8.f;
        s.filter.type = FilterType::Disk;
        s.filter.rotateTaps = rotate;
        b.render(s, {128, 96});
        const auto mask = b.r->readShadowMask();
        const auto at = [&](size_t x, size_t y) { return double(mask[y * 128 + x]); };
        const auto penumbra = [](double s) { return s > 0.0 && s < 1.0; };
        double sum = 0;
        size_t n = 0;
        for (size_t y = 0; y + 1 < 96; ++y)
            for (size_t x = 0; x < 128; ++x)
                if (penumbra(at(x, y)) && penumbra(at(x, y + 1))) sum += std::abs(at(x, y + 1) - at(x, y)), ++n;
        return std::pair{n ? sum / double(n) : 0.0, n};
    };
    const auto [rotated, nRotated] = roughness(true);
    const auto [fixed, nFixed] = roughness(false);
    EXPECT_GT(nFixed, 50u) << "a penumbra to measure";
    EXPECT_GT(nRotated, 50u);
    EXPECT_GT(rotated, 2.5 * fixed) << "rotated " << rotated << ", one pattern " << fixed;
}
