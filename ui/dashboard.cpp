#include "dashboard.h"

#include "file_list.h"
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

namespace ui {

const std::vector<std::string>& controlGroups() {
    static const std::vector<std::string> groups = {"Scene", "Camera & light", "Warp", "Partitions",
                                                    "Bias",  "Filtering",      "Views"};
    return groups;
}

std::string settingGroup(std::string_view key) {
    if (key == "technique" || key.starts_with("virtual.") || key.starts_with("warp.") ||
        key.starts_with("shadow_map.") || key.starts_with("stabilize."))
        return "Warp";
    if (key.starts_with("splits.") || key.starts_with("focus.") || key.starts_with("casters.")) return "Partitions";
    if (key.starts_with("bias.")) return "Bias";
    if (key.starts_with("filter.") || key.starts_with("light."))
        return "Filtering"; // the sun size sets PCSS's penumbra
    return "Views";
}

Dashboard::Dashboard(LoadedScene scene, DashboardState state, DashboardOptions options)
    : scene_(std::move(scene)), state_(std::move(state)), options_(std::move(options)) {
    sides_[0].renderer = std::make_unique<renderer::Renderer>(scene_.file.scene);
    scenePath_ = scene_.source;
    viewChoice_ = options_.view;
    homeCamera_ = scene_.file.scene.camera;
    upAxis_ = options_.up;
    initLights();
}

Dashboard::~Dashboard() {
    casterLod_.cancel();
    cancelInspections();
    finishBackgroundWork(); // the workers read the scene's ground truth
}

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
    casterLod_.cancel(); // its build reads the scene being replaced
    cancelInspections();
    finishBackgroundWork(); // … and so do the inspections (its ground truth)
    scene_ = std::move(loaded);
    homeCamera_ = scene_.file.scene.camera;
    for (Side& s : sides_)
        if (s.renderer) s.renderer->setScene(scene_.file.scene);
    state_.camera = OrbitCamera::from(scene_.file.scene.camera);
    state_.sun = SunAngles::from(scene_.file.scene.lights[0].direction);
    state_.lights.clear(); // the new scene's
    initLights();
    ++sceneGeneration_;
    viewChoice_.clear();
    hovered_.reset();
    pinned_.reset();
    status_ = "loaded " + scene_.source + " (" + std::to_string(scene_.file.scene.triangleCount()) + " triangles)";
    // Files (not built-in names) become recent ones, however they were opened: field, browser, drop.
    std::error_code ec;
    if (std::filesystem::is_regular_file(scene_.source, ec)) {
        const std::string path = std::filesystem::absolute(scene_.source, ec).lexically_normal().string();
        state_.recentFiles = withRecentFile(state_.recentFiles, path);
    }
}

void Dashboard::applyCameraInput(const FrameInput& input) {
    const ImGuiIO& io = ImGui::GetIO();
    flying_ = flyLooking_ && glm::length(input.fly) > 0.f; // right mouse held on the eye view, WASD/QE
    if (flying_) {
        const float step = state_.flySpeed * std::clamp(input.deltaSeconds, 0.f, 0.25f);
        state_.camera.fly(input.fly.z * step, input.fly.x * step, input.fly.y * step);
    }
    const glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
    if (cameraDragging_ && (delta.x != 0.f || delta.y != 0.f)) {
        const bool left = ImGui::IsMouseDown(ImGuiMouseButton_Left),
                   middle = ImGui::IsMouseDown(ImGuiMouseButton_Middle);
        if (left && !io.KeyShift && !io.KeyCtrl) state_.camera.rotate(delta.x, delta.y);
        else if (middle || (left && io.KeyShift))
            state_.camera.pan(delta.x, delta.y, cameraAreaHeight_, scene_.file.scene.camera.fovYDeg);
        else if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) state_.camera.look(delta.x, delta.y);
    }
    if (cameraHovered_ && io.MouseWheel != 0.f && !io.KeyCtrl) state_.camera.zoom(io.MouseWheel);
    // Recorded again by this frame's eye panel.
    cameraHovered_ = cameraDragging_ = flyLooking_ = false;
}

namespace {

Rect contentArea(const Rect& panel, float header, float pad) noexcept {
    return {panel.x + pad, panel.y + header, std::max(0.f, panel.w - 2.f * pad), std::max(0.f, panel.h - header - pad)};
}

} // namespace

