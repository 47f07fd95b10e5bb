// The dashboard's view panels (eye, light, heatmap) with zoom, pan and the pixel inspector; the
// splitters between panels; the status bar.
//
// Index
//   [SECTION] Drawing helpers ................ drawImage, markPixel, panelBegin, header rows (header_fit.h),
//                                              zoomButtons, pinClick, sideLabel
//   [SECTION] Image areas and pixel probes ... imageArea, probeEye, probeLight, refreshPin
//   [SECTION] View panels .................... drawEyePanel, drawLightPanel, drawHeatmapPanel
//   [SECTION] Splitters ...................... drawSplitters
//   [SECTION] Status bar ..................... describeProbe, drawStatusBar
#include "dashboard.h"

#include "header_fit.h"
#include "heatmap_legend.h"
#include "text_fit.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ui {

namespace {

// ---- [SECTION] Drawing helpers --------------------------------------------------------------

ImTextureID textureId(GLuint t) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t)); }
ImVec2 iv(glm::vec2 v) { return {v.x, v.y}; }

/// Draws the part of a placed image between image fractions u0 and u1 (for split-screen compare).
void drawImage(ImDrawList* dl, GLuint texture, const ImagePlacement& p, float u0 = 0.f, float u1 = 1.f) {
    if (p.screen.w <= 0.f || p.screen.h <= 0.f) return;
    const float a = std::max(p.uvMin.x, u0), b = std::min(p.uvMax.x, u1);
    if (b <= a) return;
    const float span = p.uvMax.x - p.uvMin.x;
    const float x0 = p.screen.x + (a - p.uvMin.x) / span * p.screen.w;
    const float x1 = p.screen.x + (b - p.uvMin.x) / span * p.screen.w;
    // GL textures are bottom row first: flip v.
    dl->AddImage(textureId(texture), ImVec2(x0, p.screen.y), ImVec2(x1, p.screen.bottom()), ImVec2(a, 1.f - p.uvMin.y),
                 ImVec2(b, 1.f - p.uvMax.y));
}

/// Outline of image pixel `px` on screen (the pinned pixel's marker).
void markPixel(ImDrawList* dl, const ImageView& view, const Rect& area, int w, int h, glm::ivec2 px) {
    const ImagePlacement p = placeImage(view, area, w, h);
    if (p.screen.w <= 0.f) return;
    const glm::vec2 origin = glm::vec2(p.screen.x, p.screen.y) - p.uvMin * glm::vec2(w, h) * p.scale;
    const glm::vec2 a = origin + glm::vec2(px) * p.scale, b = a + glm::vec2(std::max(p.scale, 3.f));
    dl->AddRect(iv(a - 2.f), iv(b + 2.f), IM_COL32(255, 255, 0, 255), 0.f, 0, 1.5f);
}

