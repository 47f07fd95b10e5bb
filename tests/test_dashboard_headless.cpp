// The dashboard drawn headless (OSMesa): every panel has content, and each setting changes the
// panels it should and no other.
#include "app/dashboard_setup.h"
#include "dashboard_test_util.h"
#include "renderer/context.h"
#include "ui/dashboard_headless.h"

#include <gtest/gtest.h>

#include <fstream>

#include <cmath>
#include <cstdlib>
#include <cstring>

namespace {

struct Region {
    double mean = 0, variance = 0;
};

Region stats(const geometry::analysis::Image& img, const ui::Rect& r) {
    double sum = 0, sum2 = 0;
    size_t n = 0;
    for (int y = int(r.y); y < int(r.bottom()) && y < img.height; ++y)
        for (int x = int(r.x); x < int(r.right()) && x < img.width; ++x) {
            const uint8_t* p = img.at(x, y);
            const double l = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            sum += l;
            sum2 += l * l;
            ++n;
        }
    Region out;
    if (n) {
        out.mean = sum / double(n);
        out.variance = sum2 / double(n) - out.mean * out.mean;
    }
    return out;
}

using testutil::differing;

/// Fraction of near-white pixels inside r.
double stats_of_white(const geometry::analysis::Image& img, const ui::Rect& r) {
    size_t white = 0, n = 0;
    for (int y = int(r.y); y < int(r.bottom()); ++y)
        for (int x = int(r.x); x < int(r.right()); ++x, ++n) {
            const uint8_t* p = img.at(x, y);
            white += p[0] > 245 && p[1] > 245 && p[2] > 245;
        }
    return n ? double(white) / double(n) : 0.0;
}

class HeadlessDashboardTest : public ::testing::Test {
protected:
    static constexpr int kW = 960, kH = 600;
    void SetUp() override {
        context_ = renderer::createOSMesaContext();
        app::RenderOptions o;
        o.scene = "plane";
        o.size = {kW, kH};
        o.out = ::testing::TempDir() + "dashboard_test";
        options_ = o;
    }
    std::unique_ptr<ui::HeadlessDashboard> make(const std::vector<std::string>& assignments = {}) {
        app::RenderOptions o = options_;
        for (const auto& a : assignments) geometry::shadow::applyAssignment(o.settings, a);
        ui::LoadedScene scene = app::loadDashboardScene(o);
        ui::DashboardState state = app::initialDashboardState(scene, o);
        return std::make_unique<ui::HeadlessDashboard>(std::move(scene), state, app::dashboardOptions(o), kW, kH);
    }
    std::unique_ptr<renderer::GlContext> context_;
    app::RenderOptions options_;
};

TEST_F(HeadlessDashboardTest, EveryPanelHasContent) {
    auto d = make();
    const geometry::analysis::Image img = d->render(2);
    ASSERT_EQ(img.width, kW);
    ASSERT_EQ(img.height, kH);
    const ui::DashboardRects& r = d->dashboard().rects();
    const std::pair<const char*, ui::Rect> panels[] = {{"controls", r.controls}, {"eye", r.eye},
                                                       {"light", r.light},       {"heatmap", r.heatmap},
                                                       {"stats", r.stats},       {"status", r.status}};
    for (const auto& [name, rect] : panels) {
        const Region s = stats(img, rect);
        EXPECT_GT(s.variance, 40.0) << name << " looks empty (mean " << s.mean << ")";
    }
    // The eye panel shows the rendered eye image: sky blue at its top.
    const uint8_t* sky = img.at(int(r.eye.x + r.eye.w / 2), int(r.eye.y + 60));
    EXPECT_GT(sky[2], sky[0]) << "blue sky at the top of the eye view";
    // Statistics arrived: the inspection ran and found receivers.
    const geometry::analysis::Inspection* in = d->dashboard().inspection(0);
    ASSERT_NE(in, nullptr);
    EXPECT_GT(in->aliasing.count, 1000u);
    ASSERT_TRUE(in->truth);
    EXPECT_TRUE(renderer::takeGlErrors().empty());
}

TEST_F(HeadlessDashboardTest, FilterKernelChangesTheEyePanelOnly) {
    auto narrow = make({"filter.type=pcf", "filter.kernel=1"});
    auto wide = make({"filter.type=pcf", "filter.kernel=7"});
    const geometry::analysis::Image a = narrow->render(2), b = wide->render(2);
    const ui::DashboardRects& r = narrow->dashboard().rects();
    EXPECT_GT(differing(a, b, r.eye), 200u) << "wider PCF softens the shadow edges";
    EXPECT_EQ(differing(a, b, r.light), 0u) << "the shadow map does not depend on the filter";
}

TEST_F(HeadlessDashboardTest, WarpMethodChangesTheLightPanel) {
    auto uniform = make({"warp.method=uniform"});
    auto lispsm = make({"warp.method=lispsm"});
    const geometry::analysis::Image a = uniform->render(2), b = lispsm->render(2);
    const ui::DashboardRects& r = uniform->dashboard().rects();
    const double area = double(r.light.w) * r.light.h;
    EXPECT_GT(double(differing(a, b, r.light)), 0.05 * area) << "the warp reshapes the light's view";
}

TEST_F(HeadlessDashboardTest, SameStateSamePixels) {
    auto first = make({"warp.method=lispsm"});
    auto second = make({"warp.method=lispsm"});
    const geometry::analysis::Image a = first->render(2), b = second->render(2);
    const ui::DashboardRects& r = first->dashboard().rects();
    for (const ui::Rect& rect : {r.eye, r.light, r.heatmap, r.controls})
        EXPECT_EQ(differing(a, b, rect), 0u) << "deterministic panels (stats hold live timings)";
}

TEST_F(HeadlessDashboardTest, CompareShowsBothSidesAndTheirDifference) {
    app::RenderOptions o = options_;
    ui::LoadedScene scene = app::loadDashboardScene(o);
    ui::DashboardState state = app::initialDashboardState(scene, o);
    geometry::shadow::applySetting(state.settings[1], "warp.method", "lispsm");
    state.views.compare = ui::CompareMode::SideBySide;
    state.views.heatmap = ui::HeatmapKind::Difference;
    ui::HeadlessDashboard d(std::move(scene), state, app::dashboardOptions(o), kW, kH);
    const geometry::analysis::Image img = d.render(2);
    ASSERT_NE(d.dashboard().inspection(1), nullptr);
    const geometry::analysis::Inspection& a = *d.dashboard().inspection(0);
    const geometry::analysis::Inspection& b = *d.dashboard().inspection(1);
    EXPECT_EQ(a.width, b.width);
    EXPECT_NE(a.aliasing.p95, b.aliasing.p95) << "two warps, two error distributions";
    // The difference heatmap is not uniform grey: m_A / m_B varies over the receivers.
    EXPECT_GT(stats(d.dashboard().heatmapImage(), {0, 0, float(a.width), float(a.height)}).variance, 20.0);
    EXPECT_GT(stats(img, d.dashboard().rects().eye).variance, 40.0);
}

// The soft heatmap: with truth and a sun of non-zero size it shows s − v (PCF's fixed kernel against a
// 2° sun differs somewhere: not uniform); with a point sun it stays a placeholder and the soft truth absent.
TEST_F(HeadlessDashboardTest, SoftHeatmapShowsTheRenderAgainstTheSunsDisk) {
    const auto heatmapVariance = [&](float sunDeg) {
        app::RenderOptions o = options_;
        ui::LoadedScene scene = app::loadDashboardScene(o);
        ui::DashboardState state = app::initialDashboardState(scene, o);
        state.settings[0].filter.type = geometry::shadow::FilterType::Pcf;
        state.settings[0].filter.kernel = 5;
        state.settings[0].light.angularDiameterDeg = sunDeg;
        state.views.truth = true;
        state.views.heatmap = ui::HeatmapKind::Soft;
        ui::HeadlessDashboard d(std::move(scene), state, app::dashboardOptions(o), kW, kH);
        (void)d.render(3);
        const geometry::analysis::Inspection* in = d.dashboard().inspection(0);
        EXPECT_NE(in, nullptr);
        EXPECT_EQ(in && in->softTruth.has_value(), sunDeg > 0.f);
        const geometry::analysis::Image h = d.dashboard().heatmapImage();
        return stats(h, {0, 0, float(h.width), float(h.height)}).variance;
    };
    EXPECT_GT(heatmapVariance(2.f), 20.0);
    EXPECT_LT(heatmapVariance(0.f), 1.0) << "a placeholder";
}

TEST(HeadlessDashboard, RefusesAbsurdSizes) {
    auto context = renderer::createOSMesaContext();
    app::RenderOptions o;
    o.scene = "plane";
    EXPECT_THROW(ui::HeadlessDashboard(app::loadDashboardScene(o), {}, {}, 10, 10), std::invalid_argument);
    EXPECT_THROW(ui::HeadlessDashboard(app::loadDashboardScene(o), {}, {}, 100000, 600), std::invalid_argument);
}

} // namespace

