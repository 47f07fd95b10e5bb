// The dashboard's pure parts: layout, image zoom/pan, camera rig, config file, control groups, the
// light list's checks and the light gizmo's projection.
//
// Index: layout · image zoom/pan · camera rig · config file · control groups · drawing only what
// changed (issue 18) · the light list and its gizmo (issue 29)
#include "geometry/shadow/settings.h"
#include "ui/dashboard.h"
#include "ui/dashboard_config.h"
#include "ui/dashboard_layout.h"
#include "ui/header_fit.h"
#include "ui/image_view.h"
#include "ui/light_gizmo.h"
#include "ui/light_list.h"
#include "ui/orbit_camera.h"
#include "ui/pass_inputs.h"
#include "ui/progressive.h"
#include "ui/recent_median.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace ui;
using namespace ui::charts;

namespace {

bool inside(const Rect& inner, const Rect& outer) {
    return inner.x >= outer.x && inner.y >= outer.y && inner.right() <= outer.right() + 1e-3f &&
           inner.bottom() <= outer.bottom() + 1e-3f;
}
bool overlaps(const Rect& a, const Rect& b) {
    return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom() && a.w > 0 && b.w > 0 &&
           a.h > 0 && b.h > 0;
}

} // namespace

TEST(DashboardLayout, PanelsTileTheWindowWithoutOverlap) {
    for (const auto& [w, h, scale] :
         {std::tuple{1600.f, 900.f, 1.f}, {1280.f, 720.f, 1.f}, {3840.f, 2160.f, 2.f}, {640.f, 400.f, 1.f}}) {
        const DashboardRects r = layoutDashboard(w, h, {}, scale);
        const Rect window{0, 0, w, h};
        const std::vector<Rect> panels = {r.controls, r.eye, r.light, r.heatmap, r.stats, r.status};
        for (size_t i = 0; i < panels.size(); ++i) {
            EXPECT_TRUE(inside(panels[i], window)) << i << " at " << w << "x" << h;
            EXPECT_GT(panels[i].w, 0.f) << i;
            EXPECT_GT(panels[i].h, 0.f) << i;
            EXPECT_EQ(panels[i].x, std::floor(panels[i].x)) << "whole pixels";
            for (size_t j = i + 1; j < panels.size(); ++j)
                EXPECT_FALSE(overlaps(panels[i], panels[j])) << i << " " << j;
        }
        EXPECT_FLOAT_EQ(r.status.bottom(), h);
        EXPECT_LE(r.heatmap.right(), w);
        EXPECT_GE(r.heatmap.right(), w - 1.f) << "the views use the full width";
        EXPECT_FLOAT_EQ(r.eye.y, r.light.y);
        EXPECT_FLOAT_EQ(r.eye.h, r.heatmap.h);
    }
}

TEST(DashboardLayout, ScaleGrowsFixedSizes) {
    const DashboardRects a = layoutDashboard(3000, 2000, {}, 1.f), b = layoutDashboard(3000, 2000, {}, 2.f);
    EXPECT_FLOAT_EQ(b.controls.w, 2.f * a.controls.w);
    EXPECT_FLOAT_EQ(b.status.h, 2.f * a.status.h);
}

TEST(DashboardLayout, DegenerateWindowsGiveEmptyRectsNotNaN) {
    for (const auto& [w, h] : {std::pair{0.f, 0.f},
                               {-5.f, 10.f},
                               {std::numeric_limits<float>::quiet_NaN(), 100.f},
                               {1.f, 1.f},
                               {std::numeric_limits<float>::infinity(), 5.f}}) {
        const DashboardRects r = layoutDashboard(w, h, {}, 1.f);
        for (const Rect& p : {r.controls, r.eye, r.light, r.heatmap, r.stats, r.status}) {
            EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.w) && std::isfinite(p.h));
            EXPECT_GE(p.w, 0.f);
            EXPECT_GE(p.h, 0.f);
        }
    }
}

