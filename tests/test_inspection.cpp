// Inspection metrics on OSMesa: the measured aliasing error agrees with the analytic model, LiSPSM
// balances near and far error, and ray-traced truth catches misclassified pixels.
#include "render_test_util.h"

#include "app/headless_frame.h"
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/mesh_builder.h"
#include "geometry/shadow/analytic_error.h"
#include "renderer/context.h"
#include "renderer/inspection.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::io;
using namespace geometry::analysis;

namespace {

/// Plane scene at γ = 90°: view and light both 45° to the ground (their projective factors
/// cancel), and a tall mast far away so the scene bounds S hold the whole view frustum (the
/// analytic model knows no clipping by S). Near 1, far 30, 64×128 pixels, 2048² map.
struct GammaNinety {
    std::unique_ptr<renderer::GlContext> context = renderer::createOSMesaContext();
    Scene scene = makePlaneScene();
    std::unique_ptr<renderer::Renderer> r;
    const glm::vec3 v = glm::normalize(glm::vec3(0, -1, -1));
    GammaNinety() {
        MeshBuilder mast("mast", glm::vec3(0.5f));
        mast.addCylinder({38, -300, 38}, {38, 300, 38}, 0.2f, 8);
        scene.meshes.push_back(mast.build());
        scene.lights[0].direction = {0, -1, 1};
        scene.camera.near = 1;
        scene.camera.far = 30;
        scene.camera.fovYDeg = 60;
        r = std::make_unique<renderer::Renderer>(scene);
    }
    /// Measured m at the image centre, where the ground point on the view axis lies at view depth D.
    std::pair<double, ShadowPlan> measure(WarpMethod method, float D) {
        scene.camera.eye = -v * D;
        scene.camera.target = glm::vec3(0.f);
        ShadowSettings s;
        s.warp.method = method;
        const Viewport vp{64, 128};
        ShadowPlan plan = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], vp);
        r->render(plan, vp, 64);
        return {r->readPositions()[64 * 64 + 32].w, plan};
    }
    double analytic(const ShadowPlan& plan, float D) const {
        const ErrorModel em{1, 30, glm::radians(30.0), glm::radians(double(plan.gammaDeg)), 128, 2048};
        return aliasingErrorZ(em, plan.splits[0].nPrime, D);
    }
};

GammaNinety& gammaNinety() {
    static GammaNinety g;
    return g;
}

} // namespace

TEST(Inspection, MeasuredAliasingAgreesWithTheAnalyticModelAlongTheViewAxis) {
    auto& g = gammaNinety();
    for (auto method : {WarpMethod::Uniform, WarpMethod::Lispsm})
        for (float D : {1.1f, 2.f, 4.f, 8.f, 16.f, 29.5f}) {
            const auto [m, plan] = g.measure(method, D);
            EXPECT_NEAR(plan.gammaDeg, 90.f, 0.01f);
            const double mz = g.analytic(plan, D);
            EXPECT_NEAR(m / mz, 1.0, 0.25)
                << warpMethodName(method) << " at depth " << D << ": m " << m << ", m_z " << mz;
        }
    EXPECT_EQ(renderer::takeGlErrors(), "");
}

TEST(Inspection, LispsmBalancesNearAndFarErrorUniformDoesNot) {
    auto& g = gammaNinety();
    const double lNear = g.measure(WarpMethod::Lispsm, 1.1f).first, lFar = g.measure(WarpMethod::Lispsm, 29.5f).first;
    EXPECT_NEAR(lNear / lFar, 1.0, 0.2) << lNear << " vs " << lFar;
    const double uNear = g.measure(WarpMethod::Uniform, 1.1f).first, uFar = g.measure(WarpMethod::Uniform, 29.5f).first;
    EXPECT_GT(uNear / uFar, 5.0) << uNear << " vs " << uFar;
}

namespace {
geometry::analysis::Inspection planeWithTruth(float bias) {
    app::RenderOptions o;
    o.scene = "plane";
    o.backend = "osmesa";
    o.size = {320, 240};
    o.settings.resolution = 2048;
    o.settings.filter.type = FilterType::None;
    o.settings.bias.constant = bias;
    const app::HeadlessFrame f = app::renderHeadless(o, 0);
    const GroundTruth truth(f.scene);
    return renderer::inspect(*f.renderer, f.plan, &truth);
}
} // namespace

TEST(Inspection, TruthAgreesOnPoleShadowsAndCatchesNegativeBias) {
    const geometry::analysis::Inspection good = planeWithTruth(0.05f);
    ASSERT_TRUE(good.truth);
    EXPECT_GT(good.truth->count, 20000u);
    EXPECT_LT(good.truth->falseShadow + good.truth->falseLit, 0.005);
    // The pole shadows are there in the truth too (not an all-lit frame).
    size_t shadowed = 0;
    for (size_t i = 0; i < good.occluded->size(); ++i) shadowed += good.receiver[i] && (*good.occluded)[i];
    EXPECT_GT(shadowed, 100u);
    const geometry::analysis::Inspection bad = planeWithTruth(-0.5f);
    EXPECT_GT(bad.truth->falseShadow, 0.2);
}