bool panelBegin(const char* id, const Rect& r) {
    ImGui::SetCursorScreenPos(ImVec2(r.x, r.y));
    return ImGui::BeginChild(id, ImVec2(std::max(r.w, 1.f), std::max(r.h, 1.f)), true,
                             ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
}

/// Records the last item's extent against the room left on its row (text_fit.h): a header that
/// does not fit its panel shows in the legibility test.
void recordHeaderItem(const std::string& id, const std::string& text) {
    if (!textFitEnabled()) return;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    textFitRecord("header:" + id, text, ImGui::GetItemRectSize().x, right - ImGui::GetItemRectMin().x);
}

/// The zoom of an image as its header shows it.
std::string zoomText(const ImageView& view) {
    if (!(view.zoom > 0.f)) return "fit";
    char text[32];
    std::snprintf(text, sizeof text, "%.0f%%", double(view.zoom) * 100.0);
    return text;
}

/// A header row's pieces at the current font (header_fit.h); the widget's widths are the caller's.
HeaderItems headerItems(const std::string& title, const std::string& shortTitle, const ImageView& view,
                        float widgetPreferred = 0.f, float widgetMin = 0.f) {
    const ImGuiStyle& st = ImGui::GetStyle();
    const auto button = [&](const char* t) { return ImGui::CalcTextSize(t).x + 2.f * st.FramePadding.x; };
    HeaderItems h;
    h.title = ImGui::CalcTextSize(title.c_str()).x;
    h.shortTitle = ImGui::CalcTextSize(shortTitle.c_str()).x;
    h.widgetPreferred = widgetPreferred;
    h.widgetMin = widgetMin;
    h.zoomButtons = button("Fit") + st.ItemSpacing.x + button("1:1");
    h.zoomText = ImGui::CalcTextSize(zoomText(view).c_str()).x;
    h.spacing = st.ItemSpacing.x;
    return h;
}

/// The title a fitted header shows, drawn and recorded.
void headerTitle(const char* id, const std::string& title, const std::string& shortTitle, const HeaderFit& fit) {
    const std::string& text = fit.shortTitle ? shortTitle : title;
    ImGui::TextUnformatted(text.c_str());
    recordHeaderItem(std::string(id) + ".title", text);
}

void zoomButtons(ImageView& view, const char* id, bool showZoomText = true) {
    ImGui::PushID(id);
    ImGui::SameLine();
    if (ImGui::SmallButton("Fit")) view = ImageView{};
    widgetMapRecord(std::string(id) + ".fit");
    recordHeaderItem(std::string(id) + ".fit", "Fit");
    ImGui::SameLine();
    if (ImGui::SmallButton("1:1")) view = oneToOne(view);
    widgetMapRecord(std::string(id) + ".one_to_one");
    recordHeaderItem(std::string(id) + ".one_to_one", "1:1");
    if (showZoomText) {
        const std::string text = zoomText(view);
        ImGui::SameLine();
        ImGui::TextDisabled("%s", text.c_str());
        recordHeaderItem(std::string(id) + ".zoom", text);
    }
    ImGui::PopID();
}

/// Shift and a left click that did not drag (a drag orbits or pans): pins the pixel under the
/// cursor. A gesture of its own, so that a double-click (fit) pins nothing on the way.
bool pinClick() {
    const ImGuiIO& io = ImGui::GetIO();
    return io.KeyShift && ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 16.f;
}

/// "A" or "B" in the top right corner of an image area while comparing: which side the view shows.
void sideLabel(const Rect& area, int side) {
    const char* text = side == 0 ? "A" : "B";
    const ImVec2 size = ImGui::CalcTextSize(text), at(area.right() - size.x - 8.f, area.y + 5.f);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(ImVec2(at.x - 3.f, at.y - 1.f), ImVec2(at.x + size.x + 3.f, at.y + size.y + 1.f),
                      IM_COL32(0, 0, 0, 150), 2.f);
    dl->AddText(at, IM_COL32(255, 255, 255, 235), text);
}

} // namespace

// ---- [SECTION] Image areas and pixel probes -------------------------------------------------

