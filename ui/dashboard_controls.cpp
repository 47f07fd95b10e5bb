// The controls panel: screenshot, export and help buttons, scene picker (file field, browser),
// camera and light, A/B compare with the side being edited, the settings groups generated from the
// declaration, view options, presets (the Lights group: dashboard_lights.cpp).
//
// Index
//   sunGizmo · drawControlsPanel · drawSceneGroup · setNearFar, resetCamera, fitCamera ·
//   drawCameraLightGroup · drawSettingsGroups · drawViewsGroup · drawPresetsGroup
#include "dashboard.h"

#include "geometry/io/preset.h"
#include "geometry/scene/light_angle.h"
#include "settings_panel.h"
#include "widget_map.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace ui {

namespace {

bool inGroup(std::string_view key, const void* ctx) {
    return settingGroup(key) == *static_cast<const std::string*>(ctx);
}

void help(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

/// A disc showing the sun: direction = azimuth, distance from the centre = 90° − elevation.
/// Dragging inside it moves the sun. Returns true when it changed.
bool sunGizmo(SunAngles& sun, float size) {
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("sun_gizmo", ImVec2(size, size));
    widgetMapRecord("sun_gizmo");
    const ImVec2 c(p0.x + size * 0.5f, p0.y + size * 0.5f);
    const float radius = size * 0.5f - 4.f;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddCircleFilled(c, radius, IM_COL32(30, 40, 60, 255), 48);
    dl->AddCircle(c, radius, IM_COL32(140, 140, 150, 255), 48);
    dl->AddCircle(c, radius * 0.5f, IM_COL32(80, 80, 90, 255), 48);
    dl->AddLine(ImVec2(c.x - radius, c.y), ImVec2(c.x + radius, c.y), IM_COL32(80, 80, 90, 255));
    dl->AddLine(ImVec2(c.x, c.y - radius), ImVec2(c.x, c.y + radius), IM_COL32(80, 80, 90, 255));
    bool changed = false;
    if (ImGui::IsItemActive()) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        const float dx = (m.x - c.x) / radius, dy = (m.y - c.y) / radius;
        const float r = std::min(std::sqrt(dx * dx + dy * dy), 1.f);
        sun.elevationDeg = 90.f * (1.f - r);
        if (r > 1e-3f) sun.azimuthDeg = glm::degrees(std::atan2(dx, dy));
        changed = true;
    }
    const float r = radius * std::clamp(1.f - sun.elevationDeg / 90.f, 0.f, 1.f);
    const float az = glm::radians(sun.azimuthDeg);
    dl->AddCircleFilled(ImVec2(c.x + r * std::sin(az), c.y + r * std::cos(az)), 6.f, IM_COL32(255, 210, 60, 255));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Drag: the sun's azimuth (around) and elevation (centre = overhead)");
    return changed;
}

} // namespace

void Dashboard::drawControlsPanel() {
    const Rect& r = rects_.controls;
    ImGui::SetCursorScreenPos(ImVec2(r.x, r.y));
    if (ImGui::BeginChild("controls", ImVec2(std::max(r.w, 1.f), std::max(r.h, 1.f)), true)) {
        // Widgets take what the longest label ("shadow_map.resolution") leaves.
        ImGui::PushItemWidth(-ImGui::CalcTextSize("shadow_map.resolution ").x);
        if (ImGui::Button("Screenshot (F12)")) screenshotRequested_ = true;
        widgetMapRecord("screenshot");
        help("Saves the eye, light and heatmap views and the whole dashboard as PNG, into a new numbered folder");
        ImGui::SameLine();
        if (ImGui::Button("Export…")) openExportDialog();
        widgetMapRecord("export");
        help("One view (eye A or B, light, heatmap, the dashboard) drawn offscreen at a size you choose, as PNG");
        ImGui::SameLine();
        if (ImGui::Button("?")) help_.toggle();
        widgetMapRecord("help_button");
        help("Every mouse gesture and key (F1)");
        drawSceneGroup();
        drawCameraLightGroup();
        drawLightsGroup();
        drawSettingsGroups();
        drawViewsGroup();
        drawPresetsGroup();
        ImGui::PopItemWidth();
    }
    ImGui::EndChild();
}

