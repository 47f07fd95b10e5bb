#include "dashboard.h"

#include "geometry/analysis/view_images.h"
#include "geometry/io/preset.h"
#include "geometry/shadow/shadow_plan.h"
#include "renderer/plan_frame.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace ui {

const std::vector<std::string>& controlGroups() {
    static const std::vector<std::string> groups = {"Scene", "Camera & light", "Warp", "Partitions",
                                                    "Bias",  "Filtering",      "Views"};
    return groups;
}

std::string settingGroup(std::string_view key) {
    if (key.starts_with("warp.") || key.starts_with("shadow_map.") || key.starts_with("stabilize.")) return "Warp";
    if (key.starts_with("splits.") || key.starts_with("focus.") || key.starts_with("casters.")) return "Partitions";
    if (key.starts_with("bias.")) return "Bias";
    if (key.starts_with("filter.")) return "Filtering";
    return "Views";
}

Dashboard::Dashboard(LoadedScene scene, DashboardState state, DashboardOptions options)
    : scene_(std::move(scene)), state_(std::move(state)), options_(std::move(options)) {
    sides_[0].renderer = std::make_unique<renderer::Renderer>(scene_.file.scene);
    scenePath_ = scene_.source;
    viewChoice_ = options_.view;
    upAxis_ = options_.up;
}

Dashboard::~Dashboard() { cancelCasterLod(); }

const geometry::analysis::Inspection* Dashboard::inspection(int side) const noexcept {
    return sides_[side].inspection ? &*sides_[side].inspection : nullptr;
}

void Dashboard::loadScene(const std::string& nameOrPath) {
    if (!loader_.start(nameOrPath, upAxis_)) status_ = "a scene is still loading";
    else status_ = "loading " + nameOrPath + " …";
}

void Dashboard::pollSceneLoad() {
    std::optional<SceneLoadResult> done = loader_.poll();
    if (!done) return;
    if (auto* error = std::get_if<std::string>(&*done)) {
        status_ = "scene not loaded (the previous one stays): " + *error;
        return;
    }
    adoptScene(std::move(std::get<LoadedScene>(*done)));
}

void Dashboard::adoptScene(LoadedScene loaded) {
    cancelCasterLod(); // its build reads the scene being replaced
    scene_ = std::move(loaded);
    for (Side& s : sides_)
        if (s.renderer) s.renderer->setScene(scene_.file.scene);
    state_.camera = OrbitCamera::from(scene_.file.scene.camera);
    state_.sun = SunAngles::from(scene_.file.scene.light.direction);
    ++sceneGeneration_;
    viewChoice_.clear();
    hovered_.reset();
    pinned_.reset();
    status_ = "loaded " + scene_.source + " (" + std::to_string(scene_.file.scene.triangleCount()) + " triangles)";
}

namespace {

Rect contentArea(const Rect& panel, float header, float pad) noexcept {
    return {panel.x + pad, panel.y + header, std::max(0.f, panel.w - 2.f * pad), std::max(0.f, panel.h - header - pad)};
}

/// Exact text of the values a frame depends on, so a change anywhere re-inspects.
std::string frameKey(const geometry::shadow::ShadowSettings& s, const geometry::scene::Scene& scene,
                     geometry::shadow::Viewport size, int truthSamples, int generation) {
    std::ostringstream k;
    k << geometry::io::settingsToJson(s).dump() << '|' << std::hexfloat << scene.camera.eye.x << ','
      << scene.camera.eye.y << ',' << scene.camera.eye.z << ',' << scene.camera.target.x << ',' << scene.camera.target.y
      << ',' << scene.camera.target.z << ',' << scene.light.direction.x << ',' << scene.light.direction.y << ','
      << scene.light.direction.z << '|' << size.width << 'x' << size.height << '|' << truthSamples << '|' << generation;
    return k.str();
}

geometry::analysis::Image placeholder(int w, int h) {
    geometry::analysis::Image img;
    img.width = std::max(w, 1);
    img.height = std::max(h, 1);
    img.rgba.assign(size_t(img.width) * img.height * 4, 38);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
    return img;
}

} // namespace