TEST(DashboardLayout, SplittersMoveTheirPanelsAndStayClamped) {
    const LayoutFractions f;
    const DashboardRects before = layoutDashboard(1600, 900, f, 1.f);
    const LayoutFractions g = dragSplitter(f, Splitter::EyeLight, 100.f, 0.f, 1600, 900, 1.f);
    const DashboardRects after = layoutDashboard(1600, 900, g, 1.f);
    EXPECT_NEAR(after.eye.w - before.eye.w, 100.f, 1.5f);
    EXPECT_NEAR(after.light.w - before.light.w, -100.f, 1.5f);
    EXPECT_FLOAT_EQ(after.heatmap.w, before.heatmap.w);
    const LayoutFractions up = dragSplitter(f, Splitter::Stats, 0.f, -50.f, 1600, 900, 1.f);
    EXPECT_GT(layoutDashboard(1600, 900, up, 1.f).stats.h, before.stats.h);
    // Dragging far past the limits keeps every panel usable.
    LayoutFractions far = f;
    for (int i = 0; i < 50; ++i) far = dragSplitter(far, Splitter::EyeLight, 1e4f, 0.f, 1600, 900, 1.f);
    const DashboardRects r = layoutDashboard(1600, 900, far, 1.f);
    EXPECT_GT(r.light.w, 50.f);
    EXPECT_GT(r.heatmap.w, 50.f);
    const LayoutFractions nan = clampFractions({std::nanf(""), std::nanf(""), std::nanf(""), std::nanf("")});
    EXPECT_FLOAT_EQ(nan.eyeEnd, LayoutFractions{}.eyeEnd);
}

TEST(ImageView, FitShowsTheWholeImageCentred) {
    const Rect panel{10, 20, 400, 300};
    const ImagePlacement p = placeImage({}, panel, 800, 400); // 2:1 into 4:3 → letterboxed
    EXPECT_FLOAT_EQ(p.scale, 0.5f);
    EXPECT_FLOAT_EQ(p.screen.w, 400.f);
    EXPECT_FLOAT_EQ(p.screen.h, 200.f);
    EXPECT_FLOAT_EQ(p.screen.y, 20.f + 50.f);
    EXPECT_EQ(p.uvMin, glm::vec2(0.f));
    EXPECT_EQ(p.uvMax, glm::vec2(1.f));
}

TEST(ImageView, PixelUnderTheCursorIsExact) {
    const Rect panel{0, 0, 100, 100};
    ImageView oneToOneView;
    oneToOneView.zoom = 1.f;
    // A 100×100 image at 1:1 fills the panel exactly: screen (x+0.5, y+0.5) is pixel (x, y).
    for (int y : {0, 17, 99})
        for (int x : {0, 42, 99}) {
            const auto px = pixelAt(oneToOneView, panel, 100, 100, {x + 0.5f, y + 0.5f});
            ASSERT_TRUE(px);
            EXPECT_EQ(*px, glm::ivec2(x, y));
        }
    EXPECT_FALSE(pixelAt(oneToOneView, panel, 100, 100, {-1.f, 5.f}));
    EXPECT_FALSE(pixelAt(oneToOneView, panel, 100, 100, {std::nanf(""), 5.f}));
}

TEST(ImageView, ZoomKeepsThePointUnderTheCursor) {
    const Rect panel{50, 50, 320, 240};
    ImageView v;
    const glm::vec2 cursor(100.f, 120.f);
    const auto before = pixelAt(v, panel, 640, 480, cursor);
    ASSERT_TRUE(before);
    for (int i = 0; i < 6; ++i) {
        v = zoomAround(v, panel, 640, 480, cursor, 1.6f);
        const auto after = pixelAt(v, panel, 640, 480, cursor);
        ASSERT_TRUE(after);
        EXPECT_LE(std::abs(after->x - before->x), 1) << "zoom step " << i;
        EXPECT_LE(std::abs(after->y - before->y), 1) << "zoom step " << i;
    }
    EXPECT_GT(v.zoom, 5.f);
    EXPECT_LE(placeImage(v, panel, 640, 480).screen.w, panel.w);
    // Zoom is bounded.
    for (int i = 0; i < 100; ++i) v = zoomAround(v, panel, 640, 480, cursor, 10.f);
    EXPECT_FLOAT_EQ(v.zoom, kMaxZoom);
}

