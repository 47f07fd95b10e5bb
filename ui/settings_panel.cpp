#include "settings_panel.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace ui {

bool drawSettingsWidgets(geometry::ShadowSettings& settings) {
    using Kind = geometry::SettingInfo::Kind;
    bool changed = false;
    for (const auto& info : geometry::settingsDeclaration()) {
        const std::string label(info.key);
        double value = info.get(settings);
        bool edited = false;
        switch (info.kind) {
        case Kind::Bool: {
            bool b = value != 0.0;
            edited = ImGui::Checkbox(label.c_str(), &b);
            value = b ? 1.0 : 0.0;
            break;
        }
        case Kind::Choice: {
            int index = static_cast<int>(value);
            if (ImGui::BeginCombo(label.c_str(), std::string(info.choices[std::clamp(index, 0, int(info.choices.size()) - 1)]).c_str())) {
                for (int i = 0; i < int(info.choices.size()); ++i)
                    if (ImGui::Selectable(std::string(info.choices[i]).c_str(), i == index)) index = i, edited = true;
                ImGui::EndCombo();
            }
            value = index;
            break;
        }
        case Kind::Int: {
            int v = static_cast<int>(value);
            const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (info.logScale ? ImGuiSliderFlags_Logarithmic : 0);
            edited = ImGui::SliderInt(label.c_str(), &v, int(info.min), int(info.max), "%d", flags);
            if (info.odd && v % 2 == 0) v = v + 1 <= int(info.max) ? v + 1 : v - 1; // odd-only keys snap
            value = v;
            break;
        }
        case Kind::Float: {
            float v = static_cast<float>(value);
            const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (info.logScale ? ImGuiSliderFlags_Logarithmic : 0);
            edited = ImGui::SliderFloat(label.c_str(), &v, float(info.min), float(info.max), "%.4g", flags);
            value = v;
            break;
        }
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n(%s)", std::string(info.help).c_str(), info.rangeText().c_str());
        if (edited && value >= info.min && value <= info.max) {
            info.set(settings, value);
            changed = true;
        }
    }
    return changed;
}

} // namespace ui
