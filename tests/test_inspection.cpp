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
        scene.light.direction = {0, -1, 1};
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
        ShadowPlan plan = planShadows(s, scene.bounds(), scene.camera, scene.light, vp);
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

// Planted acne (a constant bias of −0.5 m pulls receivers into their own surface) shows as interior
// false shadow, not as edge error (docs/design.md §4 "Truth classes").
TEST(Inspection, PlantedAcneIsInteriorFalseShadow) {
    const Scene scene = makePlaneScene();
    auto context = renderer::createOSMesaContext();
    renderer::Renderer r(scene);
    const GroundTruth truth(scene);
    ShadowSettings s;
    s.resolution = 1024;
    s.bias.type = BiasType::Constant;
    s.bias.constant = -0.5f;
    s.filter.type = FilterType::None;
    const Viewport vp{320, 240};
    const ShadowPlan plan = planShadows(s, scene.bounds(), scene.camera, scene.light, vp);
    r.render(plan, vp, renderer::ViewOptions{});
    const Inspection in = renderer::inspect(r, plan, &truth);
    ASSERT_TRUE(in.truthClasses);
    const TruthClasses& t = *in.truthClasses;
    EXPECT_GT(t.interiorFalseShadow, 0.3) << "edge " << t.edgeError;
    EXPECT_LT(t.edgeError, t.interiorFalseShadow / 10);
    EXPECT_LT(t.interiorFalseLit, 0.01);
    ASSERT_FALSE(in.splitTruthClasses.empty());
    EXPECT_NEAR(in.splitTruthClasses[0].interiorFalseShadow, t.interiorFalseShadow, 1e-12) << "one split: the same";
    // A sane bias leaves almost nothing interior.
    s.bias.constant = 0.05f;
    const ShadowPlan good = planShadows(s, scene.bounds(), scene.camera, scene.light, vp);
    r.render(good, vp, renderer::ViewOptions{});
    const Inspection clean = renderer::inspect(r, good, &truth);
    EXPECT_LT(clean.truthClasses->interiorFalseShadow, 0.005);
}
