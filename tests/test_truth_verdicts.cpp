// Verdicts no setting can game (docs/design.md §4 "Truth classes", "Like for like"), rendered on
// the platform's deck view: the undecidable pixels come from the scene and the view alone, so an
// absurd bias cannot hide its own peter-panning among them; the figures do not depend on a tie rule
// or on the sample count; a wide kernel's darkening of lit ground is counted.
#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/inspection.h"
#include "geometry/io/preset.h"
#include "geometry/io/scene_file.h"
#include "renderer/context.h"
#include "renderer/inspection.h"
#include "renderer/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace geometry::shadow;
using namespace geometry::analysis;

namespace {

const std::string kResources = std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/";

/// One scene file's view with its GL context, renderer and truth: plan, render and inspect frames.
struct ViewRig {
    geometry::io::SceneFile file;
    geometry::scene::Camera camera;
    geometry::scene::Light light;
    std::unique_ptr<renderer::GlContext> context = renderer::createOSMesaContext();
    std::unique_ptr<renderer::Renderer> r;
    std::unique_ptr<GroundTruth> truth;

    ViewRig(const std::string& scene, const std::string& view) : file(geometry::io::resolveScene(scene)) {
        const auto& v = file.views.at(view);
        camera = v.camera;
        light = v.light;
        r = std::make_unique<renderer::Renderer>(file.scene);
        truth = std::make_unique<GroundTruth>(file.scene);
    }
    [[nodiscard]] Inspection inspect(const ShadowSettings& s, Viewport vp, int samples) {
        const ShadowPlan plan = planShadows(s, file.scene.bounds(), camera, light, vp);
        r->render(plan, vp, renderer::ViewOptions{.lightViewSize = 16, .overlays = false, .unwarped = false});
        return renderer::inspect(*r, plan, truth.get(), samples);
    }
};

ShadowSettings preset(const std::string& name) { return geometry::io::loadPreset(kResources + "presets/" + name); }

ViewRig& deck() {
    static ViewRig rig(kResources + "scenes/platform.json", "deck");
    return rig;
}

double errors(const TruthClasses& t) { return t.interiorFalseShadow + t.interiorFalseLit + t.edgeError; }

} // namespace

// Five biases (two of them absurd), three filters and three map resolutions of one frame leave
// exactly the same pixels undecidable, contacts included.
TEST(Verdicts, TheUndecidableSetIsTheSameForEverySetting) {
    const Viewport vp{320, 180};
    std::vector<ShadowSettings> configs;
    const ShadowSettings paper = preset("paper.json");
    for (const std::string bias : {"bias.constant=0.02", "bias.constant=10", "bias.type=slope",
                                   "bias.type=normal_offset", "bias.normal_offset=16"}) {
        ShadowSettings s = paper;
        if (bias == "bias.normal_offset=16") applyAssignment(s, "bias.type=normal_offset");
        applyAssignment(s, bias);
        configs.push_back(s);
    }
    for (const std::string filter : {"filter.type=hw2x2", "filter.type=pcss", "filter.type=esm"}) {
        ShadowSettings s = paper;
        applyAssignment(s, filter);
        configs.push_back(s);
    }
    for (const int resolution : {512, 1024, 4096}) {
        ShadowSettings s = paper;
        s.resolution = resolution;
        configs.push_back(s);
    }
    std::vector<uint8_t> first;
    for (const ShadowSettings& s : configs) {
        const Inspection in = deck().inspect(s, vp, 1);
        ASSERT_EQ(in.ambiguity.size(), size_t(vp.width * vp.height));
        if (first.empty()) {
            first = in.ambiguity;
            size_t contact = 0, any = 0;
            for (const uint8_t a : first) {
                contact += a == uint8_t(Ambiguity::Contact);
                any += a != 0;
            }
            EXPECT_GT(contact, 10u) << "the deck has contacts";
            EXPECT_LT(double(any), 0.05 * double(first.size()));
            continue;
        }
        size_t differ = 0;
        for (size_t i = 0; i < first.size(); ++i) differ += in.ambiguity[i] != first[i];
        EXPECT_EQ(differ, 0u) << "bias " << int(s.bias.type) << " " << s.bias.constant << " normal offset "
                              << s.bias.normalOffset << ", filter " << int(s.filter.type) << ", resolution "
                              << s.resolution;
    }
}