std::optional<glm::ivec2> Dashboard::imageArea(ViewPanel panel, GLuint texture, int w, int h, const Rect& area,
                                               bool cameraControls, const char* id) {
    if (area.w < 1.f || area.h < 1.f || w <= 0 || h <= 0) return std::nullopt;
    ImageView& view = state_.imageViews[int(panel)];
    ImGui::SetCursorScreenPos(ImVec2(area.x, area.y));
    ImGui::InvisibleButton(id, ImVec2(area.w, area.h),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    widgetMapRecord(id);
    const bool hovered = ImGui::IsItemHovered(), active = ImGui::IsItemActive();
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 mouse(io.MousePos.x, io.MousePos.y), delta(io.MouseDelta.x, io.MouseDelta.y);
    // The camera moves in applyCameraInput(), before the frame draws, from what this records; the
    // image's own zoom and pan (ctrl, and the other panels) happen here.
    if (cameraControls) {
        cameraHovered_ = cameraHovered_ || hovered;
        cameraDragging_ = cameraDragging_ || active;
        cameraAreaHeight_ = area.h;
        flyLooking_ = flyLooking_ || (active && ImGui::IsMouseDown(ImGuiMouseButton_Right));
    }
    if (hovered && io.MouseWheel != 0.f && (!cameraControls || io.KeyCtrl))
        view = zoomAround(view, area, w, h, mouse, std::pow(1.25f, io.MouseWheel));
    if (active && (delta.x != 0.f || delta.y != 0.f)) {
        const bool left = ImGui::IsMouseDown(ImGuiMouseButton_Left),
                   middle = ImGui::IsMouseDown(ImGuiMouseButton_Middle);
        if (cameraControls ? left && io.KeyCtrl : left || middle) view = panBy(view, area, w, h, delta);
    }
    if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        view = ImageView{};
        if (cameraControls) fitCamera(); // the eye view: the whole scene in view
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(ImVec2(area.x, area.y), ImVec2(area.right(), area.bottom()), IM_COL32(20, 20, 22, 255));
    drawImage(dl, texture, placeImage(view, area, w, h));
    return hovered ? pixelAt(view, area, w, h, mouse) : std::nullopt;
}

PixelProbe Dashboard::probeEye(int side, glm::ivec2 px, ViewPanel panel) const {
    const Side& s = sides_[side];
    PixelProbe p;
    p.panel = panel;
    p.side = side;
    p.pixel = px;
    if (s.inspection && px.x < s.inspection->width && px.y < s.inspection->height) {
        const geometry::analysis::Inspection& in = *s.inspection;
        const size_t i = size_t(px.y) * in.width + px.x;
        p.sky = in.aux[i].z < 0.f;
        p.receiver = in.receiver[i] != 0;
        p.shadow = in.shadow[i];
        p.m = in.m[i];
        p.texel = {in.aux[i].x, in.aux[i].y};
        p.split = int(in.aux[i].z);
        p.mapDepth = in.aux[i].w;
        p.position = in.positions[i];
        const geometry::scene::Camera& cam = scene_.file.scene.camera;
        p.viewDepth = glm::dot(p.position - cam.eye, glm::normalize(cam.target - cam.eye));
        if (in.occluded) p.truthShadowed = (*in.occluded)[i] != 0;
    }
    return p;
}

PixelProbe Dashboard::probeLight(glm::ivec2 px) {
    PixelProbe p;
    p.panel = ViewPanel::Light;
    p.side = shownSide();
    p.pixel = px;
    const Side& s = sides_[p.side];
    const int split = std::clamp(state_.views.lightSplit, 0, std::max(0, int(s.plan.splits.size()) - 1));
    p.split = split;
    if (!state_.views.unwarped && split < int(s.plan.splits.size()) && s.renderer) {
        const int res = std::min(s.plan.splits[split].resolution, s.renderer->stats().shadowResolution);
        // The light view shows the split's map, its bottom row at the image's bottom.
        p.mapTexel = {px.x * res / lightViewSize_, (lightViewSize_ - 1 - px.y) * res / lightViewSize_};
        p.storedDepth = s.renderer->readShadowDepth(split, p.mapTexel.x, p.mapTexel.y);
    }
    return p;
}

void Dashboard::refreshPin() {
    if (!pinned_) return;
    const PixelProbe at = *pinned_;
    pinned_ = at.panel == ViewPanel::Light ? probeLight(at.pixel) : probeEye(at.side, at.pixel, at.panel);
}

// ---- [SECTION] View panels ------------------------------------------------------------------

void Dashboard::drawEyePanel() {
    if (panelBegin("eye_panel", rects_.eye)) {
        const CompareMode mode = state_.views.compare;
        const std::string title = mode == CompareMode::Off          ? "Eye view"
                                  : mode == CompareMode::SideBySide ? "Eye view: A | B"
                                                                    : "Eye view: A / B split";
        const std::string shortTitle = mode == CompareMode::Off ? "Eye" : "Eye A|B";
        ImageView& eyeView = state_.imageViews[int(ViewPanel::Eye)];
        const HeaderFit fit = fitHeader(headerItems(title, shortTitle, eyeView), ImGui::GetContentRegionAvail().x);
        headerTitle("eye", title, shortTitle, fit);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Drag: orbit. Shift+drag or middle-drag: pan. Right-drag: look, with WASD/QE to fly.\n"
                "Wheel: dolly. Ctrl+wheel: zoom the image around the cursor, ctrl+drag: pan it.\n"
                "Shift+click: pin the pixel in the inspector. Double-click: fit the camera to the scene.\n"
                "F1: every gesture and key.");
        zoomButtons(eyeView, "eye", fit.zoomText);
        const ImageView& view = eyeView;
        const geometry::shadow::Viewport size = sides_[0].size;
        const bool clicked = pinClick();
        if (mode == CompareMode::SideBySide && sides_[1].renderer) {
            const float half = std::floor((eyeArea_.w - 2.f) * 0.5f);
            const Rect left{eyeArea_.x, eyeArea_.y, half, eyeArea_.h};
            const Rect right{eyeArea_.x + half + 2.f, eyeArea_.y, half, eyeArea_.h};
            for (int i = 0; i < 2; ++i) {
                const Rect& r = i == 0 ? left : right;
                const auto px = imageArea(ViewPanel::Eye, sides_[i].renderer->eyeTexture(), size.width, size.height, r,
                                          true, i == 0 ? "eye_image" : "eye_image_b");
                sideLabel(r, i);
                if (px) {
                    hovered_ = probeEye(i, *px, ViewPanel::Eye);
                    if (clicked) pinned_ = hovered_;
                }
            }
        } else {
            const auto px = imageArea(ViewPanel::Eye, sides_[0].renderer->eyeTexture(), size.width, size.height,
                                      eyeArea_, true, "eye_image");
            if (mode == CompareMode::Split && sides_[1].renderer) {
                // B over the right part, a draggable divider between them.
                ImDrawList* dl = ImGui::GetWindowDrawList();
                const ImagePlacement place = placeImage(view, eyeArea_, size.width, size.height);
                float& s = state_.views.splitPosition;
                drawImage(dl, sides_[1].renderer->eyeTexture(), place, s, 1.f);
                const float span = std::max(place.uvMax.x - place.uvMin.x, 1e-6f);
                const float x = place.screen.x +
                                (std::clamp(s, place.uvMin.x, place.uvMax.x) - place.uvMin.x) / span * place.screen.w;
                dl->AddLine(ImVec2(x, eyeArea_.y), ImVec2(x, eyeArea_.bottom()), IM_COL32(255, 255, 255, 220), 2.f);
                dl->AddText(ImVec2(x - 18, eyeArea_.y + 4), IM_COL32(255, 255, 255, 230), "A");
                dl->AddText(ImVec2(x + 8, eyeArea_.y + 4), IM_COL32(255, 255, 255, 230), "B");
                ImGui::SetCursorScreenPos(ImVec2(x - 5, eyeArea_.y + eyeArea_.h * 0.4f));
                ImGui::InvisibleButton("compare_divider", ImVec2(10, eyeArea_.h * 0.2f));
                widgetMapRecord("compare_divider");
                if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
                if (ImGui::IsItemActive() && place.screen.w > 0.f)
                    s = std::clamp(s + ImGui::GetIO().MouseDelta.x / place.screen.w * span, 0.f, 1.f);
                dl->AddRectFilled(ImVec2(x - 4, eyeArea_.y + eyeArea_.h * 0.45f),
                                  ImVec2(x + 4, eyeArea_.y + eyeArea_.h * 0.55f), IM_COL32(255, 255, 255, 200), 2.f);
            }
            if (px) {
                const bool onB =
                    mode == CompareMode::Split && float(px->x) >= state_.views.splitPosition * float(size.width);
                hovered_ = probeEye(onB ? 1 : 0, *px, ViewPanel::Eye);
                if (clicked) pinned_ = hovered_;
            }
        }
        if (pinned_ && pinned_->panel != ViewPanel::Light && mode != CompareMode::SideBySide)
            markPixel(ImGui::GetWindowDrawList(), view, eyeArea_, size.width, size.height, pinned_->pixel);
        if (mode == CompareMode::SideBySide && sides_[1].renderer) {
            const float half = std::floor((eyeArea_.w - 2.f) * 0.5f);
            drawLightGizmo({eyeArea_.x, eyeArea_.y, half, eyeArea_.h}, size.width, size.height);
            drawLightGizmo({eyeArea_.x + half + 2.f, eyeArea_.y, half, eyeArea_.h}, size.width, size.height);
        } else {
            drawLightGizmo(eyeArea_, size.width, size.height);
        }
    }
    ImGui::EndChild();
}