namespace {

TEST_F(HeadlessDashboardTest, AFailedSceneLoadKeepsThePreviousScene) {
    auto d = make();
    (void)d->render(1);
    const size_t triangles = d->dashboard().scene().file.scene.triangleCount();
    d->dashboard().loadScene("/nonexistent/model.stl");
    for (int i = 0; i < 200 && d->dashboard().loading(); ++i) (void)d->render(1);
    (void)d->render(1);
    EXPECT_FALSE(d->dashboard().loading());
    EXPECT_EQ(d->dashboard().scene().source, "plane");
    EXPECT_EQ(d->dashboard().scene().file.scene.triangleCount(), triangles);
    const std::string& status = d->dashboard().status();
    EXPECT_NE(status.find("previous one stays"), std::string::npos) << status;
    EXPECT_NE(status.find("/nonexistent/model.stl"), std::string::npos) << status;
    EXPECT_EQ(status.find('\n'), std::string::npos);
}

TEST_F(HeadlessDashboardTest, ASceneLoadsInTheBackgroundWithProgress) {
    auto d = make();
    (void)d->render(1);
    d->dashboard().loadScene("platform");
    EXPECT_TRUE(d->dashboard().loading());
    for (int i = 0; i < 2000 && d->dashboard().loading(); ++i) (void)d->render(1); // the UI keeps drawing meanwhile
    (void)d->render(1);
    EXPECT_EQ(d->dashboard().scene().source, "platform");
    EXPECT_GT(d->dashboard().scene().file.scene.triangleCount(), 200000u);
    EXPECT_NE(d->dashboard().status().find("loaded platform"), std::string::npos) << d->dashboard().status();
}

TEST(SceneLoader, ReportsProgressAndErrors) {
    std::vector<float> seen;
    const ui::SceneLoadResult ok =
        ui::SceneLoader::loadNow("plane", [&](float f, std::string_view) { seen.push_back(f); });
    ASSERT_TRUE(std::holds_alternative<ui::LoadedScene>(ok));
    EXPECT_NE(std::get<ui::LoadedScene>(ok).truth, nullptr);
    ASSERT_FALSE(seen.empty());
    EXPECT_FLOAT_EQ(seen.back(), 1.f);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    const ui::SceneLoadResult bad = ui::SceneLoader::loadNow("/no/such/file.obj");
    ASSERT_TRUE(std::holds_alternative<std::string>(bad));
    EXPECT_NE(std::get<std::string>(bad).find("/no/such/file.obj"), std::string::npos);
}

} // namespace

