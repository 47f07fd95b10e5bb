// The dashboard draws only what changed (issue 18): hover and idle frames draw no pass, a drag
// draws coarse frames and one full frame when it pauses, eye-side settings reuse the shadow maps,
// Reset camera restores the view, and a near/far edit re-inspects. The light list (issue 29): added,
// retyped and inspected lights are drawn and inspected, bad edits are refused. Headless (OSMesa),
// with the pointer driven through HeadlessDashboard::step.
#include "app/dashboard_setup.h"
#include "dashboard_test_util.h"
#include "renderer/context.h"
#include "ui/dashboard_headless.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <cstring>
#include <limits>

namespace {

using testutil::differing;

bool operator==(const ui::PassCounts& a, const ui::PassCounts& b) {
    return a.shadow == b.shadow && a.eyeFull == b.eyeFull && a.eyeCoarse == b.eyeCoarse &&
           a.inspections == b.inspections;
}

std::string describe(const ui::PassCounts& c) {
    return std::to_string(c.shadow) + " shadow, " + std::to_string(c.eyeFull) + " full, " +
           std::to_string(c.eyeCoarse) + " coarse, " + std::to_string(c.inspections) + " inspections, " +
           std::to_string(c.cancelled) + " cancelled";
}

class DashboardInteraction : public ::testing::Test {
protected:
    static constexpr int kW = 960, kH = 600;
    void SetUp() override {
        context_ = renderer::createOSMesaContext();
        app::RenderOptions o;
        o.scene = "platform";
        o.size = {kW, kH};
        o.out = ::testing::TempDir() + "dashboard_interaction";
        geometry::shadow::applyAssignment(o.settings, "shadow_map.resolution=512");
        ui::LoadedScene scene = app::loadDashboardScene(o);
        ui::DashboardState state = app::initialDashboardState(scene, o);
        ui::DashboardOptions options = app::dashboardOptions(o);
        options.clock = [this] { return clock_; }; // the tests advance time themselves: no sleeps
        d_ = std::make_unique<ui::HeadlessDashboard>(std::move(scene), state, std::move(options), kW, kH);
        (void)d_->render(1);
    }
    ui::Dashboard& dash() { return d_->dashboard(); }
    glm::vec2 eyeCentre() {
        const ui::Rect& r = dash().rects().eye;
        return {r.x + r.w * 0.5f, r.y + r.h * 0.6f};
    }
    /// Drags with the left button over the eye view: press, `steps` moves of (dx, 0), release.
    void orbit(int steps, float dx) {
        glm::vec2 p = eyeCentre();
        d_->step({p, {true, false, false}, 0.f});
        for (int i = 0; i < steps; ++i) {
            p.x += dx;
            d_->step({p, {true, false, false}, 0.f});
        }
        d_->step({p, {false, false, false}, 0.f});
    }
    std::unique_ptr<renderer::GlContext> context_;
    std::unique_ptr<ui::HeadlessDashboard> d_;
    double clock_ = 0; // seconds, the dashboard's clock
};

TEST_F(DashboardInteraction, HoverAndIdleFramesDrawNoPass) {
    const geometry::analysis::Image before = d_->render(1);
    const ui::PassCounts counts = dash().passCounts();
    ASSERT_GE(counts.eyeFull, 1u);
    ASSERT_GE(counts.inspections, 1u);
    glm::vec2 p = eyeCentre();
    for (int i = 0; i < 40; ++i, p.x += 1.f) d_->step({p});
    for (int i = 0; i < 20; ++i) d_->step({});
    EXPECT_TRUE(dash().passCounts() == counts) << describe(counts) << " -> " << describe(dash().passCounts());
    EXPECT_FALSE(dash().nextFrameIn()) << "nothing pending: the front end may sleep until input";
    // The status bar did show the hovered pixel meanwhile: the probe reads the last inspection.
    d_->step({eyeCentre()});
    const geometry::analysis::Image hovered = d_->image();
    EXPECT_GT(differing(before, hovered, dash().rects().status), 100u);
    EXPECT_EQ(differing(before, hovered, dash().rects().eye), 0u);
}

TEST_F(DashboardInteraction, EyeSideSettingsReuseTheShadowMaps) {
    dash().state().settings[0].filter.type = geometry::shadow::FilterType::Pcf;
    const geometry::analysis::Image pcf3 = d_->render(1);
    const ui::PassCounts a = dash().passCounts();
    dash().state().settings[0].filter.kernel = 7;
    const geometry::analysis::Image pcf7 = d_->render(1);
    const ui::PassCounts b = dash().passCounts();
    EXPECT_EQ(b.shadow, a.shadow) << "the kernel does not change the maps";
    EXPECT_EQ(b.eyeFull, a.eyeFull + 1);
    EXPECT_EQ(b.inspections, a.inspections + 1);
    EXPECT_GT(differing(pcf3, pcf7, dash().rects().eye), 200u) << "7x7 PCF softens the edges";
    EXPECT_EQ(differing(pcf3, pcf7, dash().rects().light), 0u) << "same maps, same light view";
    dash().state().settings[0].warp.method = geometry::shadow::WarpMethod::Lispsm;
    (void)d_->render(1);
    EXPECT_EQ(dash().passCounts().shadow, b.shadow + 1) << "a warp changes the maps";
}

TEST_F(DashboardInteraction, ADragDrawsCoarseFramesThenOneFullFrame) {
    const ui::PassCounts a = dash().passCounts();
    orbit(6, 8.f);
    const ui::PassCounts b = dash().passCounts();
    EXPECT_GE(b.eyeCoarse, a.eyeCoarse + 5) << describe(b);
    EXPECT_EQ(b.eyeFull, a.eyeFull) << "no full frame while the pointer moves";
    EXPECT_EQ(b.inspections, a.inspections) << "coarse frames are not inspected";
    EXPECT_TRUE(dash().coarse());
    const auto due = dash().nextFrameIn();
    ASSERT_TRUE(due);
    EXPECT_LE(*due, ui::kRefinePause);
    clock_ += ui::kRefinePause + 0.03; // the input pauses
    for (int i = 0; i < 5; ++i) d_->step({});
    (void)d_->render(1);
    const ui::PassCounts c = dash().passCounts();
    EXPECT_EQ(c.eyeFull, b.eyeFull + 1) << "exactly one refinement: " << describe(c);
    EXPECT_EQ(c.eyeCoarse, b.eyeCoarse);
    EXPECT_EQ(c.inspections, b.inspections + 1);
    EXPECT_FALSE(dash().coarse());
    for (int i = 0; i < 10; ++i) d_->step({});
    EXPECT_TRUE(dash().passCounts() == c) << describe(dash().passCounts());
}

TEST_F(DashboardInteraction, ASlowDiscreteChangeShowsCoarseFirstAndRefinesOnTheNextFrame) {
    // A response budget no frame fits, as on a slow machine: the warp change (a combo, not a drag)
    // shows at reduced resolution in the frame that takes it and at full resolution in the next,
    // with no pause to wait for. (The window's budget is ui::kResponseBudgetMs; tests pin it.)
    dash().setResponseBudget(0.0);
    const ui::PassCounts a = dash().passCounts();
    dash().state().settings[0].warp.method = geometry::shadow::WarpMethod::Lispsm;
    d_->step({});
    const ui::PassCounts b = dash().passCounts();
    EXPECT_EQ(b.eyeCoarse, a.eyeCoarse + 1) << describe(b);
    EXPECT_EQ(b.shadow, a.shadow + 1) << "the new warp's maps, at the coarse frame's reduction";
    EXPECT_EQ(b.eyeFull, a.eyeFull);
    EXPECT_TRUE(dash().coarse());
    ASSERT_TRUE(dash().nextFrameIn());
    EXPECT_EQ(*dash().nextFrameIn(), 0.0) << "refined at once: no more input follows a discrete change";
    d_->step({}); // the clock has not moved
    const ui::PassCounts c = dash().passCounts();
    EXPECT_EQ(c.eyeFull, b.eyeFull + 1) << describe(c);
    EXPECT_EQ(c.eyeCoarse, b.eyeCoarse);
    EXPECT_EQ(c.shadow, b.shadow + 1) << "the coarse frame's maps were smaller: drawn again at full size";
    EXPECT_FALSE(dash().coarse());

    // Budget infinite (headless renders, tests by default): the same kind of change draws in full at once.
    dash().setResponseBudget(INFINITY);
    dash().state().settings[0].warp.method = geometry::shadow::WarpMethod::Uniform;
    d_->step({});
    EXPECT_EQ(dash().passCounts().eyeFull, c.eyeFull + 1);
    EXPECT_EQ(dash().passCounts().eyeCoarse, c.eyeCoarse);
}

TEST_F(DashboardInteraction, ChangingTheViewCancelsTheStatisticsUnderWay) {
    dash().state().views.truthSamples = 4;
    d_->step({}); // a full frame; its statistics (16 truth rays a pixel) start on a worker
    const uint64_t cancelled = dash().passCounts().cancelled;
    dash().state().sun.azimuthDeg += 20.f;
    d_->step({});
    EXPECT_EQ(dash().passCounts().cancelled, cancelled + 1);
    (void)d_->render(1);
    ASSERT_NE(dash().inspection(0), nullptr);
    EXPECT_EQ(dash().inspection(0)->truthSamples, 4);
}

TEST_F(DashboardInteraction, ResetCameraRestoresTheView) {
    const geometry::analysis::Image home = d_->render(1);
    orbit(4, 25.f);
    ASSERT_TRUE(dash().setNearFar(2.f, 300.f));
    clock_ += 0.2;
    const geometry::analysis::Image moved = d_->render(1);
    EXPECT_GT(differing(home, moved, dash().rects().eye), 1000u);
    dash().resetCamera();
    const geometry::analysis::Image back = d_->render(1);
    EXPECT_EQ(differing(home, back, dash().rects().eye), 0u);
    EXPECT_EQ(differing(home, back, dash().rects().heatmap), 0u);
}

// A pinned pixel shows the current view's values (issue 32: pin, Reset camera, and the pin said
// depth 5.3 "not a receiver" where hovering the same pixel said depth 331, split 2).
TEST_F(DashboardInteraction, APinnedPixelReadsTheCurrentView) {
    orbit(4, 25.f);
    clock_ += 0.2;
    (void)d_->render(1);
    const glm::vec2 p = eyeCentre();
    ImGui::GetIO().KeyShift = true;           // shift+click pins (a plain click does not: double-click fits)
    d_->step({p, {true, false, false}, 0.f}); // a click without a drag
    d_->step({p, {false, false, false}, 0.f});
    ImGui::GetIO().KeyShift = false;
    ASSERT_TRUE(dash().pinnedPixel());
    const ui::PixelProbe moved = *dash().pinnedPixel();
    dash().resetCamera();
    clock_ += 0.2;
    (void)d_->render(1);
    ASSERT_TRUE(dash().pinnedPixel());
    const ui::PixelProbe& pin = *dash().pinnedPixel();
    // What hovering that pixel shows now.
    const ui::PixelProbe hover = dash().probeEye(0, pin.pixel, ui::ViewPanel::Eye);
    ASSERT_EQ(moved.pixel, pin.pixel);
    EXPECT_NE(moved.viewDepth, hover.viewDepth) << "the camera moved: the pixel shows another point";
    EXPECT_EQ(pin.viewDepth, hover.viewDepth);
    EXPECT_EQ(pin.position, hover.position);
    EXPECT_EQ(pin.split, hover.split);
    EXPECT_EQ(pin.receiver, hover.receiver);
    EXPECT_EQ(pin.shadow, hover.shadow);
}

// The GPU rows are filled from the first frames, with no change to trigger a draw (issue 32: they
// showed "–" until the first change): the dashboard keeps polling while times are in flight.
TEST_F(DashboardInteraction, GpuTimesArriveWithoutAChange) {
    const ui::PassCounts counts = dash().passCounts();
    for (int i = 0; i < 10 && dash().nextFrameIn(); ++i) {
        clock_ += 0.05;
        d_->step({});
    }
    ASSERT_NE(dash().frameStats(0), nullptr);
    EXPECT_TRUE(dash().frameStats(0)->gpu.valid);
    EXPECT_GT(dash().frameStats(0)->gpu.of(renderer::Pass::Eye), 0.0);
    EXPECT_GT(dash().shadowGpuMs(0), 0.0) << "the shadow row too, though the frames since reuse the maps";
    EXPECT_TRUE(dash().passCounts() == counts) << "polling draws no pass";
    EXPECT_FALSE(dash().nextFrameIn()) << "every time arrived: nothing pending";
}

TEST_F(DashboardInteraction, ANearFarEditReinspects) {
    const geometry::analysis::Image before = d_->render(1);
    const double p95 = dash().inspection(0)->aliasing.p95;
    const ui::PassCounts a = dash().passCounts();
    const auto& cam = dash().scene().file.scene.camera;
    ASSERT_TRUE(dash().setNearFar(cam.near * 20.f, cam.far));
    const geometry::analysis::Image after = d_->render(1);
    EXPECT_EQ(dash().passCounts().inspections, a.inspections + 1);
    EXPECT_NE(dash().inspection(0)->aliasing.p95, p95);
    EXPECT_GT(differing(before, after, dash().rects().heatmap), 1000u) << "the heatmap follows the new n";
    EXPECT_FALSE(dash().setNearFar(5.f, 1.f));
    EXPECT_NE(dash().status().find("near/far refused"), std::string::npos) << dash().status();
}

// ---- The light list (issue 29) ---------------------------------------------------------------

uint64_t pixelSum(const geometry::analysis::Image& img) {
    uint64_t sum = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i)
        if (i % 4 != 3) sum += img.rgba[i];
    return sum;
}