TEST(ImageView, PanMovesTheImageWithTheDrag) {
    const Rect panel{0, 0, 200, 200};
    ImageView v;
    v.zoom = 4.f;
    const auto before = pixelAt(v, panel, 200, 200, {100.f, 100.f});
    v = panBy(v, panel, 200, 200, {40.f, 0.f}); // drag right: the image follows the mouse
    const auto after = pixelAt(v, panel, 200, 200, {140.f, 100.f});
    ASSERT_TRUE(before && after);
    EXPECT_EQ(*before, *after);
    EXPECT_FLOAT_EQ(oneToOne(v).zoom, 1.f);
}

TEST(OrbitCamera, PanFlyAndLookMoveAsNamed) {
    geometry::scene::Camera c;
    c.eye = {0, 0, 10};
    c.target = {0, 0, 0};
    OrbitCamera o = OrbitCamera::from(c);
    EXPECT_NEAR(glm::length(o.eye() - c.eye), 0.f, 1e-4f);
    OrbitCamera panned = o;
    panned.pan(-100.f, 0.f, 500.f, 60.f); // drag left: the scene moves left, the camera right
    EXPECT_GT(panned.target.x, 0.f);
    EXPECT_NEAR(glm::length(panned.eye() - panned.target), o.distance, 1e-4f);
    OrbitCamera flown = o;
    flown.fly(2.f, 0.f, 0.f);
    EXPECT_NEAR(flown.eye().z, 8.f, 1e-4f) << "forward is towards the target";
    OrbitCamera looked = o;
    looked.look(50.f, 0.f);
    EXPECT_NEAR(glm::length(looked.eye() - o.eye()), 0.f, 1e-3f) << "looking keeps the eye";
    EXPECT_GT(glm::length(looked.target - o.target), 0.1f);
    OrbitCamera nan = o;
    nan.rotate(std::nanf(""), std::nanf(""));
    nan.pan(std::nanf(""), 1.f, 0.f, 60.f);
    EXPECT_TRUE(std::isfinite(nan.eye().x));
}

TEST(DashboardConfig, RoundTripsSettingsViewsAndLayout) {
    DashboardState s;
    geometry::shadow::applySetting(s.settings[0], "warp.method", "lispsm");
    geometry::shadow::applySetting(s.settings[1], "filter.kernel", "7");
    s.views.heatmap = HeatmapKind::Truth;
    s.views.compare = CompareMode::Split;
    s.views.splitPosition = 0.25f;
    s.views.truthSamples = 3;
    s.layout.eyeEnd = 0.5f;
    s.flySpeed = 42.f;
    const WindowGeometry win{1234, 777};
    const nlohmann::json j = dashboardToJson(s, win);
    DashboardState back;
    WindowGeometry backWin;
    dashboardFromJson(nlohmann::json::parse(j.dump()), back, backWin);
    EXPECT_EQ(dashboardToJson(back, backWin), j);
    EXPECT_EQ(backWin.width, 1234);
    EXPECT_EQ(back.views.heatmap, HeatmapKind::Truth);
    EXPECT_EQ(back.views.truthSamples, 3);
    EXPECT_FLOAT_EQ(back.layout.eyeEnd, 0.5f);
}