void Dashboard::drawLightPanel() {
    if (panelBegin("light_panel", rects_.light)) {
        const Side& side = sides_[shownSide()];
        // The inspected light's maps: a directional light's splits, a spot light's one map, a point
        // light's six cube faces.
        const geometry::scene::LightType type = side.plan.light.type;
        const bool several = lights().size() > 1;
        // While comparing, the side shown (the one being edited) is named in the title and the image.
        const std::string sideName = !comparing() ? "" : shownSide() == 0 ? ", A" : ", B";
        const std::string title =
            several ? "Light " + std::to_string(inspectedLight()) + " (" +
                          std::string(geometry::scene::lightTypeName(type)) +
                          (state_.views.unwarped ? " unwarped" : "") + ")" + sideName
                    : std::string("Light view (") + (state_.views.unwarped ? "unwarped" : "warped") + sideName + ")";
        const std::string shortTitle = "Light" + (several ? " " + std::to_string(inspectedLight()) : "") + sideName;
        ImageView& lightView = state_.imageViews[int(ViewPanel::Light)];
        const float em = ImGui::GetFontSize();
        const HeaderFit fit = fitHeader(headerItems(title, shortTitle, lightView, std::max(60.f, em * 6.f), em * 3.5f),
                                        ImGui::GetContentRegionAvail().x);
        headerTitle("light", title, shortTitle, fit);
        if (comparing()) widgetMapRecord(shownSide() == 0 ? "light.side=A" : "light.side=B");
        ImGui::SameLine();
        const int splits = lightViewMaps();
        ImGui::SetNextItemWidth(fit.widget);
        int split = std::clamp(state_.views.lightSplit, 0, splits - 1);
        const char* format = type == geometry::scene::LightType::Point  ? "face %d"
                             : type == geometry::scene::LightType::Spot ? "map %d"
                                                                        : "split %d";
        if (ImGui::SliderInt("##split", &split, 0, splits - 1, format)) state_.views.lightSplit = split;
        widgetMapRecord("views.light_split");
        recordHeaderItem("light.split", "split slider");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Which of the inspected light's maps the light view shows: a split, a spot light's map, "
                              "or a point light's cube face (+X, −X, +Y, −Y, +Z, −Z)");
        zoomButtons(lightView, "light", fit.zoomText);
        if (side.renderer) {
            const GLuint tex =
                state_.views.unwarped ? side.renderer->unwarpedLightTexture() : side.renderer->lightTexture();
            const auto px =
                imageArea(ViewPanel::Light, tex, lightViewSize_, lightViewSize_, lightArea_, false, "light_image");
            if (comparing()) sideLabel(lightArea_, shownSide());
            if (px) {
                hovered_ = probeLight(*px);
                if (pinClick()) pinned_ = hovered_;
            }
        }
    }
    ImGui::EndChild();
}