TEST_F(DashboardInteraction, AnAddedSpotLightIsDrawnAndInspected) {
    const geometry::analysis::Image before = d_->render(1);
    dash().state().views.lightGizmo = false;
    EXPECT_EQ(differing(before, d_->render(1), dash().rects().eye), 0u) << "no gizmo for the sun alone";
    dash().state().views.lightGizmo = true;
    const uint64_t eyeBefore = pixelSum(dash().eyeImage(0));
    ASSERT_EQ(dash().lights().size(), 1u);
    const uint64_t inspections = dash().passCounts().inspections;
    ASSERT_TRUE(dash().addLight()) << dash().status();
    ASSERT_EQ(dash().lights().size(), 2u);
    EXPECT_EQ(dash().inspectedLight(), 1u) << "Add inspects the new light";
    const geometry::scene::Light spot = dash().lights()[1]; // lights() returns a copy
    EXPECT_EQ(spot.type, geometry::scene::LightType::Spot);
    EXPECT_GT(spot.position.y, dash().scene().file.scene.bounds().hi.y) << "above the scene";
    const geometry::analysis::Image after = d_->render(1);
    EXPECT_NE(pixelSum(dash().eyeImage(0)), eyeBefore) << "the spot light adds its light to the eye view";
    EXPECT_EQ(dash().lightViewMaps(), 1) << "a spot light has one map";
    EXPECT_EQ(dash().plan(0).light.type, geometry::scene::LightType::Spot) << "the plan kept is the inspected light's";
    EXPECT_GT(differing(before, after, dash().rects().light), 1000u) << "the light view shows the spot light's map";
    EXPECT_GT(dash().passCounts().inspections, inspections) << "the statistics follow the inspected light";
    ASSERT_NE(dash().inspection(0), nullptr);
    // The gizmo marks the lights over the eye view (drawn by ImGui, not into the eye image).
    dash().state().views.lightGizmo = false;
    const geometry::analysis::Image bare = d_->render(1);
    EXPECT_GT(differing(after, bare, dash().rects().eye), 20u);
    EXPECT_EQ(differing(after, bare, dash().rects().light), 0u);
}

