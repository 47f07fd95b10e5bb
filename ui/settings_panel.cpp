#include "settings_panel.h"

#include "text_fit.h"
#include "widget_map.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <type_traits>

namespace ui {

namespace {

using Kind = geometry::shadow::SettingInfo::Kind;

/// An Int or Float row's slider (ImGui's scalar slider on T), logarithmic when the row says so.
/// No AlwaysClamp: a typed out-of-range value must be refused with a message, not silently turned
/// into something else.
template <typename T>
bool numberSlider(const geometry::shadow::SettingInfo& info, const std::string& label, double& value) {
    constexpr bool isInt = std::is_same_v<T, int>;
    T v = static_cast<T>(value);
    const T lo = static_cast<T>(info.min), hi = static_cast<T>(info.max);
    const ImGuiSliderFlags flags = info.logScale ? ImGuiSliderFlags_Logarithmic : 0;
    const char* format = isInt ? "%d" : "%.4g";
    const float frameW = ImGui::CalcItemWidth();
    // (The style's slider grab is translucent, so the value drawn over it stays readable: imgui_setup.cpp.)
    const bool edited = ImGui::SliderScalar(label.c_str(), isInt ? ImGuiDataType_S32 : ImGuiDataType_Float, &v, &lo,
                                            &hi, format, flags);
    char text[32];
    if constexpr (isInt) std::snprintf(text, sizeof text, format, v);
    else std::snprintf(text, sizeof text, format, double(v));
    if (textFitEnabled())
        textFitRecordText("settings value:" + std::string(info.key), text,
                          frameW - 2.f * ImGui::GetStyle().FramePadding.x);
    value = v;
    return edited;
}

/// The row's widget; `value` in and out; true when the user changed it this frame.
bool valueWidget(const geometry::shadow::SettingInfo& info, const std::string& label, double& value) {
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
        const int shown = std::clamp(index, 0, int(info.choices.size()) - 1);
        if (textFitEnabled())
            textFitRecordText("settings value:" + std::string(info.key), info.choices[shown],
                              ImGui::CalcItemWidth() - ImGui::GetFrameHeight() -
                                  2.f * ImGui::GetStyle().FramePadding.x);
        if (ImGui::BeginCombo(label.c_str(), std::string(info.choices[shown]).c_str())) {
            for (int i = 0; i < int(info.choices.size()); ++i) {
                if (ImGui::Selectable(std::string(info.choices[i]).c_str(), i == index)) index = i, edited = true;
                widgetMapRecord(std::string(info.key) + "=" + std::string(info.choices[i]));
            }
            ImGui::EndCombo();
        }
        value = index;
        break;
    }
    case Kind::Int: {
        edited = numberSlider<int>(info, label, value);
        const int v = static_cast<int>(value);
        if (edited && info.odd && v % 2 == 0 && v >= info.min && v <= info.max)
            value = v + 1 <= int(info.max) ? v + 1 : v - 1; // odd-only keys snap
        break;
    }
    case Kind::Float: edited = numberSlider<float>(info, label, value); break;
    }
    return edited;
}

/// A value typed into a slider's text field (ctrl+click) counts once, when the field closes with an
/// edit: ImGui reports every keystroke, and "9" on the way to "999" must not apply. Returns whether
/// `value` is to be applied now.
bool typedValueComplete(const geometry::shadow::SettingInfo& info, const std::string& label, bool edited,
                        double& value) {
    static std::map<std::string, double> typed;
    if (ImGui::IsItemActive() && ImGui::GetIO().WantTextInput && (info.kind == Kind::Int || info.kind == Kind::Float)) {
        if (edited) typed[label] = value;
        return false;
    }
    const auto it = typed.find(label);
    if (it == typed.end()) return edited;
    // The field closed (Return, or a click elsewhere) since the last keystroke; Escape cancels. An
    // edit in the closing frame itself (the last digit and Return together) is the freshest value.
    const bool escaped = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false) ||
                         ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (!escaped && !edited) value = it->second;
    typed.erase(it);
    return !escaped || edited;
}

