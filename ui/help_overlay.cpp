#include "help_overlay.h"

#include "gesture_table.h"
#include "widget_map.h"

#include <GLFW/glfw3.h> // only the key code checked below
#include <imgui.h>

#include <algorithm>
#include <string>

namespace ui {

static_assert(kHelpKeyIndex == GLFW_KEY_F1, "the GLFW backend stores F1 at its GLFW code");

void HelpOverlay::frame(float width, float height) {
    if (ImGui::IsKeyPressed(kHelpKeyIndex, false)) open_ = !open_;
    if (!open_) return;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
        open_ = false;
        return;
    }
    const float em = ImGui::GetFontSize();
    // Tall enough for every row, the header and the title bar where the window allows (the table
    // scrolls otherwise).
    const ImGuiStyle& style = ImGui::GetStyle();
    const float row = ImGui::GetTextLineHeight() + 2.f * style.CellPadding.y;
    const float rows = float(gestureTable().size()) + 3.f;
    const ImVec2 size(std::min(width - 2.f * em, 60.f * em),
                      std::min(height - 2.f * em, rows * row + ImGui::GetFrameHeight() + 2.f * style.WindowPadding.y));
    ImGui::SetNextWindowPos(ImVec2(width * 0.5f, height * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::max(size.x, 1.f), std::max(size.y, 1.f)), ImGuiCond_Always);
    ImGui::SetNextWindowFocus();
    bool open = true;
    if (ImGui::Begin("Mouse and keys (F1)", &open,
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                         ImGuiWindowFlags_NoResize)) {
        widgetMapRecordRect("help", {ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x,
                                     ImGui::GetWindowSize().y});
        if (ImGui::BeginTable("gestures", 3,
                              ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollY)) {
            ImGui::TableSetupScrollFreeze(0, 1);
            ImGui::TableSetupColumn("Where", ImGuiTableColumnFlags_WidthFixed, 11.f * em);
            ImGui::TableSetupColumn("Gesture or key", ImGuiTableColumnFlags_WidthFixed, 13.f * em);
            ImGui::TableSetupColumn("Does", ImGuiTableColumnFlags_WidthStretch);
            ImGui::TableHeadersRow();
            for (const Gesture& g : gestureTable()) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(g.where.data(), g.where.data() + g.where.size());
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(g.input.data(), g.input.data() + g.input.size());
                // Published per row (the tests check every row is shown).
                widgetMapRecord("help:" + std::string(g.where) + ":" + std::string(g.input));
                ImGui::TableNextColumn();
                ImGui::TextWrapped("%.*s", int(g.action.size()), g.action.data());
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
    if (!open) open_ = false;
}

} // namespace ui