TEST_F(DashboardInteraction, APointLightOffersSixFacesAndSwitchingBackFollows) {
    const int directionalMaps = dash().lightViewMaps();
    ASSERT_TRUE(dash().addLight());
    geometry::scene::Light point = dash().lights()[1];
    point.type = geometry::scene::LightType::Point;
    ASSERT_TRUE(dash().setLight(1, point)) << dash().status();
    (void)d_->render(1);
    EXPECT_EQ(dash().lightViewMaps(), 6) << "six cube faces";
    EXPECT_EQ(dash().plan(0).splits.size(), 6u);
    dash().state().views.lightSplit = 4;
    const geometry::analysis::Image face4 = d_->render(1);
    dash().state().views.lightSplit = 40; // beyond the faces: clamped to the last
    const geometry::analysis::Image face40 = d_->render(1);
    EXPECT_TRUE(renderer::takeGlErrors().empty());
    dash().state().views.lightSplit = 5;
    const geometry::analysis::Image face5 = d_->render(1);
    EXPECT_EQ(differing(face40, face5, dash().rects().light), 0u) << "the selector clamps to the light's faces";
    EXPECT_GT(differing(face4, face5, dash().rects().light), 100u);
    // Back to the directional light: its splits, its statistics.
    dash().state().views.lightSplit = 0;
    const uint64_t inspections = dash().passCounts().inspections;
    ASSERT_TRUE(dash().inspectLight(0));
    (void)d_->render(1);
    EXPECT_EQ(dash().plan(0).light.type, geometry::scene::LightType::Directional);
    EXPECT_EQ(dash().lightViewMaps(), directionalMaps);
    EXPECT_EQ(dash().passCounts().inspections, inspections + 1) << "switching the inspected light re-inspects";
}