// A 10 m constant bias and a normal offset of 16 texels lose the grating's shadows: counted as
// errors (≥ 5 % of the receivers), peter-panning among them, not hidden as undecidable.
TEST(Verdicts, AbsurdBiasesCountAsErrors) {
    const Viewport vp{320, 180};
    ShadowSettings sane = preset("paper.json");
    const Inspection good = deck().inspect(sane, vp, 2);
    ShadowSettings constant = sane;
    constant.bias.constant = 10.f;
    ShadowSettings normal = preset("ssm.json");
    applyAssignment(normal, "bias.normal_offset=16");
    applyAssignment(normal, "bias.slope=32");
    for (const ShadowSettings& s : {constant, normal}) {
        const Inspection bad = deck().inspect(s, vp, 2);
        const TruthClasses& t = *bad.truthClasses;
        EXPECT_GE(errors(t), 0.05) << "interior " << t.interiorFalseLit << " edge " << t.edgeError;
        EXPECT_GT(t.contactFalseLit, 5.0 * good.truthClasses->contactFalseLit);
        EXPECT_GT(t.contactGapMedian, 0.0);
        EXPECT_DOUBLE_EQ(t.ambiguous, good.truthClasses->ambiguous) << "the same undecidable share";
    }
    EXPECT_LT(errors(*good.truthClasses), 0.03);
}

// The same frame at 2 × 2 and 3 × 3 samples: the interior figures agree within a factor 2 (no tie
// at c = 0.5 counts as lit or shadowed; the edges are placed from the same fine grid).
TEST(Verdicts, TwoAndThreeSamplesPerAxisAgreeOnTheInterior) {
    const Viewport vp{320, 180};
    ShadowSettings acne = preset("ssm.json");
    applyAssignment(acne, "bias.type=constant");
    applyAssignment(acne, "bias.constant=0.002");
    const TruthClasses two = *deck().inspect(acne, vp, 2).truthClasses;
    const TruthClasses three = *deck().inspect(acne, vp, 3).truthClasses;
    const double a = two.interiorFalseShadow + two.interiorFalseLit;
    const double b = three.interiorFalseShadow + three.interiorFalseLit;
    EXPECT_GT(a, 0.01) << "a frame with acne";
    EXPECT_LT(a, 2.0 * b);
    EXPECT_LT(b, 2.0 * a);
}

// Like for like: the eye pass drawn again at the truth's samples. With the same maps, more samples
// per axis do not move the edge error by much (no floor from comparing one sample with an area).
TEST(Verdicts, TheRenderIsSampledWhereTheTruthIs) {
    const Viewport vp{160, 90};
    const ShadowSettings s = preset("paper.json");
    const Inspection in = deck().inspect(s, vp, 3);
    ASSERT_EQ(in.sampleShadow.size(), size_t(vp.width * vp.height * 9));
    ASSERT_EQ(in.coverage.size(), size_t(vp.width * vp.height));
    // The samples' mean agrees with the one-sample render where the whole pixel is one surface, lit.
    size_t compared = 0, agree = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const size_t i = size_t(y) * size_t(vp.width) + size_t(x);
            if (!in.receiver[i] || in.coverage[i] != 1.f || in.classes[i] != TruthClass::Agrees) continue;
            const float centre = in.sampleShadow[(size_t(y) * 3 + 1) * size_t(vp.width) * 3 + size_t(x) * 3 + 1];
            if (!std::isfinite(centre)) continue;
            ++compared;
            agree += std::abs(centre - in.shadow[i]) < 1e-3f;
        }
    EXPECT_GT(compared, 1000u);
    EXPECT_GT(double(agree), 0.99 * double(compared)) << "the centre sample is the pixel's own";
    // The frame drawn before stays what the renderer shows.
    EXPECT_EQ(deck().r->stats().eyeWidth, vp.width);
    EXPECT_EQ(deck().r->readShadowMask().size(), size_t(vp.width * vp.height));
}

// A wide kernel darkens lit ground without crossing 0.5 (pssm3 with a 7 × 7 PCF on plane renders it
// at s ≈ 0.96): no sample is misclassified, but interior_mean_abs counts it.
TEST(Verdicts, AWideKernelsDarkeningIsCounted) {
    ViewRig plane(kResources + "scenes/plane.json", "default");
    const Viewport vp{160, 120};
    ShadowSettings s = preset("pssm3.json");
    const TruthClasses narrow = *plane.inspect(s, vp, 2).truthClasses;
    s.filter.kernel = 7;
    const TruthClasses wide = *plane.inspect(s, vp, 2).truthClasses;
    EXPECT_LT(narrow.interiorMeanAbs, 0.005);
    EXPECT_GT(wide.interiorMeanAbs, 0.02) << "lit ground at s ≈ 0.96";
    EXPECT_LT(wide.interiorFalseShadow, 0.001) << "no threshold calls it wrong";
}