void Dashboard::frame(float width, float height, const FrameInput& input) {
    const auto t0 = std::chrono::steady_clock::now();
    screenshotRequested_ = input.screenshot;
    pollSceneLoad();
    rects_ = layoutDashboard(width, height, state_.layout, options_.uiScale);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float pad = style.WindowPadding.x;
    const float header = pad + ImGui::GetFrameHeight() + style.ItemSpacing.y;
    eyeArea_ = contentArea(rects_.eye, header, pad);
    lightArea_ = contentArea(rects_.light, header, pad);
    heatmapArea_ = contentArea(rects_.heatmap, header, pad);
    lightViewSize_ = std::clamp(int(std::min(lightArea_.w, lightArea_.h)), 16, 2048);

    stepCasterLod();
    renderViews(input);
    stepTradeoffSweep();
    stepRecommend();
    updateInspection();
    updateHeatmap();

    widgetMapBeginFrame(width, height);
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(std::max(width, 1.f), std::max(height, 1.f)));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.f);
    ImGui::Begin("##dashboard", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar(2);
    if (width >= 1.f && height >= 1.f) {
        drawControlsPanel();
        drawEyePanel();
        drawLightPanel();
        drawHeatmapPanel();
        drawStatsPanel();
        drawSplitters(width, height);
        drawStatusBar();
    }
    ImGui::End();
    widgetMapEndFrame();
    cpuFrameMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void Dashboard::renderViews(const FrameInput& input) {
    geometry::scene::Scene& scene = scene_.file.scene;
    if (flyLooking_ && glm::length(input.fly) > 0.f) {
        const float step = state_.flySpeed * std::clamp(input.deltaSeconds, 0.f, 0.25f);
        state_.camera.fly(input.fly.z * step, input.fly.x * step, input.fly.y * step);
    }
    state_.camera.applyTo(scene.camera);
    scene.light.direction = state_.sun.direction();

    const bool sideBySide = state_.views.compare == CompareMode::SideBySide;
    geometry::shadow::Viewport size{int(sideBySide ? std::floor((eyeArea_.w - 2.f) * 0.5f) : eyeArea_.w),
                                    int(eyeArea_.h)};
    size.width = std::max(size.width, 16);
    size.height = std::max(size.height, 16);
    const int sides = comparing() ? 2 : 1;
    for (int i = 0; i < sides; ++i) {
        Side& side = sides_[i];
        if (!side.renderer) side.renderer = std::make_unique<renderer::Renderer>(scene);
        giveCasterLod(*side.renderer);
        try {
            const auto p0 = std::chrono::steady_clock::now();
            side.plan = renderer::planFrame(*side.renderer, state_.settings[i], scene.bounds(), scene.camera,
                                            scene.light, size);
            side.planMicroseconds =
                std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - p0).count();
            renderer::ViewOptions v;
            v.lightViewSize = lightViewSize_;
            v.lightSplit = std::clamp(state_.views.lightSplit, 0, std::max(0, int(side.plan.splits.size()) - 1));
            v.overlays = state_.views.overlays;
            v.unwarped = state_.views.unwarped && i == shownSide();
            side.renderer->render(side.plan, size, v);
            side.size = size;
        } catch (const std::exception& e) {
            status_ = std::string(i ? "B: " : "") + e.what();
        }
    }
}

void Dashboard::updateInspection() {
    const int sides = comparing() ? 2 : 1;
    for (int i = 0; i < sides; ++i) {
        Side& side = sides_[i];
        if (!side.renderer || side.size.width <= 0) continue;
        const std::string key = frameKey(state_.settings[i], scene_.file.scene, side.size,
                                         state_.views.truth ? state_.views.truthSamples : 0, sceneGeneration_);
        if (key == side.inspectedKey && side.inspection) continue;
        try {
            side.inspection =
                renderer::inspect(*side.renderer, side.plan, state_.views.truth ? scene_.truth.get() : nullptr,
                                  state_.views.truthSamples);
            side.eye = side.renderer->readEye();
            side.inspectedKey = key;
        } catch (const std::exception& e) {
            status_ = std::string("inspection failed: ") + e.what();
            side.inspection.reset();
        }
    }
}

