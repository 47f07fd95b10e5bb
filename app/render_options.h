#pragma once
// Options shared by every command that renders (render, and later bench, sweep, the GUI's
// start-up): declared once here.
#include "geometry/scene.h"
#include "geometry/shadow_plan.h"

#include <optional>
#include <string>

namespace CLI { class App; }

namespace app {

struct RenderOptions {
    std::string scene = "platform";
    geometry::Viewport size{1280, 720};
    std::string out = "out";
    std::string backend = "auto";
    std::optional<geometry::Camera> camera;         // eye + target overrides
    std::optional<glm::vec3> light;                 // l overrides
    geometry::ShadowSettings settings;             // --shadow-res, --set key=value
};

/// Adds --scene, --size, --out, --backend, --camera, --light, --shadow-res, --set to `cmd`.
void addRenderOptions(CLI::App& cmd, RenderOptions& options);

/// Adds the repeatable --set key=value option for shadow settings (keys from settingsDeclaration()).
void addSettingOption(CLI::App& cmd, geometry::ShadowSettings& settings);

/// The scene named by options.scene with the camera and light overrides applied.
/// Throws std::invalid_argument with a one-line reason.
[[nodiscard]] geometry::Scene loadScene(const RenderOptions& options);

} // namespace app