TEST_F(DashboardInteraction, TheSunAnglesEditTheInspectedLight) {
    ASSERT_TRUE(dash().addLight());
    const std::vector<geometry::scene::Light> before = dash().lights();
    dash().state().sun.azimuthDeg += 30.f;
    dash().state().sun.elevationDeg = 60.f;
    (void)d_->render(1);
    const std::vector<geometry::scene::Light> after = dash().lights();
    EXPECT_TRUE(after[0] == before[0]) << "light 0 is not inspected";
    EXPECT_FALSE(after[1].direction == before[1].direction) << "the spot light's axis turned";
    EXPECT_TRUE(dash().scene().file.scene.lights == after) << "the scene holds the lights drawn";
    dash().resetLights();
    EXPECT_EQ(dash().lights().size(), 1u) << "back to the scene's own light";
    EXPECT_GT(glm::dot(dash().lights()[0].l(), before[0].l()), 0.9999f) << "the scene's sun";
}

TEST_F(DashboardInteraction, InvalidLightEditsAreRefusedAndChangeNothing) {
    const auto refused = [this](bool ok, const std::vector<geometry::scene::Light>& before, const char* what) {
        EXPECT_FALSE(ok) << what;
        EXPECT_TRUE(dash().lights() == before) << what;
        EXPECT_NE(dash().status().find("refused"), std::string::npos) << what << ": " << dash().status();
        dash().setStatus("");
    };
    refused(dash().removeLight(0), dash().lights(), "removing the only light");
    ASSERT_TRUE(dash().addLight());
    const geometry::scene::Light spot = dash().lights()[1];
    for (float cone : {0.f, 180.f, -5.f, std::numeric_limits<float>::quiet_NaN()}) {
        geometry::scene::Light l = spot;
        l.coneDeg = cone;
        refused(dash().setLight(1, l), dash().lights(), ("cone " + std::to_string(cone)).c_str());
    }
    geometry::scene::Light l = spot;
    l.position.x = std::numeric_limits<float>::quiet_NaN();
    refused(dash().setLight(1, l), dash().lights(), "NaN position");
    l = spot;
    l.range = 0.f;
    refused(dash().setLight(1, l), dash().lights(), "range 0");
    l = spot;
    l.direction = glm::vec3(0.f);
    refused(dash().setLight(1, l), dash().lights(), "zero direction");
    while (dash().lights().size() < geometry::scene::kMaxLights) ASSERT_TRUE(dash().addLight());
    refused(dash().addLight(), dash().lights(), "a 9th light");
    // The refusals left a drawable list: it still renders, every light.
    (void)d_->render(1);
    EXPECT_EQ(dash().scene().file.scene.lights.size(), geometry::scene::kMaxLights);
    EXPECT_TRUE(renderer::takeGlErrors().empty());
    // Removing works down to one light, the inspected index following.
    while (dash().lights().size() > 1) ASSERT_TRUE(dash().removeLight(dash().lights().size() - 1));
    EXPECT_EQ(dash().inspectedLight(), 0u);
    refused(dash().removeLight(0), dash().lights(), "removing the last light");
}

} // namespace

// --light N (the GUI and `render --views dashboard`) opens the dashboard on that light: a point
// light's six faces in the light view, its statistics.
TEST(DashboardSetup, TheLightOptionPicksTheInspectedLight) {
    const auto context = renderer::createOSMesaContext();
    app::RenderOptions o;
    o.scene = "resources/scenes/plane_lights.json"; // found as the app finds its resources
    o.size = {320, 240};
    o.out = ::testing::TempDir() + "dashboard_light_option";
    o.lightIndex = 2;
    geometry::shadow::applyAssignment(o.settings, "shadow_map.resolution=256");
    ui::LoadedScene scene = app::loadDashboardScene(o);
    const ui::DashboardState state = app::initialDashboardState(scene, o);
    EXPECT_EQ(state.inspectedLight, 2);
    ASSERT_EQ(state.lights.size(), 3u);
    ui::HeadlessDashboard d(std::move(scene), state, app::dashboardOptions(o), 640, 400);
    (void)d.render(1);
    EXPECT_EQ(d.dashboard().inspectedLight(), 2u);
    EXPECT_EQ(d.dashboard().lightViewMaps(), 6);
    EXPECT_EQ(d.dashboard().lights()[2].position, glm::vec3(2, 3, 3));
}