TEST(Inspection, TexelUtilizationFallsWithResolution) {
    app::RenderOptions o;
    o.scene = "plane";
    o.backend = "osmesa";
    o.size = {160, 120};
    double previous = 2.0;
    for (int res : {128, 512, 2048}) {
        o.settings.resolution = res;
        const app::HeadlessFrame f = app::renderHeadless(o, 0);
        const geometry::analysis::Inspection in = renderer::inspect(*f.renderer, f.plan, nullptr);
        ASSERT_EQ(in.utilization.size(), 1u);
        EXPECT_GT(in.utilization[0], 0.0);
        EXPECT_LT(in.utilization[0], previous) << res;
        previous = in.utilization[0];
        EXPECT_GT(in.aliasing.count, 5000u);
        EXPECT_TRUE(std::isfinite(in.aliasing.p95));
    }
}

namespace {

/// A scene with its GL context, renderer and ray-traced truth: plan, render and inspect a frame.
struct TruthRig {
    Scene scene;
    std::unique_ptr<renderer::GlContext> context = renderer::createOSMesaContext();
    renderer::Renderer r{scene};
    GroundTruth truth{scene};
    explicit TruthRig(Scene s) : scene(std::move(s)) {}
    [[nodiscard]] ShadowPlan plan(const ShadowSettings& s, Viewport vp) const {
        return planShadows(s, scene.bounds(), scene.camera, scene.lights[0], vp);
    }
    [[nodiscard]] Inspection inspect(const ShadowPlan& plan, Viewport vp, int truthSamples = 1) {
        r.render(plan, vp, renderer::ViewOptions{});
        return renderer::inspect(r, plan, &truth, truthSamples);
    }
};

} // namespace

// Planted acne (a constant bias of −0.5 m pulls receivers into their own surface) shows as interior
// false shadow, not as edge error (docs/design.md §4 "Truth classes").
TEST(Inspection, PlantedAcneIsInteriorFalseShadow) {
    TruthRig rig(makePlaneScene());
    ShadowSettings s;
    s.resolution = 1024;
    s.bias.type = BiasType::Constant;
    s.bias.constant = -0.5f;
    s.filter.type = FilterType::None;
    const Viewport vp{320, 240};
    const Inspection in = rig.inspect(rig.plan(s, vp), vp);
    ASSERT_TRUE(in.truthClasses);
    const TruthClasses& t = *in.truthClasses;
    EXPECT_GT(t.interiorFalseShadow, 0.3) << "edge " << t.edgeError;
    EXPECT_LT(t.edgeError, t.interiorFalseShadow / 10);
    EXPECT_LT(t.interiorFalseLit, 0.01);
    ASSERT_FALSE(in.splitTruthClasses.empty());
    EXPECT_NEAR(in.splitTruthClasses[0].interiorFalseShadow, t.interiorFalseShadow, 1e-12) << "one split: the same";
    // A sane bias leaves almost nothing interior.
    s.bias.constant = 0.05f;
    const Inspection clean = rig.inspect(rig.plan(s, vp), vp);
    EXPECT_LT(clean.truthClasses->interiorFalseShadow, 0.005);
}

namespace {

/// A slab (y 1.9–2) covering x < 0.3 and reaching far past the view, over a ground box; a camera
/// straight down from 10 m; a light 16.7° off the vertical, along x. The slab's one shadow edge in
/// view is the ground line x = 0.9, which falls on a column (or row) of the uniform map.
Scene slabScene() {
    Scene scene;
    scene.name = "slab";
    MeshBuilder ground("ground", glm::vec3(0.8f));
    ground.addBox({0.f, -0.05f, 0.f}, {30.f, 0.05f, 30.f});
    MeshBuilder slab("slab", glm::vec3(0.5f));
    slab.addBox({0.3f - 15.f, 1.95f, 0.f}, {15.f, 0.05f, 30.f});
    scene.meshes.push_back(ground.build());
    scene.meshes.push_back(slab.build());
    scene.camera.eye = {0.f, 10.f, 0.f};
    scene.camera.target = {0.f, 0.f, 0.f};
    scene.camera.up = {0.f, 0.f, -1.f};
    scene.camera.fovYDeg = 40.f;
    scene.camera.near = 1.f;
    scene.camera.far = 20.f;
    scene.lights[0].direction = {0.3f, -1.f, 0.f};
    return scene;
}

} // namespace