void Dashboard::frame(float width, float height, const FrameInput& input) {
    const auto t0 = std::chrono::steady_clock::now();
    screenshotRequested_ = input.screenshot;
    pollSceneLoad();
    if (pendingExport_) { // before this frame's widgets: the dashboard export draws its own frames
        (void)exportView(*pendingExport_);
        pendingExport_.reset();
    }
    rects_ = layoutDashboard(width, height, state_.layout, options_.uiScale);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float pad = style.WindowPadding.x;
    const float header = pad + ImGui::GetFrameHeight() + style.ItemSpacing.y;
    eyeArea_ = contentArea(rects_.eye, header, pad);
    lightArea_ = contentArea(rects_.light, header, pad);
    heatmapArea_ = contentArea(rects_.heatmap, header, pad);
    lightViewSize_ = std::clamp(int(std::min(lightArea_.w, lightArea_.h)), 16, 2048);

    stepCasterLod();
    applyCameraInput(input);
    renderViews();
    // GPU times arrive a frame or more after their passes: poll them while the views stand still,
    // so the stats panel's GPU rows fill in without waiting for the next change.
    // The shadow row keeps the time of the frame that last drew the maps (later ones reuse them).
    gpuTimesInFlight_ = false;
    for (Side& s : sides_) {
        if (!s.renderer) continue;
        if (s.renderer->pollGpuTimes()) gpuTimesInFlight_ = true;
        if (const double ms = s.renderer->lastDrawnGpuMs(renderer::Pass::Shadow); std::isfinite(ms)) s.shadowGpuMs = ms;
    }
    const MeasureContext measuring = measureContext();
    if (auto status = sweep_.step(measuring)) status_ = std::move(*status);
    if (auto status = recommend_.step(measuring)) status_ = std::move(*status);
    pollInspections();
    updateInspection();
    updateHeatmap();
    refreshPin(); // before anything shows it: a pin follows every change of view, settings and scene

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
    drawDialogs(width, height);
    // What the next frame draws at: coarse while this frame's input drags, dollies or flies.
    const ImGuiIO& io = ImGui::GetIO();
    const bool dragging = ImGui::IsAnyItemActive() && (io.MouseDown[0] || io.MouseDown[1] || io.MouseDown[2]);
    continuousInput_ = dragging || io.MouseWheel != 0.f || flying_;
    widgetMapCounter("passes.shadow", double(counts_.shadow));
    widgetMapCounter("passes.eye_full", double(counts_.eyeFull));
    widgetMapCounter("passes.eye_coarse", double(counts_.eyeCoarse));
    widgetMapCounter("passes.inspections", double(counts_.inspections));
    widgetMapCounter("coarse", coarse() ? 1.0 : 0.0);
    widgetMapCounter("statistics_pending", sides_[0].job || sides_[1].job ? 1.0 : 0.0);
    widgetMapCounter("text_input", io.WantTextInput ? 1.0 : 0.0); // keys go to a field, not to flying
    // What the stats and inspector show, for the end-to-end tests of "nothing stale" (issue 32).
    if (const renderer::FrameStats* st = frameStats(0);
        st && st->gpu.valid && st->gpu.drawn[size_t(renderer::Pass::Eye)])
        widgetMapCounter("gpu.eye_ms", st->gpu.of(renderer::Pass::Eye));
    if (std::isfinite(sides_[0].shadowGpuMs)) widgetMapCounter("gpu.shadow_ms", sides_[0].shadowGpuMs);
    if (pinned_) {
        widgetMapCounter("pin.x", pinned_->pixel.x);
        widgetMapCounter("pin.y", pinned_->pixel.y);
        if (std::isfinite(pinned_->viewDepth)) widgetMapCounter("pin.view_depth", pinned_->viewDepth);
    }
    widgetMapEndFrame();
    cpuFrameMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
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
        // A new folder each time: documentation screenshots are never overwritten.
        const std::filesystem::path dir = createNumberedFolder(options_.screenshotDir);
        const auto save = [&](const char* name, const geometry::analysis::Image& img) {
            if (img.width <= 0 || img.height <= 0) return;
            const std::string path = (dir / name).string();
            geometry::analysis::writePng(path, img);
            written.push_back(path);
        };
        save("eye.png", eyeImage(0));
        if (comparing()) save("eye_b.png", eyeImage(1));
        save("light.png", lightImage());
        save("heatmap.png", geometry::analysis::withLegend(heatmapImage_, heatmapLegend_));
        save("dashboard.png", dashboard);
        std::string list;
        for (const auto& p : written) list += (list.empty() ? "" : ", ") + std::filesystem::path(p).filename().string();
        status_ = "saved " + dir.string() + "/: " + list;
    } catch (const std::exception& e) {
        status_ = std::string("screenshot failed: ") + e.what();
    }
    return written;
}

} // namespace ui