void Dashboard::drawSceneGroup() {
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const geometry::scene::Scene& scene = scene_.file.scene;
    if (const uint64_t placed = scene.placedTriangleCount(); placed != scene.triangleCount())
        ImGui::Text("%s: %zu triangles (%llu placed by instancing), %zu meshes", scene.name.c_str(),
                    scene.triangleCount(), static_cast<unsigned long long>(placed), scene.meshes.size());
    else ImGui::Text("%s: %zu triangles, %zu meshes", scene.name.c_str(), scene.triangleCount(), scene.meshes.size());
    if (ImGui::BeginCombo("scene", scene_.source.c_str())) {
        for (const auto& choice : options_.sceneChoices) {
            if (ImGui::Selectable(choice.c_str(), choice == scene_.source)) {
                scenePath_ = choice;
                loadScene(choice);
            }
            widgetMapRecord("scene=" + choice);
        }
        ImGui::EndCombo();
    }
    widgetMapRecord("scene");
    help("Built-in scenes and the scene files in resources/scenes");
    // The path gets the panel's whole width (a path does not fit beside a label); the buttons below.
    ImGui::SetNextItemWidth(-FLT_MIN);
    ImGui::InputTextWithHint("##file", "file: a built-in name, scene file or model", &scenePath_);
    widgetMapRecord("scene.file");
    help("A built-in name, a scene file (.json) or a mesh (.obj .stl .off .ply .gltf .glb); or drop a file on the "
         "window");
    if (ImGui::Button("Browse…")) openFileBrowser();
    widgetMapRecord("scene.browse");
    help("Choose a scene or model file (recent files at the top)");
    ImGui::SameLine();
    if (ImGui::Button("Load")) loadScene(scenePath_);
    widgetMapRecord("scene.load");
    const std::string upLabel = upAxis_ ? std::string(geometry::io::upAxisName(*upAxis_)) : "auto (STL z, else y)";
    if (ImGui::BeginCombo("up axis", upLabel.c_str())) {
        const std::optional<geometry::io::UpAxis> choices[] = {std::nullopt,
                                                               geometry::io::UpAxis::Y,
                                                               geometry::io::UpAxis::Z,
                                                               geometry::io::UpAxis::NegY,
                                                               geometry::io::UpAxis::NegZ,
                                                               geometry::io::UpAxis::X,
                                                               geometry::io::UpAxis::NegX};
        for (const auto& choice : choices) {
            const std::string name = choice ? std::string(geometry::io::upAxisName(*choice)) : "auto";
            if (ImGui::Selectable(name.c_str(), choice == upAxis_) && choice != upAxis_) {
                upAxis_ = choice;
                if (geometry::io::isModelFile(scene_.source)) loadScene(scene_.source); // turn it now
            }
            widgetMapRecord("scene.up=" + name);
        }
        ImGui::EndCombo();
    }
    widgetMapRecord("scene.up");
    help("Which axis of a model file points up (CAD exports are often z-up); the model is reloaded turned onto "
         "its base. auto: z for STL, y for the other formats");
    if (loader_.busy()) {
        ImGui::ProgressBar(loader_.progress(), ImVec2(-1, 0), (loader_.stage() + "…").c_str());
        widgetMapRecord("scene.progress");
    }
    if (!scene_.file.views.empty() &&
        ImGui::BeginCombo("view", viewChoice_.empty() ? "(choose)" : viewChoice_.c_str())) {
        for (const auto& [name, view] : scene_.file.views) {
            if (ImGui::Selectable(name.c_str(), name == viewChoice_)) {
                viewChoice_ = name;
                homeCamera_ = view.camera;
                state_.camera = OrbitCamera::from(view.camera);
                scene_.file.scene.camera.fovYDeg = view.camera.fovYDeg;
                scene_.file.scene.camera.near = view.camera.near;
                scene_.file.scene.camera.far = view.camera.far;
                state_.sun = SunAngles::from(view.light.direction);
            }
        }
        ImGui::EndCombo();
    }
    help("The scene file's canonical views (camera + light), as benchmarks and sweeps use them");
}

bool Dashboard::setNearFar(float n, float f) {
    if (!(std::isfinite(n) && std::isfinite(f) && n > 0.f && f > n)) {
        status_ = "near/far refused: need 0 < near < far";
        return false;
    }
    scene_.file.scene.camera.near = n;
    scene_.file.scene.camera.far = f;
    return true;
}

void Dashboard::resetCamera() {
    state_.camera = OrbitCamera::from(homeCamera_);
    scene_.file.scene.camera = homeCamera_; // the lens too: fov, near, far
}