void Dashboard::drawHeatmapPanel() {
    if (panelBegin("heatmap_panel", rects_.heatmap)) {
        const int side = shownSide();
        const std::string title = !comparing() ? "Heatmap" : side == 0 ? "Heatmap, A" : "Heatmap, B";
        const std::string shortTitle = !comparing() ? "Heat" : side == 0 ? "Heat, A" : "Heat, B";
        ImageView& heatView = state_.imageViews[int(ViewPanel::Heatmap)];
        // The combo keeps room for its longest name and the arrow.
        float longest = 0.f;
        for (int i = 0; i < int(HeatmapKind::Count); ++i)
            longest = std::max(longest, ImGui::CalcTextSize(std::string(heatmapName(HeatmapKind(i))).c_str()).x);
        const float comboMin = longest + ImGui::GetFrameHeight() + 2.f * ImGui::GetStyle().FramePadding.x;
        const HeaderFit fit = fitHeader(
            headerItems(title, shortTitle, heatView, std::max(comboMin, ImGui::GetFontSize() * 8.f), comboMin),
            ImGui::GetContentRegionAvail().x);
        headerTitle("heatmap", title, shortTitle, fit);
        if (comparing()) widgetMapRecord(side == 0 ? "heatmap.side=A" : "heatmap.side=B");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(fit.widget);
        if (ImGui::BeginCombo("##heatmap", std::string(heatmapName(state_.views.heatmap)).c_str())) {
            for (int i = 0; i < int(HeatmapKind::Count); ++i) {
                const std::string name(heatmapName(HeatmapKind(i)));
                if (ImGui::Selectable(name.c_str(), int(state_.views.heatmap) == i))
                    state_.views.heatmap = HeatmapKind(i);
                widgetMapRecord("views.heatmap=" + name);
            }
            ImGui::EndCombo();
        }
        widgetMapRecord("views.heatmap");
        recordHeaderItem("heatmap.kind", std::string(heatmapName(state_.views.heatmap)));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("aliasing: log2 m; truth: interior false shadow red, false lit blue, edge errors amber, "
                              "ambiguous teal; splits; texels: the map's "
                              "texel grid; difference: m_A / m_B (A/B compare); soft: s - v against the sun's disk "
                              "(truth with light.angular_diameter_deg > 0)");
        zoomButtons(heatView, "heatmap", fit.zoomText);
        const auto px = imageArea(ViewPanel::Heatmap, heatmap_.id(), heatmap_.width(), heatmap_.height(), heatmapArea_,
                                  false, "heatmap_image");
        drawHeatmapLegend(heatmapLegend_, heatmapArea_);
        const HeatmapKind kind = state_.views.heatmap;
        const bool needsTruth = (kind == HeatmapKind::Truth || kind == HeatmapKind::Soft) && !state_.views.truth;
        const bool needsSun =
            kind == HeatmapKind::Soft && !(state_.settings[size_t(side)].light.angularDiameterDeg > 0.f);
        const bool needsCompare = kind == HeatmapKind::Difference && !comparing();
        if (comparing() && kind != HeatmapKind::Difference) sideLabel(heatmapArea_, side);
        if (needsTruth || needsSun || needsCompare)
            ImGui::GetWindowDrawList()->AddText(ImVec2(heatmapArea_.x + 8, heatmapArea_.y + 8),
                                                IM_COL32(255, 255, 255, 255),
                                                needsTruth ? "turn on ground truth (Views)"
                                                : needsSun ? "give the sun a size (light.angular_diameter_deg)"
                                                           : "turn on A/B compare (Views)");
        if (px) {
            hovered_ = probeEye(side, *px, ViewPanel::Heatmap);
            if (pinClick()) pinned_ = hovered_;
        }
        if (pinned_ && pinned_->panel != ViewPanel::Light)
            markPixel(ImGui::GetWindowDrawList(), state_.imageViews[int(ViewPanel::Heatmap)], heatmapArea_,
                      heatmap_.width(), heatmap_.height(), pinned_->pixel);
    }
    ImGui::EndChild();
}