TEST(DashboardConfig, CorruptFilesAreReportedAndChangeNothing) {
    const auto dir = std::filesystem::temp_directory_path() / ("shadowscope_config_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / "dashboard.json";
    DashboardState s;
    WindowGeometry w;
    EXPECT_FALSE(loadDashboardConfig(dir / "missing.json", s, w)) << "no file is not an error";
    const std::vector<std::string> bad = {
        "{not json",
        "[1, 2]",
        R"({"settings": {"warp": {"method": "nonsense"}}})",
        R"({"views": {"heatmap": "rainbow"}})",
        R"({"views": {"truth_samples": 9}})",
        R"({"layout": {"window": [10, 10]}})",
        R"({"layout": {"eye_end": "wide"}})",
        R"({"surprise": 1})",
        std::string("\0\1\2", 3),
    };
    for (const std::string& text : bad) {
        std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
        DashboardState state;
        geometry::shadow::applySetting(state.settings[0], "splits.count", "3");
        WindowGeometry win;
        const auto error = loadDashboardConfig(path, state, win);
        ASSERT_TRUE(error) << text;
        EXPECT_EQ(error->find('\n'), std::string::npos) << "one line";
        EXPECT_EQ(state.settings[0].splits.count, 3) << "nothing applied: " << text;
        EXPECT_EQ(win.width, WindowGeometry{}.width);
    }
    // A good file saves and loads back.
    DashboardState good;
    geometry::shadow::applySetting(good.settings[0], "bias.type", "slope");
    ASSERT_FALSE(saveDashboardConfig(path, good, {800, 600}));
    DashboardState loaded;
    WindowGeometry win;
    ASSERT_FALSE(loadDashboardConfig(path, loaded, win));
    EXPECT_EQ(loaded.settings[0].bias.type, geometry::shadow::BiasType::Slope);
    EXPECT_EQ(win.height, 600);
    std::filesystem::remove_all(dir);
}

TEST(DashboardControls, EverySettingBelongsToAShownGroup) {
    const auto& groups = controlGroups();
    for (const auto& info : geometry::shadow::settingsDeclaration()) {
        const std::string g = settingGroup(info.key);
        EXPECT_NE(std::find(groups.begin(), groups.end(), g), groups.end()) << info.key;
        EXPECT_NE(g, "Views") << info.key << " would be drawn nowhere";
    }
    EXPECT_EQ(settingGroup("filter.kernel"), "Filtering");
    EXPECT_EQ(settingGroup("splits.alpha"), "Partitions");
    EXPECT_EQ(settingGroup("warp.method"), "Warp");
}

// ---- Drawing only what changed (issue 18) ---------------------------------------------------

TEST(Progressive, DecidesWhatASideDraws) {
    using ui::Draw;
    constexpr double pause = ui::kRefinePause;
    EXPECT_EQ(ui::decideDraw(true, true, true, false, 0.0, pause), Draw::Coarse);  // a drag step
    EXPECT_EQ(ui::decideDraw(true, false, true, false, 0.0, 0.0), Draw::Full);     // a typed value, a combo
    EXPECT_EQ(ui::decideDraw(true, false, false, false, 0.0, 0.0), Draw::Coarse);  // … too slow in full: coarse first
    EXPECT_EQ(ui::decideDraw(true, false, true, true, 0.0, 0.0), Draw::Full);      // a discrete change ends a drag
    EXPECT_EQ(ui::decideDraw(false, false, true, true, 0.05, pause), Draw::None);  // coarse, input paused briefly
    EXPECT_EQ(ui::decideDraw(false, true, true, true, 0.15, pause), Draw::Full);   // … long enough: refine
    EXPECT_EQ(ui::decideDraw(false, false, true, true, 0.0, 0.0), Draw::Full);     // after a discrete change: at once
    EXPECT_EQ(ui::decideDraw(false, false, true, true, NAN, pause), Draw::Full);   // unknown pause: refine
    EXPECT_EQ(ui::decideDraw(false, false, true, false, 10.0, pause), Draw::None); // idle
}

TEST(Progressive, FullFrameFitsTheResponseBudget) {
    EXPECT_TRUE(ui::fullFrameFits(NAN, 2, 150.0)); // nothing timed yet
    EXPECT_TRUE(ui::fullFrameFits(70.0, 2, 150.0));
    EXPECT_FALSE(ui::fullFrameFits(80.0, 2, 150.0)); // A/B: both sides count
    EXPECT_FALSE(ui::fullFrameFits(151.0, 1, 150.0));
}

TEST(HeaderFit, ShrinksTheWidgetThenDropsTheZoomTextThenShortensTheTitle) {
    // Light view's row at 1280×720, roughly: title 150, slider 40–90, Fit + 1:1 70, "100%" 35, spacing 8.
    const ui::HeaderItems h{150.f, 60.f, 90.f, 40.f, 70.f, 35.f, 8.f};
    const float full = 150 + 8 + 90 + 8 + 70 + 8 + 35;
    ui::HeaderFit f = ui::fitHeader(h, full);
    EXPECT_TRUE(f.fits && !f.shortTitle && f.zoomText);
    EXPECT_EQ(f.widget, 90.f);
    f = ui::fitHeader(h, full - 30.f); // the slider gives way first
    EXPECT_TRUE(f.fits && !f.shortTitle && f.zoomText);
    EXPECT_EQ(f.widget, 60.f);
    f = ui::fitHeader(h, full - 60.f); // below the slider's minimum: the zoom text goes
    EXPECT_TRUE(f.fits && !f.shortTitle && !f.zoomText);
    EXPECT_EQ(f.widget, 73.f);
    f = ui::fitHeader(h, 200.f); // then the short title
    EXPECT_TRUE(f.fits && f.shortTitle && !f.zoomText);
    EXPECT_EQ(f.widget, 54.f);
    f = ui::fitHeader(h, 100.f); // nothing fits: the most compact row, reported
    EXPECT_FALSE(f.fits);
    EXPECT_TRUE(f.shortTitle && !f.zoomText);
    EXPECT_EQ(f.widget, 40.f);
    EXPECT_FALSE(ui::fitHeader(h, NAN).fits);
    const ui::HeaderItems eye{70.f, 30.f, 0.f, 0.f, 70.f, 35.f, 8.f}; // no widget, no spacing for it
    f = ui::fitHeader(eye, 70 + 8 + 70 + 8 + 35);
    EXPECT_TRUE(f.fits && f.zoomText && !f.shortTitle);
    EXPECT_EQ(f.widget, 0.f);
}

TEST(Progressive, CoarseDivisorFitsTheBudget) {
    EXPECT_EQ(ui::coarseDivisor(NAN, 20.0, 100.0), 2);
    EXPECT_EQ(ui::coarseDivisor(0.0, 20.0, 100.0), 2);
    EXPECT_EQ(ui::coarseDivisor(200.0, 40.0, 100.0), 2); // 40 + 200/4 = 90 ≤ 100
    EXPECT_EQ(ui::coarseDivisor(300.0, 40.0, 100.0), 4); // 40 + 300/4 = 115 > 100
    EXPECT_EQ(ui::coarseDivisor(300.0, NAN, 100.0), 2);  // 0 + 75
}

TEST(RecentMedian, KeepsTheLastValuesAndIgnoresNonFinite) {
    ui::RecentMedian m(3);
    EXPECT_TRUE(std::isnan(m.median()));
    m.add(5.0);
    EXPECT_EQ(m.median(), 5.0);
    m.add(1.0);
    EXPECT_EQ(m.median(), 3.0); // mean of the middle two
    m.add(NAN);
    m.add(INFINITY);
    EXPECT_EQ(m.count(), 2u);
    m.add(100.0); // one cold outlier does not move the median far
    EXPECT_EQ(m.median(), 5.0);
    m.add(2.0); // the oldest (5) drops out
    m.add(3.0); // then 1
    EXPECT_EQ(m.count(), 3u);
    EXPECT_EQ(m.median(), 3.0); // {100, 2, 3}
}

TEST(PassInputs, EveryInputTheViewsDependOnCounts) {
    ui::PassInputs a;
    ui::PassInputs b = a;
    EXPECT_TRUE(a == b);
    b.camera.near *= 2.f;
    EXPECT_FALSE(a == b) << "near/far edits redraw and re-inspect";
    b = a;
    b.camera.up = {0.f, 0.f, 1.f};
    EXPECT_FALSE(a == b);
    b = a;
    b.settings.filter.kernel = 5;
    EXPECT_FALSE(a == b);
    b = a;
    b.size.width += 1;
    EXPECT_FALSE(a == b);
    ui::InspectionInputs i{a, 0}, j{a, 2};
    EXPECT_FALSE(i == j) << "truth samples re-inspect without redrawing";
}

TEST(PassInputs, EveryLightCounts) {
    ui::PassInputs a;
    a.lights = {geometry::scene::Light{}};
    ui::PassInputs b = a;
    b.lights.push_back(ui::defaultSpotLight({}));
    EXPECT_FALSE(a == b) << "an added light redraws";
    b = a;
    b.lights[0].radius = 1.f;
    EXPECT_FALSE(a == b);
    b = a;
    b.inspectedLight = 1;
    EXPECT_FALSE(a == b) << "switching the inspected light redraws and re-inspects";
}

// ---- The light list (issue 29) ---------------------------------------------------------------

TEST(LightList, RefusesWhatSceneFilesRefuse) {
    using geometry::scene::Light;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    Light spot = defaultSpotLight({});
    EXPECT_FALSE(lightProblem(spot));
    EXPECT_FALSE(lightProblem(Light{}));
    const auto with = [&](auto edit) {
        Light l = spot;
        edit(l);
        return lightProblem(l).has_value();
    };
    EXPECT_TRUE(with([](Light& l) { l.coneDeg = 0.f; }));
    EXPECT_TRUE(with([](Light& l) { l.coneDeg = 180.f; }));
    EXPECT_FALSE(with([](Light& l) { l.coneDeg = 179.9f; }));
    EXPECT_TRUE(with([&](Light& l) { l.coneDeg = nan; }));
    EXPECT_TRUE(with([&](Light& l) { l.position.y = nan; }));
    EXPECT_TRUE(with([&](Light& l) { l.position.x = inf; }));
    EXPECT_TRUE(with([&](Light& l) { l.direction.z = nan; }));
    EXPECT_TRUE(with([](Light& l) { l.direction = glm::vec3(0.f); }));
    EXPECT_TRUE(with([](Light& l) { l.range = 0.f; }));
    EXPECT_TRUE(with([&](Light& l) { l.range = inf; }));
    EXPECT_TRUE(with([](Light& l) { l.radius = -0.1f; }));
    EXPECT_FALSE(with([](Light& l) { l.radius = 0.f; }));
    EXPECT_TRUE(lightListProblem({}));
    EXPECT_FALSE(lightListProblem(std::vector<Light>(geometry::scene::kMaxLights)));
    EXPECT_TRUE(lightListProblem(std::vector<Light>(geometry::scene::kMaxLights + 1)));
    std::vector<Light> list(3);
    list[2].range = -1.f;
    const auto problem = lightListProblem(list);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("light 2"), std::string::npos) << *problem;
}