void Dashboard::fitCamera() {
    geometry::scene::Camera& cam = scene_.file.scene.camera;
    const float aspect = eyeSize_.height > 0 ? float(eyeSize_.width) / float(eyeSize_.height) : 16.f / 9.f;
    const geometry::scene::Aabb box = fitBounds(scene_.file.scene);
    state_.camera.fit(box, cam.fovYDeg, aspect);
    // The far plane moves out where the framed box would cross it; near stays (the splits start there).
    const float reach = state_.camera.distance + 0.5f * glm::length(box.hi - box.lo);
    if (!box.empty() && std::isfinite(reach) && cam.far < reach) cam.far = 1.05f * reach;
}

void Dashboard::drawCameraLightGroup() {
    if (!ImGui::CollapsingHeader("Camera & light", ImGuiTreeNodeFlags_DefaultOpen)) return;
    geometry::scene::Camera& cam = scene_.file.scene.camera;
    ImGui::TextWrapped("Eye view: drag to orbit, shift+drag or middle-drag to pan, wheel to dolly, right-drag to "
                       "look and WASD/QE to fly, double-click to fit, shift+click to pin. F1: every gesture.");
    ImGui::SliderFloat("fly speed", &state_.flySpeed, 0.1f, 1000.f, "%.3g units/s", ImGuiSliderFlags_Logarithmic);
    float nearFar[2] = {cam.near, cam.far};
    if (ImGui::InputFloat2("near, far", nearFar, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue))
        (void)setNearFar(nearFar[0], nearFar[1]);
    widgetMapRecord("camera.near_far");
    help("The view frustum's n and f (the splits and warps depend on them)");
    if (ImGui::Button("Reset camera")) resetCamera();
    widgetMapRecord("camera.reset");
    help(viewChoice_.empty() ? "Back to the scene's camera" : ("Back to the camera of view " + viewChoice_).c_str());
    ImGui::Separator();
    ImGui::SliderFloat("sun azimuth", &state_.sun.azimuthDeg, -180.f, 180.f, "%.1f°");
    widgetMapRecord("sun.azimuth");
    help("The inspected light's direction (Lights), as azimuth and elevation of where it comes from");
    ImGui::SliderFloat("sun elevation", &state_.sun.elevationDeg, -89.f, 90.f, "%.1f°");
    widgetMapRecord("sun.elevation");
    sunGizmo(state_.sun, std::min(ImGui::GetContentRegionAvail().x, 9.f * ImGui::GetFontSize()));
    const geometry::shadow::ShadowPlan& plan = sides_[0].plan;
    ImGui::Text("γ = %.2f°  (light–view angle %.2f°)", plan.gammaDeg, plan.lightViewAngleDeg);
    help("γ: the smallest angle between light and view directions (0 = parallel, the dueling frusta when "
         "the light faces the camera)");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.f);
    ImGui::SliderFloat("##target_angle", &targetGammaDeg_, 0.f, 180.f, "%.1f°");
    widgetMapRecord("set_gamma.angle");
    ImGui::SameLine();
    if (ImGui::Button("Set light–view angle")) {
        const glm::vec3 v = cam.target - cam.eye;
        state_.sun = SunAngles::from(geometry::scene::lightAtViewAngle(v, state_.sun.direction(), targetGammaDeg_));
    }
    widgetMapRecord("set_gamma");
    help("Turns the light about the eye so it makes this angle with the view direction (0: from behind the eye, "
         "90: across, 180: facing the camera); γ = min(angle, 180 − angle)");
}

