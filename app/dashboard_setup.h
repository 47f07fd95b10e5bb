#pragma once
// What the dashboard needs from the command line, shared by the GUI and `render --views
// dashboard` so both start from the same scene, settings and pickers (same pixels).
#include "render_options.h"
#include "ui/dashboard.h"

#include <filesystem>
#include <string>
#include <vector>

namespace app {

/// The scene picker's entries: built-in names, then resources/scenes/*.json (sorted).
[[nodiscard]] std::vector<std::string> sceneChoices();
/// The preset picker's entries: resources/presets/*.json (sorted).
[[nodiscard]] std::vector<std::string> presetChoices();

/// options' scene (with --view, --camera, --light applied) and its ray-tracing BVH. Throws like
/// loadScene().
[[nodiscard]] ui::LoadedScene loadDashboardScene(const RenderOptions& options);

/// The dashboard's starting state: A = B = options.settings, camera and light from the scene.
[[nodiscard]] ui::DashboardState initialDashboardState(const ui::LoadedScene& scene, const RenderOptions& options);

/// Dashboard options for the pickers, screenshots into options.out.
[[nodiscard]] ui::DashboardOptions dashboardOptions(const RenderOptions& options);

} // namespace app
