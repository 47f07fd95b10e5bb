// The light list (docs/design.md §3.10): the Lights group of the controls panel (list, Add, Remove,
// type, position, direction, cone, range, radius), the edits it makes, each checked and refused with
// a status line when it would leave an invalid light, and the light gizmo over the eye view.
//
// Index
//   [SECTION] The list ............... initLights, commitSun, lights, inspectedLight, lightViewMaps
//   [SECTION] Edits .................. refuseLight, addLight, removeLight, setLight, inspectLight, resetLights
//   [SECTION] Lights group ........... drawLightsGroup
//   [SECTION] Gizmo .................. drawLightGizmo
#include "dashboard.h"

#include "light_gizmo.h"
#include "light_list.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

namespace ui {

namespace {

using geometry::scene::Light;
using geometry::scene::LightType;

void lightsTip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

std::string lightLabel(size_t i, const Light& l) {
    char buf[96];
    if (l.positional())
        std::snprintf(buf, sizeof buf, "%zu  %s at (%.3g, %.3g, %.3g)", i, geometry::scene::lightTypeName(l.type),
                      double(l.position.x), double(l.position.y), double(l.position.z));
    else std::snprintf(buf, sizeof buf, "%zu  %s", i, geometry::scene::lightTypeName(l.type));
    return buf;
}

} // namespace

// ---- [SECTION] The list ---------------------------------------------------------------------

void Dashboard::initLights() {
    sceneLights_ = scene_.file.scene.lights; // before the frames write the list shown into the scene
    const std::vector<Light>& own = sceneLights_;
    const bool given = !state_.lights.empty() && (state_.lightsScene.empty() || state_.lightsScene == scene_.source);
    const auto problem = given ? lightListProblem(state_.lights) : std::nullopt;
    if (given && !problem) {
        // The state's lights lead (a saved list): the sun angles start from the inspected one.
        state_.inspectedLight = std::clamp(state_.inspectedLight, 0, int(state_.lights.size()) - 1);
        state_.sun = SunAngles::from(state_.lights[size_t(state_.inspectedLight)].direction);
        sunApplied_ = state_.sun;
    } else {
        if (problem) status_ = "lights not used (the scene's stay): " + *problem;
        // The scene's lights, the sun leading as with one light (its angles set the first light).
        state_.lights = own;
        state_.inspectedLight = 0;
        sunApplied_.reset();
    }
    state_.lightsScene = scene_.source;
}

void Dashboard::commitSun() {
    if (state_.lights.empty()) state_.lights = scene_.file.scene.lights;
    state_.inspectedLight = std::clamp(state_.inspectedLight, 0, int(state_.lights.size()) - 1);
    if (sunApplied_ && *sunApplied_ == state_.sun) return;
    state_.lights[size_t(state_.inspectedLight)].direction = state_.sun.direction();
    sunApplied_ = state_.sun;
}

std::vector<Light> Dashboard::lights() const {
    std::vector<Light> out = state_.lights.empty() ? scene_.file.scene.lights : state_.lights;
    if (!sunApplied_ || *sunApplied_ != state_.sun) out[inspectedLight()].direction = state_.sun.direction();
    return out;
}

size_t Dashboard::inspectedLight() const noexcept {
    const size_t n = state_.lights.empty() ? scene_.file.scene.lights.size() : state_.lights.size();
    return size_t(std::clamp(state_.inspectedLight, 0, int(n) - 1));
}

int Dashboard::lightViewMaps() const noexcept { return std::max(1, int(sides_[shownSide()].plan.splits.size())); }

// ---- [SECTION] Edits ------------------------------------------------------------------------

bool Dashboard::refuseLight(const std::string& why) {
    status_ = "light edit refused: " + why;
    return false;
}

bool Dashboard::addLight() {
    commitSun();
    if (state_.lights.size() >= geometry::scene::kMaxLights)
        return refuseLight("a scene holds at most " + std::to_string(geometry::scene::kMaxLights) + " lights");
    state_.lights.push_back(defaultSpotLight(scene_.file.scene.bounds()));
    (void)inspectLight(state_.lights.size() - 1);
    status_ = "added light " + std::to_string(state_.lights.size() - 1) + " (spot)";
    return true;
}

bool Dashboard::removeLight(size_t index) {
    commitSun();
    if (index >= state_.lights.size()) return refuseLight("no light " + std::to_string(index));
    if (state_.lights.size() == 1) return refuseLight("a scene needs at least one light");
    state_.lights.erase(state_.lights.begin() + std::ptrdiff_t(index));
    size_t inspected = size_t(state_.inspectedLight);
    if (index < inspected || inspected >= state_.lights.size()) --inspected;
    state_.inspectedLight = int(inspected);
    state_.sun = SunAngles::from(state_.lights[inspected].direction);
    sunApplied_ = state_.sun;
    status_ = "removed light " + std::to_string(index);
    return true;
}

bool Dashboard::setLight(size_t index, const Light& light) {
    commitSun();
    if (index >= state_.lights.size()) return refuseLight("no light " + std::to_string(index));
    if (auto problem = lightProblem(light)) return refuseLight("light " + std::to_string(index) + ": " + *problem);
    state_.lights[index] = light;
    if (int(index) == state_.inspectedLight) { // the sun angles follow its direction
        state_.sun = SunAngles::from(light.direction);
        sunApplied_ = state_.sun;
    }
    return true;
}

bool Dashboard::inspectLight(size_t index) {
    commitSun(); // the sun's last change stays with the light it was made on
    if (index >= state_.lights.size()) return refuseLight("no light " + std::to_string(index));
    state_.inspectedLight = int(index);
    state_.sun = SunAngles::from(state_.lights[index].direction);
    sunApplied_ = state_.sun;
    return true;
}

void Dashboard::resetLights() {
    state_.lights = sceneLights_;
    (void)inspectLight(0);
    status_ = "lights reset to the scene's";
}

// ---- [SECTION] Lights group -----------------------------------------------------------------

void Dashboard::drawLightsGroup() {
    if (!ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) return;
    commitSun();
    ImGui::PushID("lights");
    const float rows = float(std::min<size_t>(state_.lights.size(), 4));
    if (ImGui::BeginListBox("##list", ImVec2(-FLT_MIN, (rows + 0.25f) * ImGui::GetTextLineHeightWithSpacing()))) {
        for (size_t i = 0; i < state_.lights.size(); ++i) {
            if (ImGui::Selectable(lightLabel(i, state_.lights[i]).c_str(), int(i) == state_.inspectedLight))
                (void)inspectLight(i);
            widgetMapRecord("lights.select" + std::to_string(i));
        }
        ImGui::EndListBox();
    }
    widgetMapRecord("lights.list");
    lightsTip("Select a light to inspect it: drawn last, its maps in the light view, its statistics and heatmaps");
    if (ImGui::Button("Add")) (void)addLight();
    widgetMapRecord("lights.add");
    lightsTip("A spot light above the scene looking down (at most 8 lights)");
    ImGui::SameLine();
    if (ImGui::Button("Remove")) (void)removeLight(size_t(state_.inspectedLight));
    widgetMapRecord("lights.remove");
    lightsTip("Removes the inspected light (a scene keeps at least one)");
    ImGui::SameLine();
    if (ImGui::Button("Reset")) resetLights();
    widgetMapRecord("lights.reset");
    lightsTip("Back to the scene's own lights, as it was loaded (the list saved with the dashboard's config "
              "replaces them when it was made on this scene)");

    const size_t index = size_t(state_.inspectedLight);
    Light l = state_.lights[index];
    const geometry::scene::Aabb S = scene_.file.scene.bounds();
    const float extent = S.empty() ? 10.f : std::max(glm::length(S.hi - S.lo), 1e-3f);
    bool changed = false;
    int type = int(l.type);
    const char* types[] = {"directional", "spot", "point"};
    if (ImGui::Combo("type", &type, types, 3) && type != int(l.type)) {
        if (!l.positional()) { // from a directional light: start above the scene, as Add does
            const Light spot = defaultSpotLight(S);
            l.position = spot.position;
            l.range = spot.range;
        }
        l.type = LightType(type);
        changed = true;
    }
    widgetMapRecord("lights.type");
    if (l.positional()) {
        changed |= ImGui::DragFloat3("position", &l.position.x, 0.002f * extent, 0.f, 0.f, "%.4g");
        widgetMapRecord("lights.position");
        lightsTip("Where the light is (scene units); drag, or Ctrl+click to type");
    }
    if (l.type != LightType::Point) {
        changed |= ImGui::DragFloat3("direction", &l.direction.x, 0.01f, 0.f, 0.f, "%.3f");
        widgetMapRecord("lights.direction");
        lightsTip(l.positional() ? "The cone's axis, from the light into the scene (the sun angles edit it too)"
                                 : "l, from the light into the scene (the sun angles edit it too)");
    }
    if (l.type == LightType::Spot) {
        changed |= ImGui::DragFloat("cone angle", &l.coneDeg, 0.25f, 0.5f, 179.5f, "%.2f°");
        widgetMapRecord("lights.cone");
        lightsTip("Full angle of the cone, in (0, 180)°");
    }
    if (l.positional()) {
        changed |= ImGui::DragFloat("range", &l.range, 0.005f * extent, 0.f, 0.f, "%.4g");
        widgetMapRecord("lights.range");
        lightsTip("Distance beyond which the light reaches nothing; the maps' far plane (> 0)");
        changed |= ImGui::DragFloat("radius", &l.radius, 0.0005f * extent, 0.f, 0.f, "%.4g");
        widgetMapRecord("lights.radius");
        lightsTip("The emitter's radius for the soft truth (≥ 0)");
    }
    if (changed && !(l == state_.lights[index])) (void)setLight(index, l); // refused: the light stays
    ImGui::Checkbox("gizmo over the eye view", &state_.views.lightGizmo);
    widgetMapRecord("lights.gizmo");
    lightsTip("Each light drawn over the eye view: positional lights at their position with their index, spot and "
              "directional lights with an arrow along their direction (directional: from the view centre); the "
              "inspected one highlighted. Not drawn for a single directional light (the sun disc shows it)");
    ImGui::PopID();
}

// ---- [SECTION] Gizmo ------------------------------------------------------------------------

void Dashboard::drawLightGizmo(const Rect& area, int width, int height) {
    if (!state_.views.lightGizmo || area.w < 1.f || area.h < 1.f || width <= 0 || height <= 0) return;
    const std::vector<Light> shown = lights();
    // One directional light alone: the sun disc of Camera & light shows it, and the eye view stays
    // exactly the rendered image (the GUI and the headless dashboard blend overlays' edges a level
    // apart).
    if (shown.size() == 1 && !shown[0].positional()) return;
    const ImageView& view = state_.imageViews[int(ViewPanel::Eye)];
    const std::vector<LightMark> marks =
        lightMarks(scene_.file.scene.camera, glm::vec2(width, height), shown, inspectedLight());
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(ImVec2(area.x, area.y), ImVec2(area.right(), area.bottom()), true);
    const float unit = ImGui::GetFontSize();
    for (const LightMark& m : marks) {
        if (!m.at) continue;
        const auto at = screenAt(view, area, width, height, *m.at);
        if (!at) continue;
        const ImU32 colour = m.inspected ? IM_COL32(255, 210, 60, 255) : IM_COL32(200, 215, 235, 220);
        const ImU32 shadow = IM_COL32(0, 0, 0, 160);
        const ImVec2 p(at->x, at->y);
        const float thick = m.inspected ? 2.5f : 1.5f;
        ImVec2 label(p.x + 0.5f * unit, p.y - 1.2f * unit);
        if (m.direction) {
            // An arrow of a fixed screen length: long from the view centre (directional), short at a spot light.
            const float len = (m.type == LightType::Directional ? 3.5f : 2.2f) * unit;
            const glm::vec2 d = *m.direction, tip = *at + d * len, side(-d.y, d.x);
            const float head = 0.45f * unit;
            const ImVec2 t(tip.x, tip.y),
                h1(tip.x - d.x * head + side.x * head * 0.6f, tip.y - d.y * head + side.y * head * 0.6f),
                h2(tip.x - d.x * head - side.x * head * 0.6f, tip.y - d.y * head - side.y * head * 0.6f);
            dl->AddLine(p, t, shadow, thick + 2.f);
            dl->AddLine(p, t, colour, thick);
            dl->AddTriangleFilled(t, h1, h2, colour);
            if (m.type == LightType::Directional) label = ImVec2(tip.x + 0.3f * unit, tip.y - 0.5f * unit);
        }
        if (m.type != LightType::Directional) {
            const float r = (m.inspected ? 0.45f : 0.35f) * unit;
            dl->AddCircleFilled(p, r + 1.5f, shadow, 16);
            dl->AddCircleFilled(p, r, colour, 16);
        }
        const std::string text = std::to_string(m.index);
        dl->AddText(ImVec2(label.x + 1.f, label.y + 1.f), shadow, text.c_str());
        dl->AddText(label, colour, text.c_str());
    }
    dl->PopClipRect();
}

} // namespace ui