void Dashboard::updateHeatmap() {
    const ViewSettings& v = state_.views;
    const int s = shownSide();
    std::ostringstream k;
    k << sides_[0].inspectedKey << '|' << (comparing() ? sides_[1].inspectedKey : "") << '|' << s << '|'
      << heatmapName(v.heatmap) << '|' << v.heatmapBlend << '|' << v.texelGrid;
    if (k.str() == heatmapKey_) return;
    heatmapKey_ = k.str();
    const Side& side = sides_[s];
    geometry::analysis::Image img;
    try {
        if (!side.inspection) {
            img = placeholder(side.size.width, side.size.height);
        } else {
            const geometry::analysis::Inspection& in = *side.inspection;
            switch (v.heatmap) {
            case HeatmapKind::Aliasing: img = geometry::analysis::aliasingView(in, side.eye, v.heatmapBlend); break;
            case HeatmapKind::Truth:
                img = in.occluded ? geometry::analysis::truthView(in, side.eye, v.heatmapBlend)
                                  : placeholder(in.width, in.height);
                break;
            case HeatmapKind::Splits: img = geometry::analysis::splitsView(side.eye, in, side.plan); break;
            case HeatmapKind::Texels:
                img = geometry::analysis::texelsView(side.eye, in, std::max(1, v.texelGrid));
                break;
            case HeatmapKind::Difference:
                img = comparing() && sides_[0].inspection && sides_[1].inspection &&
                              sides_[0].inspection->width == sides_[1].inspection->width &&
                              sides_[0].inspection->height == sides_[1].inspection->height
                          ? geometry::analysis::differenceView(*sides_[0].inspection, *sides_[1].inspection)
                          : placeholder(in.width, in.height);
                break;
            case HeatmapKind::Count: img = placeholder(in.width, in.height); break;
            }
        }
    } catch (const std::exception& e) {
        status_ = std::string("heatmap: ") + e.what();
        img = placeholder(side.size.width, side.size.height);
    }
    heatmapImage_ = std::move(img);
    heatmap_.upload(heatmapImage_);
}

geometry::analysis::Image Dashboard::eyeImage(int side) const {
    return sides_[side].renderer ? sides_[side].renderer->readEye() : geometry::analysis::Image{};
}

geometry::analysis::Image Dashboard::lightImage() const {
    const auto& r = sides_[shownSide()].renderer;
    if (!r) return {};
    return state_.views.unwarped ? r->readUnwarpedLight() : r->readLight();
}

geometry::analysis::Image Dashboard::heatmapImage() const { return heatmapImage_; }

std::vector<std::string> Dashboard::saveScreenshots(const geometry::analysis::Image& dashboard) {
    std::vector<std::string> written;
    try {
        const std::filesystem::path dir = options_.screenshotDir;
        std::filesystem::create_directories(dir);
        const auto save = [&](const char* name, const geometry::analysis::Image& img) {
            if (img.width <= 0 || img.height <= 0) return;
            const std::string path = (dir / name).string();
            geometry::analysis::writePng(path, img);
            written.push_back(path);
        };
        save("eye.png", eyeImage(0));
        if (comparing()) save("eye_b.png", eyeImage(1));
        save("light.png", lightImage());
        save("heatmap.png", heatmapImage_);
        save("dashboard.png", dashboard);
        std::string list;
        for (const auto& p : written) list += (list.empty() ? "" : ", ") + p;
        status_ = "saved " + list;
    } catch (const std::exception& e) {
        status_ = std::string("screenshot failed: ") + e.what();
    }
    return written;
}

} // namespace ui