// A map whose shadow edge lies half a texel from the true one is edge error of ≈ 0.5 texel, nothing
// interior. The test first finds the lookup shift that puts the rendered edge exactly on the true
// one (the map's texel grid rounds the slab's edge to a texel boundary), checks that it leaves no
// error, then moves the lookups half a texel either way (SplitPlan::lookupShift).
TEST(Inspection, AMapShiftedByHalfATexelIsEdgeErrorOfHalfATexel) {
    TruthRig rig(slabScene());
    ShadowSettings s;
    s.resolution = 128;
    s.warp.method = WarpMethod::Uniform;
    s.filter.type = FilterType::None;
    s.bias.type = BiasType::Constant;
    s.bias.constant = 0.05f;
    const Viewport vp{256, 256};
    ShadowPlan plan = rig.plan(s, vp);
    ASSERT_EQ(plan.splits.size(), 1u);
    const auto texelAt = [&](const glm::vec3& p) {
        const glm::vec4 c = plan.splits[0].lightViewProj * glm::vec4(p, 1.f);
        return (glm::vec2(c) / c.w * 0.5f + 0.5f) * float(s.resolution);
    };
    const glm::vec2 edge = texelAt({0.3f, 2.f, 0.f}); // the slab's top edge, casting the shadow edge
    const glm::vec2 across = glm::normalize(texelAt({0.31f, 2.f, 0.f}) - edge);
    const int axis = std::abs(across.x) > std::abs(across.y) ? 0 : 1;
    ASSERT_GT(std::abs(across[axis]), 0.999f) << "the edge must fall along a texel column or row";
    // Texels whose centre the slab covers hold it; the lookup reads texel floor(t + shift): the
    // rendered edge lies at the texel boundary K next to the true edge X, minus the shift.
    const float X = edge[axis];
    ASSERT_GT(std::abs(X - std::floor(X) - 0.5f), 0.05f) << "too close to a texel centre to round reliably";
    const float K = std::round(X);
    const auto classes = [&](float shift) {
        plan.splits[0].lookupShift = glm::vec2(0.f);
        plan.splits[0].lookupShift[axis] = shift;
        const Inspection in = rig.inspect(plan, vp, 4);
        EXPECT_GT(in.aliasing.p50, 1.5) << "over a pixel per texel: half a texel is about a pixel";
        EXPECT_LT(in.aliasing.p50, 3.0);
        return *in.truthClasses;
    };
    const TruthClasses exact = classes(K - X);
    EXPECT_LT(exact.edgeError, 0.0005) << "the rendered edge on the true one";
    EXPECT_EQ(exact.interiorFalseShadow + exact.interiorFalseLit, 0.0);
    for (const float half : {0.5f, -0.5f}) {
        const TruthClasses t = classes(K - X + half);
        EXPECT_GT(t.edgeError, 0.5 * 256.0 / (256.0 * 256.0)) << "about one pixel per row: " << half;
        EXPECT_EQ(t.interiorFalseShadow + t.interiorFalseLit, 0.0) << half;
        EXPECT_NEAR(t.edgeDisplacementTexelsMedian, 0.5, 0.12) << half;
    }
}

// Classes per scene mesh: the plane scene's ground holds the pole shadows' errors; the poles are
// counted apart; together they are every counted pixel.
TEST(Inspection, TruthClassesPerMeshAddUpToTheWhole) {
    TruthRig rig(makePlaneScene());
    const Scene& scene = rig.scene;
    ShadowSettings s;
    s.resolution = 512;
    const Viewport vp{160, 120};
    const Inspection in = rig.inspect(rig.plan(s, vp), vp, 2);
    ASSERT_EQ(in.meshTruthClasses.size(), scene.meshes.size());
    ASSERT_EQ(in.meshNames.size(), scene.meshes.size());
    size_t counted = 0;
    double edge = 0;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        EXPECT_EQ(in.meshNames[m], scene.meshes[m].name);
        EXPECT_GT(in.meshTruthClasses[m].count, 0u) << in.meshNames[m];
        counted += in.meshTruthClasses[m].count;
        edge += in.meshTruthClasses[m].edgeError * double(in.meshTruthClasses[m].count);
    }
    EXPECT_LE(counted, in.truthClasses->count);
    EXPECT_GT(counted, in.truthClasses->count * 99 / 100) << "nearly every receiver lies on a mesh it was found on";
    EXPECT_NEAR(edge / double(counted), in.truthClasses->edgeError, 0.002);
    nlohmann::json j;
    j["splits"] = nlohmann::json::array({nlohmann::json::object()});
    addInspectionMetrics(j, in);
    EXPECT_EQ(j["truth"]["samples_per_pixel"], 4);
    for (const Mesh& m : scene.meshes) EXPECT_TRUE(j["meshes"].contains(m.name)) << m.name;
}