TEST(LightList, AddedSpotLightLooksDownOnTheSceneAndReachesAllOfIt) {
    geometry::scene::Aabb S;
    S.add(glm::vec3(-10.f, 0.f, -20.f));
    S.add(glm::vec3(30.f, 5.f, 20.f));
    const geometry::scene::Light l = defaultSpotLight(S);
    EXPECT_EQ(l.type, geometry::scene::LightType::Spot);
    EXPECT_FLOAT_EQ(l.position.x, 10.f);
    EXPECT_FLOAT_EQ(l.position.z, 0.f);
    EXPECT_GT(l.position.y, 5.f);
    EXPECT_EQ(l.l(), glm::vec3(0.f, -1.f, 0.f));
    for (const glm::vec3 corner : {S.lo, S.hi, glm::vec3(S.lo.x, S.lo.y, S.hi.z), glm::vec3(S.hi.x, S.lo.y, S.lo.z)})
        EXPECT_LE(glm::length(corner - l.position), l.range);
    EXPECT_FALSE(lightProblem(l));
}

TEST(LightGizmo, ProjectsAKnownPointToItsPixel) {
    // Eye on +z looking at the origin, 90° vertical field, a 200 × 100 image (aspect 2): at distance
    // 10 the image spans y ∈ [−10, 10] and x ∈ [−20, 20]. (10, 5, 0) is at ndc (0.5, 0.5): pixel
    // x = (0.5 + 1)/2 · 200 = 150, y = (1 − 0.5)/2 · 100 = 25 (y down).
    geometry::scene::Camera c;
    c.eye = {0.f, 0.f, 10.f};
    c.target = {0.f, 0.f, 0.f};
    c.up = {0.f, 1.f, 0.f};
    c.fovYDeg = 90.f;
    c.near = 0.1f;
    c.far = 100.f;
    const glm::vec2 size{200.f, 100.f};
    const auto centre = projectToImage(c, size, {0.f, 0.f, 0.f});
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->x, 100.f, 1e-3f);
    EXPECT_NEAR(centre->y, 50.f, 1e-3f);
    const auto p = projectToImage(c, size, {10.f, 5.f, 0.f});
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->x, 150.f, 1e-3f);
    EXPECT_NEAR(p->y, 25.f, 1e-3f);
    // Twice as far, half as far from the centre: (10, 5, −10) at distance 20 → (125, 37.5).
    const auto q = projectToImage(c, size, {10.f, 5.f, -10.f});
    ASSERT_TRUE(q);
    EXPECT_NEAR(q->x, 125.f, 1e-3f);
    EXPECT_NEAR(q->y, 37.5f, 1e-3f);
    EXPECT_FALSE(projectToImage(c, size, {0.f, 0.f, 20.f})) << "behind the eye";
    EXPECT_FALSE(projectToImage(c, {0.f, 0.f}, {0.f, 0.f, 0.f})) << "no image";

    // The marks: a spot light at (10, 5, 0) looking down (image +y), a point light, a directional
    // light from the view centre along +x (image +x), one behind the eye.
    std::vector<geometry::scene::Light> lights(4);
    lights[0].type = geometry::scene::LightType::Spot;
    lights[0].position = {10.f, 5.f, 0.f};
    lights[0].direction = {0.f, -1.f, 0.f};
    lights[1].type = geometry::scene::LightType::Point;
    lights[1].position = {0.f, 0.f, 0.f};
    lights[2].direction = {1.f, 0.f, 0.f};
    lights[3].type = geometry::scene::LightType::Point;
    lights[3].position = {0.f, 0.f, 30.f};
    const std::vector<LightMark> marks = lightMarks(c, size, lights, 1);
    ASSERT_EQ(marks.size(), 4u);
    ASSERT_TRUE(marks[0].at && marks[0].direction);
    EXPECT_NEAR(marks[0].at->x, 150.f, 1e-3f);
    EXPECT_NEAR(marks[0].at->y, 25.f, 1e-3f);
    EXPECT_NEAR(marks[0].direction->x, 0.f, 1e-3f);
    EXPECT_NEAR(marks[0].direction->y, 1.f, 1e-3f);
    EXPECT_FALSE(marks[0].inspected);
    EXPECT_TRUE(marks[1].inspected);
    ASSERT_TRUE(marks[1].at);
    EXPECT_FALSE(marks[1].direction) << "a point light has no axis";
    ASSERT_TRUE(marks[2].at && marks[2].direction);
    EXPECT_NEAR(marks[2].at->x, 100.f, 1e-3f);
    EXPECT_NEAR(marks[2].direction->x, 1.f, 1e-3f);
    EXPECT_FALSE(marks[3].at) << "behind the eye: no marker";
    // Seen end-on (along the view): no arrow to draw.
    lights[2].direction = {0.f, 0.f, -1.f};
    EXPECT_FALSE(lightMarks(c, size, lights, 0)[2].direction);
}