namespace {

TEST_F(HeadlessDashboardTest, ChartTabsDrawTheCurvesAndTheTradeoffSweepRuns) {
    auto d = make();
    const geometry::analysis::Image stats = d->render(2);
    d->dashboard().showTab(1); // n'(γ)
    const geometry::analysis::Image warp = d->render(2);
    const ui::Rect& r = d->dashboard().rects().stats;
    EXPECT_GT(differing(stats, warp, r), size_t(0.3 * r.w * r.h)) << "the chart replaces the table";
    // The chart has a white plot background (the table is dark).
    EXPECT_GT(stats_of_white(warp, r), 0.3);
    d->dashboard().showTab(4);
    d->dashboard().startTradeoffSweep();
    for (int i = 0; i < 20 && d->dashboard().tradeoffRunning(); ++i) (void)d->render(1);
    const auto& results = d->dashboard().tradeoffResults();
    if (const char* dump = std::getenv("SHADOWSCOPE_TEST_DUMP")) { // for looking at the charts by hand
        geometry::analysis::writePng(std::string(dump) + "/warp_tab.png", warp);
        geometry::analysis::writePng(std::string(dump) + "/tradeoff_tab.png", d->render(1));
    }
    ASSERT_GE(results.size(), 5u) << "4 presets + the current settings";
    double ssm = 0, paper = 0;
    for (const auto& p : results) {
        EXPECT_TRUE(std::isfinite(p.x) && p.x > 0) << p.label;
        if (p.preset == "ssm") ssm = p.y;
        if (p.preset == "paper") paper = p.y;
    }
    EXPECT_GT(ssm, paper) << "the uniform map aliases more than the paper's setup";
    // Other axes re-plot the same measurements: memory against edge error (truth is on by default).
    d->dashboard().setTradeoffAxes(ui::charts::TradeoffX::MemoryMiB, ui::charts::TradeoffY::Edge);
    for (const auto& p : d->dashboard().tradeoffResults()) {
        EXPECT_GT(p.x, 0.0) << p.label;
        EXPECT_TRUE(p.y >= 0.0 && p.y <= 1.0) << p.label << ": " << p.y;
    }
}

} // namespace

