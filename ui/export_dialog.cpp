#include "export_dialog.h"

#include "modal_footer.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>

namespace ui {

std::string_view exportViewName(ExportView v) noexcept {
    switch (v) {
    case ExportView::EyeA: return "eye_a";
    case ExportView::EyeB: return "eye_b";
    case ExportView::Light: return "light";
    case ExportView::Heatmap: return "heatmap";
    case ExportView::Dashboard: return "dashboard";
    case ExportView::Count: break;
    }
    return "?";
}

std::string exportSizeProblem(ExportView view, int width, int height) {
    const int minW = view == ExportView::Dashboard ? 200 : kExportMinSide;
    const int minH = view == ExportView::Dashboard ? 150 : kExportMinSide;
    if (width >= minW && height >= minH && width <= kExportMaxSide && height <= kExportMaxSide) return "";
    return std::to_string(width) + "x" + std::to_string(height) + " is outside " + std::to_string(minW) + "x" +
           std::to_string(minH) + " … " + std::to_string(kExportMaxSide) + "x" + std::to_string(kExportMaxSide);
}

std::optional<ExportRequest>
ExportDialog::frame(float width, float height, const std::array<std::array<int, 2>, size_t(ExportView::Count)>& panels,
                    bool comparing) {
    constexpr const char* kTitle = "Export a view";
    if (!open_) return std::nullopt;
    if (popupPending_) {
        ImGui::OpenPopup(kTitle);
        popupPending_ = false;
        problem_.clear();
    }
    ImGui::SetNextWindowPos(ImVec2(width * 0.5f, height * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    bool keepOpen = true;
    if (!ImGui::BeginPopupModal(kTitle, &keepOpen,
                                ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
        open_ = false;
        return std::nullopt;
    }
    if (!comparing && request_.view == ExportView::EyeB) request_.view = ExportView::EyeA;
    const char* const labels[] = {"eye A", "eye B", "light", "heatmap", "dashboard"};
    for (int i = 0; i < int(ExportView::Count); ++i) {
        if (i == int(ExportView::EyeB) && !comparing) continue; // B exists while comparing
        if (i > 0) ImGui::SameLine();
        int view = int(request_.view);
        if (ImGui::RadioButton(labels[i], &view, i)) request_.view = ExportView(view);
        widgetMapRecord("export.view=" + std::string(exportViewName(ExportView(i))));
    }
    const std::array<int, 2> panel = panels[size_t(request_.view)];
    const std::string twice = "2x panel (" + std::to_string(2 * panel[0]) + "x" + std::to_string(2 * panel[1]) + ")";
    const char* const presets[] = {"1920x1080", "3840x2160", twice.c_str(), "custom"};
    for (int i = 0; i < 4; ++i) {
        if (i > 0) ImGui::SameLine();
        ImGui::RadioButton(presets[i], &preset_, i);
        widgetMapRecord("export.size=" + std::to_string(i));
    }
    if (preset_ == 3) {
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.f);
        ImGui::InputInt2("width, height", custom_);
        widgetMapRecord("export.custom");
    }
    const std::array<int, 2> sizes[] = {
        {1920, 1080}, {3840, 2160}, {2 * panel[0], 2 * panel[1]}, {custom_[0], custom_[1]}};
    request_.width = sizes[preset_][0];
    request_.height = sizes[preset_][1];
    ImGui::TextDisabled("Drawn offscreen at %d x %d with the current settings, as `shadowscope render` draws it",
                        request_.width, request_.height);
    if (!problem_.empty()) ImGui::TextColored(ImVec4(1.f, 0.5f, 0.4f, 1.f), "%s", problem_.c_str());
    std::optional<ExportRequest> chosen;
    if (ImGui::Button("Export")) {
        problem_ = exportSizeProblem(request_.view, request_.width, request_.height);
        if (problem_.empty()) {
            chosen = request_;
            open_ = false;
        }
    }
    widgetMapRecord("export.go");
    ImGui::SameLine();
    endModal(open_, keepOpen, "export");
    return chosen;
}

} // namespace ui