TEST(ImageView, ScreenAtIsTheInverseOfPixelAt) {
    const Rect panel{10.f, 20.f, 400.f, 300.f};
    ImageView view;
    view.zoom = 3.f;
    view.centre = {0.3f, 0.6f};
    const auto s = screenAt(view, panel, 160, 90, {40.5f, 50.5f});
    ASSERT_TRUE(s);
    const auto px = pixelAt(view, panel, 160, 90, *s);
    ASSERT_TRUE(px);
    EXPECT_EQ(*px, glm::ivec2(40, 50));
    EXPECT_FALSE(screenAt(view, {0.f, 0.f, 0.f, 0.f}, 160, 90, {0.f, 0.f}));
}

TEST(DashboardConfig, RoundTripsTheLightList) {
    DashboardState s;
    s.lights = {geometry::scene::Light{}, defaultSpotLight({})};
    s.lights[1].coneDeg = 35.f;
    s.lights[1].radius = 0.5f;
    s.inspectedLight = 1;
    s.lightsScene = "platform";
    s.views.lightGizmo = false;
    const nlohmann::json j = dashboardToJson(s, {});
    DashboardState back;
    WindowGeometry win;
    dashboardFromJson(nlohmann::json::parse(j.dump()), back, win);
    EXPECT_TRUE(back.lights == s.lights);
    EXPECT_EQ(back.inspectedLight, 1);
    EXPECT_EQ(back.lightsScene, "platform");
    EXPECT_FALSE(back.views.lightGizmo);
    EXPECT_EQ(dashboardToJson(back, win), j);
    EXPECT_FALSE(dashboardToJson(DashboardState{}, {}).contains("lights")) << "no list: the scene's lights";
}