void Dashboard::drawSettingsGroups() {
    // A/B compare and the side being edited together, above the groups they apply to.
    ImGui::Separator();
    int mode = int(state_.views.compare);
    const char* modes[] = {"off", "side by side", "split screen"};
    if (ImGui::Combo("A/B compare", &mode, modes, 3)) state_.views.compare = CompareMode(mode);
    widgetMapRecord("views.compare");
    help("Two settings sets on the same camera: side by side, or one image split by a draggable divider. "
         "The heatmap's 'difference' shows m_A / m_B");
    if (comparing()) {
        ImGui::TextUnformatted("Editing:");
        ImGui::SameLine();
        ImGui::RadioButton("A", &state_.editing, 0);
        widgetMapRecord("edit.a");
        ImGui::SameLine();
        ImGui::RadioButton("B", &state_.editing, 1);
        widgetMapRecord("edit.b");
        ImGui::SameLine();
        if (ImGui::SmallButton("A→B")) state_.settings[1] = state_.settings[0];
        ImGui::SameLine();
        if (ImGui::SmallButton("B→A")) state_.settings[0] = state_.settings[1];
        ImGui::SameLine();
        if (ImGui::SmallButton("swap")) std::swap(state_.settings[0], state_.settings[1]);
    } else {
        state_.editing = 0;
    }
    geometry::shadow::ShadowSettings& s = state_.settings[std::clamp(state_.editing, 0, 1)];
    for (const std::string& group : controlGroups()) {
        if (group == "Scene" || group == "Camera & light" || group == "Views") continue;
        if (!ImGui::CollapsingHeader(group.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
        ImGui::PushID(group.c_str());
        std::string error;
        drawSettingsWidgets(s, inGroup, &group, &error);
        if (!error.empty()) status_ = error;
        if (group == "Partitions") {
            const geometry::shadow::ShadowPlan& plan = sides_[std::clamp(state_.editing, 0, 1)].plan;
            for (size_t i = 0; i < plan.splits.size(); ++i) {
                const auto& sp = plan.splits[i];
                ImGui::TextDisabled("split %zu: [%.3g, %.3g]  n' %s  res %d%s", i, sp.near, sp.far,
                                    sp.warped() ? std::to_string(sp.nPrime).c_str() : "∞ (uniform)", sp.resolution,
                                    sp.empty() ? "  empty" : "");
            }
        }
        ImGui::PopID();
    }
}

void Dashboard::drawViewsGroup() {
    if (!ImGui::CollapsingHeader("Views", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ViewSettings& v = state_.views;
    ImGui::Checkbox("overlays", &v.overlays);
    widgetMapRecord("views.overlays");
    help("Frusta, focus bodies B_i and the warp's projection P drawn over the light view");
    ImGui::Checkbox("unwarped light view", &v.unwarped);
    widgetMapRecord("views.unwarped");
    help("The light view without the warp: where the warp spends its texels");
    ImGui::Checkbox("ground truth", &v.truth);
    widgetMapRecord("views.truth");
    help("Ray-trace every receiver pixel towards the light (Embree) for the truth heatmap and statistics");
    ImGui::SliderInt("truth samples", &v.truthSamples, 1, 4, "%d per axis", ImGuiSliderFlags_AlwaysClamp);
    widgetMapRecord("views.truth_samples");
    help("N x N truth rays over each pixel's footprint: the truth's lit fraction becomes a coverage (reports use 4)");
    ImGui::SliderFloat("heatmap blend", &v.heatmapBlend, 0.f, 1.f, "%.2f");
    help("Mix the eye image under the heatmap (0: heatmap alone)");
    ImGui::SliderInt("texel grid", &v.texelGrid, 1, 64, "every %d", ImGuiSliderFlags_AlwaysClamp);
    help("Texels heatmap: a grid line every N shadow-map texels");
}

void Dashboard::drawPresetsGroup() {
    if (!ImGui::CollapsingHeader("Presets", ImGuiTreeNodeFlags_DefaultOpen)) return;
    geometry::shadow::ShadowSettings& s = state_.settings[std::clamp(state_.editing, 0, 1)];
    if (ImGui::BeginCombo("preset", "(choose)")) {
        for (const auto& choice : options_.presetChoices) {
            if (ImGui::Selectable(choice.c_str())) {
                presetPath_ = choice;
                try {
                    s = geometry::io::loadPreset(choice);
                    status_ = "loaded preset " + choice;
                } catch (const std::exception& e) {
                    status_ = e.what();
                }
            }
            widgetMapRecord("preset=" + choice);
        }
        ImGui::EndCombo();
    }
    widgetMapRecord("preset");
    ImGui::InputText("preset file", &presetPath_);
    widgetMapRecord("preset.file");
    if (ImGui::Button("Load preset")) {
        try {
            s = geometry::io::loadPreset(presetPath_);
            status_ = "loaded preset " + presetPath_;
        } catch (const std::exception& e) {
            status_ = e.what(); // the settings stay as they were
        }
    }
    widgetMapRecord("preset.load");
    ImGui::SameLine();
    if (ImGui::Button("Save preset")) {
        try {
            geometry::io::savePreset(presetPath_, s, std::filesystem::path(presetPath_).stem().string());
            status_ = "saved preset " + presetPath_;
        } catch (const std::exception& e) {
            status_ = e.what();
        }
    }
    widgetMapRecord("preset.save");
    help("The same JSON files as --preset");
}

} // namespace ui