// ---- [SECTION] Splitters --------------------------------------------------------------------

void Dashboard::drawSplitters(float width, float height) {
    for (int i = 0; i < int(Splitter::Count); ++i) {
        const Rect& r = rects_.splitters[i];
        if (r.w < 1.f || r.h < 1.f) continue;
        ImGui::SetCursorScreenPos(ImVec2(r.x, r.y));
        ImGui::PushID(i);
        ImGui::InvisibleButton("splitter", ImVec2(r.w, r.h));
        ImGui::PopID();
        const bool vertical = Splitter(i) != Splitter::Stats;
        if (ImGui::IsItemHovered() || ImGui::IsItemActive())
            ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
        if (ImGui::IsItemActive()) {
            const ImVec2 d = ImGui::GetIO().MouseDelta;
            state_.layout = dragSplitter(state_.layout, Splitter(i), d.x, d.y, width, height, options_.uiScale);
        }
        const ImU32 colour = ImGui::IsItemActive() ? IM_COL32(120, 150, 220, 255) : IM_COL32(60, 60, 66, 255);
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.right(), r.bottom()), colour);
    }
}

// ---- [SECTION] Status bar -------------------------------------------------------------------

std::string describeProbe(const PixelProbe& p) {
    char buf[512];
    if (p.panel == ViewPanel::Light) {
        std::snprintf(buf, sizeof buf, "light (%d, %d)  split %d  map texel (%d, %d)  stored depth %.6f", p.pixel.x,
                      p.pixel.y, p.split, p.mapTexel.x, p.mapTexel.y, p.storedDepth);
        return buf;
    }
    if (p.sky) {
        std::snprintf(buf, sizeof buf, "%s %s(%d, %d)  sky", p.panel == ViewPanel::Eye ? "eye" : "heatmap",
                      p.side ? "B " : "", p.pixel.x, p.pixel.y);
        return buf;
    }
    std::snprintf(buf, sizeof buf,
                  "%s %s(%d, %d)  depth %.4g  split %d  m %.4g  s %.3f  truth %s  texel (%.1f, %.1f)  map depth %.6f%s",
                  p.panel == ViewPanel::Eye ? "eye" : "heatmap", p.side ? "B " : "", p.pixel.x, p.pixel.y, p.viewDepth,
                  p.split, p.m, p.shadow, p.truthShadowed ? (*p.truthShadowed ? "shadow" : "lit") : "off", p.texel.x,
                  p.texel.y, p.mapDepth, p.receiver ? "" : "  (not a receiver)");
    return buf;
}

