#pragma once
// The dashboard's persistent state: the last settings (A and B), the view options, the window
// layout, the light list (with the scene it belongs to; "lights": {"scene", "inspected", "list"},
// each light as a scene file writes one) and the recent files ("recent_files", newest first), in
// $XDG_CONFIG_HOME/shadowscope/dashboard.json (default ~/.config/shadowscope). The settings use the
// preset layout (geometry/io/preset.h), so a config's "settings" object is a preset.
#include "dashboard_state.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace ui {

/// $XDG_CONFIG_HOME/shadowscope, else $HOME/.config/shadowscope; empty when neither is set.
[[nodiscard]] std::filesystem::path configDirectory();

/// Window size kept with the layout.
struct WindowGeometry {
    int width = 1600, height = 900;
};

[[nodiscard]] nlohmann::json dashboardToJson(const DashboardState& state, const WindowGeometry& window);

/// Applies a config object over `state` and `window`. Throws std::invalid_argument (one line,
/// naming the key) for wrong types, unknown choices, out-of-range values or a light lightProblem()
/// rejects (ui/light_list.h); nothing is applied then.
void dashboardFromJson(const nlohmann::json& j, DashboardState& state, WindowGeometry& window);

/// Loads `path` over state and window. A missing file is not an error (nullopt); a corrupt one
/// leaves both untouched and returns the one-line reason.
[[nodiscard]] std::optional<std::string> loadDashboardConfig(const std::filesystem::path& path, DashboardState& state,
                                                             WindowGeometry& window);
/// Writes atomically (a temporary file renamed over the old one); returns the reason on failure.
[[nodiscard]] std::optional<std::string> saveDashboardConfig(const std::filesystem::path& path,
                                                             const DashboardState& state, const WindowGeometry& window);

} // namespace ui