/// Help, range, and why the row is greyed (the setting that makes it inert).
void rowTooltip(const geometry::shadow::SettingInfo& info, const geometry::shadow::ShadowSettings& settings,
                bool applies) {
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
    std::string inert;
    if (const auto* by = applies ? nullptr : geometry::shadow::findSetting(info.governedBy))
        inert = "\nNo effect with " + std::string(info.governedBy) + " = " + by->format(settings);
    ImGui::SetTooltip("%s\n%s (ctrl+click to type a value)%s", info.help.c_str(), info.rangeText().c_str(),
                      inert.c_str());
}

/// Where the rows' keys go: beside the widgets when the panel leaves each widget a minimum width
/// next to the group's widest key, else on their own line above full-width widgets. Sized from the
/// text at the current font and scale (issue 32: keys were cut at the panel's edge).
struct RowLayout {
    bool inlineLabels = true;
    float itemWidth = 0, labelBox = 0;
};

RowLayout rowLayout(bool (*inGroup)(std::string_view, const void*), const void* ctx) {
    const ImGuiStyle& style = ImGui::GetStyle();
    float widest = 0, widestChoice = 0;
    for (const auto& info : geometry::shadow::settingsDeclaration()) {
        if (inGroup && !inGroup(info.key, ctx)) continue;
        widest = std::max(widest, ImGui::CalcTextSize(info.key.data(), info.key.data() + info.key.size()).x);
        for (const std::string_view c : info.choices)
            widestChoice = std::max(widestChoice, ImGui::CalcTextSize(c.data(), c.data() + c.size()).x);
    }
    // Wide enough for any choice name and for a slider whose grab leaves its value readable.
    const float minWidget =
        std::max(8.f * ImGui::GetFontSize(), widestChoice + ImGui::GetFrameHeight() + 2.f * style.FramePadding.x);
    const float avail = ImGui::GetContentRegionAvail().x;
    const float beside = avail - widest - style.ItemInnerSpacing.x;
    if (beside >= minWidget) return {true, beside, widest};
    return {false, avail, avail};
}

/// Draws the key above the widget when the layout says so; sets the widget's width; returns the
/// widget's ImGui label.
std::string rowLabel(const std::string& key, const RowLayout& layout) {
    const float box = layout.inlineLabels
                          ? ImGui::GetContentRegionAvail().x - layout.itemWidth - ImGui::GetStyle().ItemInnerSpacing.x
                          : ImGui::GetContentRegionAvail().x;
    if (textFitEnabled()) textFitRecordText("settings:" + key, key, box);
    if (layout.inlineLabels) {
        ImGui::SetNextItemWidth(layout.itemWidth);
        return key;
    }
    ImGui::TextUnformatted(key.c_str());
    ImGui::SetNextItemWidth(layout.itemWidth);
    return "##" + key;
}

} // namespace

bool drawSettingsWidgets(geometry::shadow::ShadowSettings& settings, bool (*inGroup)(std::string_view, const void*),
                         const void* ctx, std::string* error) {
    bool changed = false;
    const RowLayout layout = rowLayout(inGroup, ctx);
    for (const auto& info : geometry::shadow::settingsDeclaration()) {
        if (inGroup && !inGroup(info.key, ctx)) continue;
        const std::string label(info.key);
        double value = info.get(settings);
        // Greyed, and closed to input, while the other settings make it inert (its row's `when`).
        const bool applies = info.appliesTo(settings);
        if (!applies) ImGui::BeginDisabled();
        bool edited = valueWidget(info, rowLabel(label, layout), value);
        widgetMapRecord(label);
        edited = typedValueComplete(info, label, edited, value);
        if (!applies) ImGui::EndDisabled();
        rowTooltip(info, settings, applies);
        if (!edited) continue;
        if (std::isfinite(value) && value >= info.min && value <= info.max) {
            info.set(settings, value);
            changed = true;
        } else if (error) {
            char text[32];
            std::snprintf(text, sizeof text, "%.10g", value);
            *error = label + ": " + (std::isfinite(value) ? std::string(text) : std::string("not a number")) +
                     " refused (" + info.rangeText() + "); kept " + info.format(settings);
        }
    }
    return changed;
}

bool drawSettingsWidgets(geometry::shadow::ShadowSettings& settings) {
    return drawSettingsWidgets(settings, nullptr, nullptr, nullptr);
}

} // namespace ui