void Dashboard::drawStatusBar() {
    const Rect& r = rects_.status;
    if (r.h < 1.f) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.right(), r.bottom()), IM_COL32(32, 34, 40, 255));
    ImGui::SetCursorScreenPos(ImVec2(r.x + 6.f, r.y + std::max(0.f, (r.h - ImGui::GetTextLineHeight()) * 0.5f)));
    std::string text = hovered_ ? describeProbe(*hovered_)
                                : std::string("hover a view for exact values, shift+click to pin, F1: help");
    if (loader_.busy())
        text = "loading " + loader_.source() + ": " + loader_.stage() + " " +
               std::to_string(int(loader_.progress() * 100.f)) + "%";
    if (coarse()) {
        const int d = std::max(sides_[0].coarseDivisor, sides_[1].coarseDivisor);
        text += "   |   coarse view (1/" + std::to_string(d) + " resolution), refining when input pauses";
    } else if (sides_[0].job || sides_[1].job) {
        text += "   |   statistics: recomputing";
    }
    if (!status_.empty()) text += "   |   " + status_;
    ImGui::TextUnformatted(text.c_str());
    widgetMapStatus(status_);
    if (hovered_) { // the e2e tests compare it with the pin (nothing stale, issue 32)
        widgetMapCounter("hover.x", hovered_->pixel.x);
        widgetMapCounter("hover.y", hovered_->pixel.y);
        if (std::isfinite(hovered_->viewDepth)) widgetMapCounter("hover.view_depth", hovered_->viewDepth);
    }
    hovered_.reset(); // set again next frame while the cursor stays on a view
}

} // namespace ui
