// A findable dashboard and documentation screenshots (issue 32, items 5 and 6), headless (OSMesa):
// settings that do not apply are greyed, and changing one while it does not apply changes no pixel
// (checked for every row's `when` against the renderer and planner); double-click fits the camera,
// shift+click pins; F1 and "?" open the help with every gesture; the file browser opens at a folder
// and loads the file chosen; each F12 writes a new folder; an export is the size asked for and its
// eye view is the same PNG as `shadowscope render`.
//
// Index: applicability of every setting · the dashboard's widgets (greyed, A/B names, gestures,
// help, browser) · screenshots and exports
#include "app/dashboard_setup.h"
#include "app/render_command.h"
#include "app/render_options.h"
#include "dashboard_test_util.h"
#include "geometry/analysis/view_images.h"
#include "renderer/context.h"
#include "renderer/plan_frame.h"
#include "temp_dir_test_util.h"
#include "ui/dashboard_headless.h"
#include "ui/gesture_table.h"
#include "ui/widget_map.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <set>

namespace {

namespace fs = std::filesystem;
using geometry::analysis::Image;
using geometry::shadow::SettingInfo;
using geometry::shadow::ShadowSettings;

// ---- applicability of every setting --------------------------------------------------------------

/// Values of the governing setting to try: every choice, both flags, the first few integers.
std::vector<double> governingValues(const SettingInfo& g) {
    std::vector<double> v;
    if (g.kind == SettingInfo::Kind::Float) return {g.min, g.max};
    const double last = g.kind == SettingInfo::Kind::Int ? std::min(g.max, g.min + 3) : g.max;
    for (double x = g.min; x <= last; ++x) v.push_back(x);
    return v;
}

/// Another valid value of `info` than the one `s` holds.
double otherValue(const SettingInfo& info, const ShadowSettings& s) {
    const double now = info.get(s);
    switch (info.kind) {
    case SettingInfo::Kind::Bool: return now != 0.0 ? 0.0 : 1.0;
    case SettingInfo::Kind::Choice: return now + 1 <= info.max ? now + 1 : 0;
    case SettingInfo::Kind::Int: {
        double v = now != info.max ? info.max : info.min;
        if (info.odd && int(v) % 2 == 0) v -= 1;
        return v;
    }
    case SettingInfo::Kind::Float: return now != info.max ? info.max : info.min;
    }
    return now;
}

class SettingApplicability : public ::testing::Test {
protected:
    static constexpr int kW = 64, kH = 48;
    void SetUp() override {
        context_ = renderer::createOSMesaContext();
        app::RenderOptions o;
        o.scene = "plane";
        scene_ = app::loadScene(o);
        renderer_ = std::make_unique<renderer::Renderer>(scene_);
        lights_.push_back(scene_.lights.at(0));
        geometry::scene::Light spot; // as plane_lights.json's, without per-light settings
        spot.type = geometry::scene::LightType::Spot;
        spot.position = {-6.f, 10.f, 1.f};
        spot.direction = {6.f, -10.f, -1.f};
        spot.coneDeg = 100.f;
        spot.range = 60.f;
        lights_.push_back(spot);
        geometry::scene::Light point;
        point.type = geometry::scene::LightType::Point;
        point.position = {2.f, 3.f, 3.f};
        point.range = 40.f;
        point.radius = 0.1f;
        lights_.push_back(point);
    }
    /// The eye and light views of `s` under light `light`, concatenated.
    std::vector<uint8_t> draw(const ShadowSettings& s, size_t light) {
        const geometry::shadow::ShadowPlan plan =
            renderer::planFrame(*renderer_, s, scene_.bounds(), scene_.camera, lights_[light], {kW, kH});
        renderer::ViewOptions v;
        v.lightViewSize = 48;
        v.lightSplit = int(plan.splits.size()) - 1; // the last split: where a split setting shows most
        renderer_->render(plan, {kW, kH}, v);
        std::vector<uint8_t> pixels = renderer_->readEye().rgba;
        const Image view = renderer_->readLight();
        pixels.insert(pixels.end(), view.rgba.begin(), view.rgba.end());
        return pixels;
    }
    std::unique_ptr<renderer::GlContext> context_;
    geometry::scene::Scene scene_;
    std::unique_ptr<renderer::Renderer> renderer_;
    std::vector<geometry::scene::Light> lights_;
};

// Every row with a `when`: under each value of the governing setting that makes it inert (and with
// 1 or 3 splits), changing it to another valid value leaves every pixel of the eye and light views
// as it was, under a directional, a spot and a point light. A row whose predicate claims too much
// (a setting the shaders or the planner still read) fails here, naming the state.
TEST_F(SettingApplicability, ASettingThatDoesNotApplyChangesNoPixel) {
    int checked = 0;
    for (const SettingInfo& row : geometry::shadow::settingsDeclaration()) {
        if (!row.appliesWhen) continue;
        const SettingInfo* governing = geometry::shadow::findSetting(row.governedBy);
        ASSERT_NE(governing, nullptr) << row.key << " is governed by an unknown key " << row.governedBy;
        std::set<std::vector<double>> seen;
        int inertStates = 0;
        for (const int splits : {1, 3})
            for (const double g : governingValues(*governing)) {
                ShadowSettings s;
                s.resolution = 128;
                s.splits.count = splits;
                governing->set(s, g);
                if (row.appliesTo(s)) continue;
                ++inertStates;
                ShadowSettings changed = s;
                row.set(changed, otherValue(row, s));
                ASSERT_FALSE(row.appliesTo(changed)) << row.key;
                for (size_t light = 0; light < lights_.size(); ++light) {
                    if (!seen.insert({double(splits), g, double(light)}).second) continue;
                    const std::vector<uint8_t> a = draw(s, light), b = draw(changed, light);
                    ++checked;
                    EXPECT_TRUE(a == b) << row.key << " = " << row.format(changed) << " (was " << row.format(s)
                                        << ") changed the picture, though it does not apply with " << row.governedBy
                                        << " = " << governing->format(s) << ", splits.count = " << splits << ", light "
                                        << light;
                }
            }
        EXPECT_GT(inertStates, 0) << row.key << ": no tried state makes it inert";
    }
    EXPECT_GT(checked, 60);
}

// The example: bias.constant under slope_normal_offset.
TEST(SettingApplicabilityRows, BiasConstantAppliesOnlyToTheConstantBias) {
    const SettingInfo* row = geometry::shadow::findSetting("bias.constant");
    ASSERT_NE(row, nullptr);
    ShadowSettings s;
    for (const auto& e : geometry::shadow::kEnumEntries<geometry::shadow::BiasType>) {
        s.bias.type = e.value;
        EXPECT_EQ(row->appliesTo(s), e.value == geometry::shadow::BiasType::Constant) << e.name;
    }
}

// ---- the dashboard's widgets ---------------------------------------------------------------------

class DashboardFindable : public testutil::TempDirTest {
protected:
    static constexpr int kW = 960, kH = 600;
    DashboardFindable() : TempDirTest("shadowscope_findable_") {}
    void SetUp() override {
        TempDirTest::SetUp();
        ui::widgetMapCapture(true);
        context_ = renderer::createOSMesaContext();
        options_.scene = "plane";
        options_.size = {kW, kH};
        options_.out = (dir / "shots").string();
        geometry::shadow::applyAssignment(options_.settings, "shadow_map.resolution=512");
        ui::LoadedScene scene = app::loadDashboardScene(options_);
        state_ = app::initialDashboardState(scene, options_);
        ui::DashboardOptions options = app::dashboardOptions(options_);
        options.clock = [this] { return clock_; };
        d_ = std::make_unique<ui::HeadlessDashboard>(std::move(scene), state_, std::move(options), kW, kH);
        (void)d_->render(1);
    }
    void TearDown() override {
        d_.reset();
        ui::widgetMapCapture(false);
        TempDirTest::TearDown();
    }
    ui::Dashboard& dash() { return d_->dashboard(); }
    static nlohmann::json map() { return nlohmann::json::parse(ui::widgetMapLast()); }
    static bool has(const std::string& id) { return map()["widgets"].contains(id); }
    static bool disabled(const std::string& id) {
        const nlohmann::json m = map();
        if (!m.contains("disabled")) return false;
        for (const auto& d : m["disabled"])
            if (d == id) return true;
        return false;
    }
    static glm::vec2 centre(const std::string& id) {
        const nlohmann::json r = map()["widgets"].at(id);
        return {r[0].get<float>() + r[2].get<float>() * 0.5f, r[1].get<float>() + r[3].get<float>() * 0.5f};
    }
    glm::vec2 eyeCentre() {
        const ui::Rect& r = dash().rects().eye;
        return {r.x + r.w * 0.5f, r.y + r.h * 0.6f};
    }
    void click(glm::vec2 p) {
        d_->step({p, {true, false, false}, 0.f});
        d_->step({p, {false, false, false}, 0.f});
    }
    void click(const std::string& id) {
        ASSERT_TRUE(has(id)) << id << " is not in the widget map";
        click(centre(id));
    }
    /// Lets ImGui's clock pass the double-click time, so that the next click is a single one.
    void pause() {
        for (int i = 0; i < 25; ++i) d_->step({});
    }
    /// Scrolls the controls panel until `id` is in the widget map (recorded only while visible).
    void scrollTo(const std::string& id) {
        const ui::Rect& c = dash().rects().controls;
        const glm::vec2 over{c.x + c.w * 0.5f, c.y + c.h * 0.5f};
        for (int i = 0; i < 60 && !has(id); ++i) d_->step({over, {}, i < 30 ? -2.f : 2.f});
        d_->step({over});
        ASSERT_TRUE(has(id)) << id << " never came into view";
    }
    /// SHADOWSCOPE_TEST_DUMP=DIR: the last frame as DIR/NAME.png, for looking at by hand.
    void dump(const std::string& name) {
        if (const char* to = std::getenv("SHADOWSCOPE_TEST_DUMP"))
            geometry::analysis::writePng(std::string(to) + "/" + name + ".png", d_->image());
    }
    void key(int index) {
        ImGui::GetIO().KeysDown[index] = true;
        d_->step({});
        ImGui::GetIO().KeysDown[index] = false;
        d_->step({});
    }
    app::RenderOptions options_;
    ui::DashboardState state_;
    std::unique_ptr<renderer::GlContext> context_;
    std::unique_ptr<ui::HeadlessDashboard> d_;
    double clock_ = 0;
};

TEST_F(DashboardFindable, ASettingThatDoesNotApplyIsGreyed) {
    dash().state().settings[0].bias.type = geometry::shadow::BiasType::SlopeNormalOffset;
    d_->step({});
    scrollTo("bias.constant");
    EXPECT_TRUE(disabled("bias.constant")) << map().dump();
    scrollTo("bias.slope"); // the widget map lists the rows on screen
    EXPECT_FALSE(disabled("bias.slope"));
    EXPECT_FALSE(disabled("bias.normal_offset"));
    scrollTo("bias.z_max");
    EXPECT_TRUE(disabled("bias.z_max"));
    scrollTo("bias.constant");
    // A click on the greyed slider changes nothing.
    const float before = dash().state().settings[0].bias.constant;
    click("bias.constant");
    EXPECT_EQ(dash().state().settings[0].bias.constant, before);
    dash().state().settings[0].bias.type = geometry::shadow::BiasType::Constant;
    d_->step({});
    EXPECT_FALSE(disabled("bias.constant"));
    scrollTo("bias.slope");
    EXPECT_TRUE(disabled("bias.slope"));
}

TEST_F(DashboardFindable, EveryViewNamesTheSideItShowsWhileComparing) {
    d_->step({});
    EXPECT_FALSE(has("light.side=A"));
    EXPECT_FALSE(has("heatmap.side=A"));
    // The compare switch and the side being edited sit together, above the settings groups.
    scrollTo("views.compare");
    dash().state().views.compare = ui::CompareMode::SideBySide;
    d_->step({});
    d_->step({});
    EXPECT_TRUE(has("light.side=A"));
    EXPECT_TRUE(has("heatmap.side=A"));
    ASSERT_TRUE(has("edit.b")) << map()["widgets"].dump();
    const float compareY = centre("views.compare").y, editY = centre("edit.b").y;
    EXPECT_GT(editY, compareY);
    EXPECT_LT(editY - compareY, 3.f * ImGui::GetFrameHeightWithSpacing()) << "the switch is next to A/B compare";
    click("edit.b");
    d_->step({});
    EXPECT_EQ(dash().state().editing, 1);
    EXPECT_TRUE(has("light.side=B"));
    EXPECT_TRUE(has("heatmap.side=B"));
    EXPECT_TRUE(has("eye_image_b"));
    dump("compare_b");
}

TEST_F(DashboardFindable, DoubleClickFitsTheCameraAndPinsNothing) {
    // Somewhere else first: orbit and dolly away.
    glm::vec2 p = eyeCentre();
    d_->step({p, {true, false, false}, 0.f});
    for (int i = 0; i < 4; ++i) d_->step({p += glm::vec2(20.f, 5.f), {true, false, false}, 0.f});
    d_->step({p, {false, false, false}, 0.f});
    d_->step({p, {}, -5.f});
    clock_ += 1.0;
    (void)d_->render(1);
    pause();
    ui::OrbitCamera expected = dash().state().camera;
    const Image eye = dash().eyeImage(0);
    expected.fit(ui::fitBounds(dash().scene().file.scene), dash().scene().file.scene.camera.fovYDeg,
                 float(eye.width) / float(eye.height));
    ASSERT_GT(std::abs(expected.distance - dash().state().camera.distance), 1e-3f) << "already fitted";
    p = eyeCentre();
    click(p);
    click(p);
    const ui::OrbitCamera& c = dash().state().camera;
    EXPECT_FLOAT_EQ(c.distance, expected.distance);
    EXPECT_EQ(c.target, expected.target);
    EXPECT_FLOAT_EQ(c.yawDeg, expected.yawDeg);
    EXPECT_FLOAT_EQ(c.pitchDeg, expected.pitchDeg);
    EXPECT_FALSE(dash().pinnedPixel()) << "neither click of a double-click pins";
    // The next frame draws the fitted view.
    clock_ += 1.0;
    (void)d_->render(1);
    EXPECT_EQ(dash().plan(0).eye, c.eye());
}

TEST_F(DashboardFindable, ShiftClickPinsAndAPlainClickDoesNot) {
    const glm::vec2 p = eyeCentre();
    click(p);
    EXPECT_FALSE(dash().pinnedPixel());
    pause();
    ImGui::GetIO().KeyShift = true;
    click(p);
    ImGui::GetIO().KeyShift = false;
    ASSERT_TRUE(dash().pinnedPixel());
    EXPECT_EQ(dash().pinnedPixel()->panel, ui::ViewPanel::Eye);
    // On the heatmap too.
    pause();
    const ui::Rect& h = dash().rects().heatmap;
    ImGui::GetIO().KeyShift = true;
    click(glm::vec2(h.x + h.w * 0.5f, h.y + h.h * 0.6f));
    ImGui::GetIO().KeyShift = false;
    ASSERT_TRUE(dash().pinnedPixel());
    EXPECT_EQ(dash().pinnedPixel()->panel, ui::ViewPanel::Heatmap);
}

TEST_F(DashboardFindable, F1AndTheHelpButtonShowEveryGesture) {
    EXPECT_FALSE(dash().helpOpen());
    key(ui::kHelpKeyIndex);
    ASSERT_TRUE(dash().helpOpen());
    d_->step({});
    dump("help_overlay");
    const nlohmann::json widgets = map()["widgets"];
    ASSERT_TRUE(widgets.contains("help"));
    for (const ui::Gesture& g : ui::gestureTable()) {
        const std::string id = "help:" + std::string(g.where) + ":" + std::string(g.input);
        ASSERT_TRUE(widgets.contains(id)) << id << " is not shown";
        // Inside the overlay, not clipped away.
        const auto& r = widgets[id];
        const auto& o = widgets["help"];
        EXPECT_GE(r[1].get<float>(), o[1].get<float>()) << id;
        EXPECT_LE(r[1].get<float>() + r[3].get<float>(), o[1].get<float>() + o[3].get<float>()) << id;
    }
    key(ui::kHelpKeyIndex);
    EXPECT_FALSE(dash().helpOpen());
    d_->step({});
    EXPECT_FALSE(has("help"));
    click("help_button");
    EXPECT_TRUE(dash().helpOpen());
}

TEST_F(DashboardFindable, TheFileBrowserListsModelsAndLoadsTheOneChosen) {
    const fs::path models = dir / "models";
    fs::create_directories(models / "sub");
    {
        std::ofstream obj(models / "tri.obj");
        obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n";
    }
    write("models/readme.txt", "not a model");
    click("scene.browse");
    d_->step({});
    ASSERT_TRUE(dash().fileBrowser().isOpen());
    EXPECT_TRUE(has("browser.path"));
    EXPECT_TRUE(has("browser.up"));
    // The button opens at the current folder (the field holds a built-in name); ours, as Return on a
    // typed folder would.
    dash().openFileBrowser(models);
    d_->step({});
    d_->step({});
    EXPECT_EQ(dash().fileBrowser().folder(), models);
    EXPECT_TRUE(has("browser.entry=sub"));
    EXPECT_TRUE(has("browser.entry=tri.obj"));
    EXPECT_FALSE(has("browser.entry=readme.txt"));
    dump("file_browser");
    const glm::vec2 entry = centre("browser.entry=tri.obj");
    click(entry);
    click(entry); // double-click: chosen
    EXPECT_FALSE(dash().fileBrowser().isOpen());
    for (int i = 0; i < 400 && dash().scene().source == "plane"; ++i) d_->step({});
    EXPECT_EQ(dash().scene().source, (models / "tri.obj").lexically_normal().string()) << dash().status();
    ASSERT_FALSE(dash().state().recentFiles.empty());
    EXPECT_EQ(dash().state().recentFiles.front(), fs::absolute(models / "tri.obj").lexically_normal().string());
}

// ---- screenshots and exports ---------------------------------------------------------------------

TEST_F(DashboardFindable, TwoScreenshotsGoToTwoFoldersAndBothStay) {
    click("screenshot");
    ASSERT_TRUE(dash().screenshotRequested());
    const std::vector<std::string> first = dash().saveScreenshots(d_->image());
    d_->step({});
    const std::vector<std::string> second = dash().saveScreenshots(d_->image());
    ASSERT_EQ(first.size(), 4u);
    ASSERT_EQ(second.size(), 4u);
    const fs::path a = fs::path(first[0]).parent_path(), b = fs::path(second[0]).parent_path();
    EXPECT_NE(a, b);
    EXPECT_EQ(a.filename(), "001");
    EXPECT_EQ(b.filename(), "002");
    for (const auto& p : first) EXPECT_TRUE(fs::exists(p)) << p;
    for (const auto& p : second) EXPECT_TRUE(fs::exists(p)) << p;
    for (const char* name : {"eye.png", "light.png", "heatmap.png", "dashboard.png"}) {
        EXPECT_TRUE(fs::exists(a / name)) << name;
        EXPECT_TRUE(fs::exists(b / name)) << name;
    }
    EXPECT_NE(dash().status().find(b.string()), std::string::npos) << dash().status();
}

// The export's eye view is `shadowscope render --views eye` of the same state at the same size.
TEST_F(DashboardFindable, AnEyeExportIsTheHeadlessRenderAtThatSize) {
    const auto path = dash().exportView({ui::ExportView::EyeA, 1920, 1080});
    ASSERT_TRUE(path) << dash().status();
    const Image exported = geometry::analysis::readImageFile(*path);
    EXPECT_EQ(exported.width, 1920);
    EXPECT_EQ(exported.height, 1080);
    EXPECT_EQ(fs::path(*path).filename(), "eye_a_1920x1080.png");
    EXPECT_EQ(fs::path(*path).parent_path().filename(), "001");
    // The command line's render of that state: the dashboard's camera and lights, the settings.
    geometry::scene::Scene scene = dash().scene().file.scene;
    dash().state().camera.applyTo(scene.camera);
    scene.lights = dash().lights();
    app::RenderOptions o = options_;
    o.size = {1920, 1080};
    o.backend = "osmesa";
    o.out = (dir / "render").string();
    app::ExportOptions e;
    e.views = {"eye"};
    (void)app::renderInto(std::move(scene), o, e);
    context_->makeCurrent(); // render made its own context
    const Image rendered = geometry::analysis::readImageFile((dir / "render" / "eye.png").string());
    ASSERT_EQ(rendered.width, 1920);
    ASSERT_EQ(rendered.height, 1080);
    size_t differing = 0;
    for (size_t i = 0; i < rendered.rgba.size(); ++i) differing += rendered.rgba[i] != exported.rgba[i];
    EXPECT_EQ(differing, 0u) << "bytes differ between the export and `render --views eye`";
}

TEST_F(DashboardFindable, TheExportDialogWritesTheViewAtTheSizeChosen) {
    click("export");
    d_->step({});
    ASSERT_TRUE(dash().exportDialogOpen());
    click("export.view=light");
    click("export.size=0"); // 1920x1080
    dump("export_dialog");
    click("export.go");
    EXPECT_FALSE(dash().exportDialogOpen());
    d_->step({}); // the export is drawn at the start of the next frame
    const std::string status = dash().status();
    ASSERT_EQ(status.rfind("exported ", 0), 0u) << status;
    const Image light = geometry::analysis::readImageFile(status.substr(9));
    EXPECT_EQ(light.width, 1920);
    EXPECT_EQ(light.height, 1080);
    // A size outside the limits is refused with a reason, and nothing is written.
    EXPECT_FALSE(dash().exportView({ui::ExportView::EyeA, 9000, 100}));
    EXPECT_NE(dash().status().find("outside"), std::string::npos) << dash().status();
}

TEST_F(DashboardFindable, ADashboardExportIsTheHeadlessDashboardAtThatSize) {
    const auto path = dash().exportView({ui::ExportView::Dashboard, 640, 400});
    ASSERT_TRUE(path) << dash().status();
    const Image exported = geometry::analysis::readImageFile(*path);
    ASSERT_EQ(exported.width, 640);
    ASSERT_EQ(exported.height, 400);
    d_->step({}); // the window's dashboard goes on drawing in its own context
    EXPECT_TRUE(has("screenshot"));
    ui::LoadedScene scene = app::loadDashboardScene(options_);
    ui::DashboardOptions options = app::dashboardOptions(options_);
    options.clock = [this] { return clock_; };
    ui::HeadlessDashboard other(std::move(scene), dash().state(), std::move(options), 640, 400);
    const Image direct = other.render();
    const ui::DashboardRects& r = other.dashboard().rects();
    for (const ui::Rect& rect : {r.eye, r.light, r.heatmap, r.controls})
        EXPECT_EQ(testutil::differing(direct, exported, rect), 0u) << "deterministic panels (stats hold live timings)";
}

} // namespace
