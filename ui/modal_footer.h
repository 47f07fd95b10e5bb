#pragma once
// The end of the dashboard's modal dialogs (file browser, export): a Cancel button that Escape
// also presses, then the popup closed when the dialog is done or its title bar's close button
// was used. Call inside BeginPopupModal's block; it ends the popup.
#include "widget_map.h"

#include <imgui.h>

#include <string>

namespace ui {

/// `open`: the dialog's state, set false by Cancel/Escape; `keepOpen`: BeginPopupModal's p_open
/// (false once its close button was pressed); `id`: the dialog's name in the widget map.
inline void endModal(bool& open, bool keepOpen, const std::string& id) {
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) open = false;
    widgetMapRecord(id + ".cancel");
    if (!open || !keepOpen) {
        open = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

} // namespace ui