namespace {

// The Trade-off tab's flicker axis: each configuration walks the chosen path of the scene file and
// reports its world-space flicker.
TEST_F(HeadlessDashboardTest, TradeoffFlickerWalksTheScenePath) {
    const std::string file = ::testing::TempDir() + "plane_with_path.json";
    std::ofstream(file) << R"({"meshes": [{"builtin": "plane"}],
        "paths": {"dolly": {"camera": [{"eye": [0, 7, 16], "target": [0, 0, -2]},
                                        {"eye": [1, 7, 15.4], "target": [1, 0, -2.6]}]}}})";
    options_.scene = file;
    auto d = make();
    (void)d->render(1);
    ui::Dashboard& dash = d->dashboard();
    ASSERT_EQ(dash.scene().file.paths.count("dolly"), 1u);
    dash.setTradeoffAxes(ui::charts::TradeoffX::GpuMs, ui::charts::TradeoffY::Flicker);
    dash.setTradeoffPath("dolly");
    dash.startTradeoffSweep();
    for (int i = 0; i < 20 && dash.tradeoffRunning(); ++i) (void)d->render(1);
    const auto points = dash.tradeoffResults();
    ASSERT_GE(points.size(), 5u);
    double ssm = -1;
    for (const auto& p : points) {
        EXPECT_TRUE(std::isfinite(p.y) && p.y >= 0.0 && p.y <= 1.0) << p.label << ": " << p.y;
        if (p.preset == "ssm") ssm = p.y;
    }
    EXPECT_GT(ssm, 0.0) << "an unsnapped uniform map shimmers along the dolly";
}

// The Views group's "truth samples" reaches the inspection: 2 × 2 rays give fractional coverage.
TEST_F(HeadlessDashboardTest, TruthSamplesReachTheInspection) {
    auto d = make();
    (void)d->render(1);
    ASSERT_NE(d->dashboard().inspection(0), nullptr);
    EXPECT_EQ(d->dashboard().inspection(0)->truthSamples, 1);
    d->dashboard().state().views.truthSamples = 2;
    (void)d->render(1);
    const geometry::analysis::Inspection* in = d->dashboard().inspection(0);
    ASSERT_NE(in, nullptr);
    EXPECT_EQ(in->truthSamples, 2);
    size_t fractional = 0;
    for (size_t i = 0; i < in->coverage.size(); ++i)
        fractional += in->receiver[i] && in->coverage[i] > 0.f && in->coverage[i] < 1.f;
    EXPECT_GT(fractional, 10u);
}

