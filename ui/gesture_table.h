#pragma once
// Every mouse gesture and key of the dashboard, as one table: the help overlay (F1, "?") draws it,
// the tests check that each row is shown, and docs/design.md quotes it. A gesture added to the
// dashboard gets its row here.
#include <string_view>
#include <vector>

namespace ui {

struct Gesture {
    std::string_view where;  // "Eye view", "Light view, heatmap", "Sliders", "Keys", …
    std::string_view input;  // "Shift+click", "Wheel", "F12", …
    std::string_view action; // what it does
};

[[nodiscard]] const std::vector<Gesture>& gestureTable();

/// The help key's index in ImGuiIO::KeysDown: the GLFW backend (imgui_impl_glfw, ImGui 1.86) stores
/// keys by their GLFW code, and 1.86 has no ImGuiKey for F1. GLFW_KEY_F1 = 290; the headless
/// dashboard's tests press it the same way.
inline constexpr int kHelpKeyIndex = 290;

} // namespace ui