TEST(DashboardConfig, ABadLightListIsRefusedAndKeepsTheState) {
    const std::string nine = [] {
        std::string list;
        for (int i = 0; i < 9; ++i) list += std::string(i ? ", " : "") + R"({"type": "directional"})";
        return list;
    }();
    const std::vector<std::string> bad = {
        R"({"lights": {"list": [{"type": "spot", "cone_deg": 0}]}})",
        R"({"lights": {"list": [{"type": "spot", "cone_deg": 180}]}})",
        R"({"lights": {"list": [{"type": "point", "range": 0}]}})",
        R"({"lights": {"list": [{"type": "point", "radius": -1}]}})",
        R"({"lights": {"list": [{"direction": [0, 0, 0]}]}})",
        R"({"lights": {"list": [{"position": [0, "up", 0]}]}})",
        R"({"lights": {"list": [{"type": "laser"}]}})",
        R"({"lights": {"list": [{"colour": [1, 1, 1]}]}})",
        R"({"lights": {"list": []}})",
        R"({"lights": {"list": [)" + nine + "]}}",
        R"({"lights": {"list": [{}], "inspected": 1}})",
        R"({"lights": [{}]})",
    };
    for (const std::string& text : bad) {
        DashboardState state;
        state.lights = {defaultSpotLight({})};
        state.views.overlays = false;
        const DashboardState before = state;
        WindowGeometry win;
        try {
            dashboardFromJson(nlohmann::json::parse(text), state, win);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
            EXPECT_NE(std::string(e.what()).find("lights"), std::string::npos) << e.what();
        }
        EXPECT_TRUE(state.lights == before.lights) << text;
        EXPECT_FALSE(state.views.overlays) << text;
    }
}