// Recommend runs the tune search on the current view, one measurement per frame, shows the tune
// chart, and its result loads into B for an A/B comparison; a bad target is refused in the status bar.
TEST_F(HeadlessDashboardTest, RecommendFindsSettingsAndAppliesThemToB) {
    auto d = make();
    (void)d->render(1);
    ui::Dashboard& dash = d->dashboard();
    EXPECT_FALSE(dash.startRecommend("speed=1"));
    EXPECT_NE(dash.status().find("--target"), std::string::npos) << dash.status();
    dash.showTab(4);
    const geometry::analysis::Image before = d->render(1);
    const double p95 = dash.inspection(0)->aliasing.p95;
    ASSERT_TRUE(dash.startRecommend("p95=" + std::to_string(p95 * 0.6), 24)); // the filter axis has 5 values
    int frames = 0;
    for (; frames < 40 && dash.recommendRunning(); ++frames) (void)d->render(1);
    EXPECT_FALSE(dash.recommendRunning());
    EXPECT_GE(frames, 12) << "one measurement per frame";
    ASSERT_TRUE(dash.recommendation()) << dash.status();
    EXPECT_NE(dash.status().find("recommended"), std::string::npos) << dash.status();
    const geometry::analysis::Image after = d->render(1);
    const ui::Rect& r = dash.rects().stats;
    EXPECT_GT(differing(before, after, r), size_t(0.05 * r.w * r.h)) << "the tune chart replaces the trade-off chart";
    dash.applyRecommendation(1);
    EXPECT_EQ(dash.state().settings[1].resolution, dash.recommendation()->resolution);
    EXPECT_NE(dash.state().views.compare, ui::CompareMode::Off);
    (void)d->render(2);
    ASSERT_NE(dash.inspection(1), nullptr);
    EXPECT_LE(dash.inspection(1)->aliasing.p95, p95 * 0.6) << "B meets the target on this view";
}

} // namespace

namespace {

/// Rows of the controls panel's first button (the first rows with bright text pixels).
int firstTextHeight(const geometry::analysis::Image& img, const ui::Rect& r) {
    int first = -1, last = -1;
    for (int y = int(r.y); y < int(r.y + r.h * 0.2f); ++y) {
        bool bright = false;
        for (int x = int(r.x); x < int(r.x + r.w * 0.5f) && !bright; ++x) bright = img.at(x, y)[0] > 200;
        if (bright && first < 0) first = y;
        if (!bright && first >= 0) {
            last = y;
            break;
        }
    }
    return first < 0 || last < 0 ? 0 : last - first;
}

TEST_F(HeadlessDashboardTest, HighDpiScaleDoublesTheLayoutAndRasterizesTextLarger) {
    app::RenderOptions o = options_;
    const auto render = [&](float scale, int w, int h) {
        ui::LoadedScene scene = app::loadDashboardScene(o);
        ui::DashboardState state = app::initialDashboardState(scene, o);
        ui::DashboardOptions options = app::dashboardOptions(o);
        options.uiScale = scale;
        ui::HeadlessDashboard d(std::move(scene), state, options, w, h);
        const geometry::analysis::Image img = d.render(2);
        return std::pair{img, d.dashboard().rects()};
    };
    const auto [one, r1] = render(1.f, 960, 600);
    const auto [two, r2] = render(2.f, 1920, 1200);
    EXPECT_FLOAT_EQ(r2.controls.w, 2.f * r1.controls.w);
    EXPECT_FLOAT_EQ(r2.status.h, 2.f * r1.status.h);
    const int h1 = firstTextHeight(one, r1.controls), h2 = firstTextHeight(two, r2.controls);
    ASSERT_GT(h1, 5);
    EXPECT_NEAR(double(h2) / double(h1), 2.0, 0.35) << "the font is rasterized at twice the size, not scaled";
}

} // namespace
