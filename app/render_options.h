#pragma once
// Options shared by every command that renders (render, bench, sweep, the GUI's start-up):
// declared once here.
#include "geometry/io/scene_file.h"
#include "geometry/scene/scene.h"
#include "geometry/shadow/shadow_plan.h"

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct RenderOptions {
    std::string scene = "platform";         // built-in name, scene file (.json) or model file
    std::string view;                       // a canonical view of the scene; empty: the scene's camera
    std::optional<geometry::io::UpAxis> up; // --up: a model file's up axis; empty: its format's default
    geometry::shadow::Viewport size{1280, 720};
    std::string out = "out";
    std::string backend = "auto";
    std::optional<geometry::scene::Camera> camera; // eye + target overrides
    std::optional<glm::vec3> light;                // --light dx,dy,dz: the inspected light's l overrides
    size_t lightIndex = 0;                         // --light N: the light inspected (light view, reports)
    geometry::shadow::ShadowSettings settings;     // --preset FILE, --shadow-res, --set
    bool settingsGiven = false;                    // any of those three was on the command line key=value
    // OptionUse::Bench only: every --view, every --preset (each one configuration), every --set.
    std::vector<std::string> views, presets, assignments;
};

/// How a command uses the shared options.
enum class OptionUse {
    /// One --view; --preset files, --shadow-res and --set layer onto one `settings`; --camera and
    /// --light override the view; every backend.
    Render,
    /// Configurations measured side by side: --view repeats (into `views`), each --preset is one
    /// configuration (into `presets`), --set applies to all of them (into `assignments`); headless
    /// backends only; no --camera, --light or --shadow-res.
    Bench,
};

/// "WxH" with 1 ≤ W, H ≤ 16384; throws std::invalid_argument naming --size otherwise.
[[nodiscard]] geometry::shadow::Viewport parseSize(const std::string& text);

/// Adds --scene, --view, --size, --out, --backend, --camera, --light, --preset, --shadow-res, --set to `cmd`
/// (for OptionUse::Bench the first five, --preset and --set, as that use describes). Defaults are the
/// values `options` holds when this is called. For OptionUse::Render, after parsing, options.settings
/// is: its value when this was called, then every --preset file (in command-line order), then
/// --shadow-res, then every --set (in command-line order), whatever the order of those options on the
/// command line; untouched when none of the three is given.
void addRenderOptions(CLI::App& cmd, RenderOptions& options, OptionUse use = OptionUse::Render);

/// Ground truth as a command asks for it: --truth and --truth-samples N (N × N rays per pixel).
struct TruthOptions {
    bool enabled = false;
    int samples = 1; // per axis
};

/// Adds --truth (`truthHelp`; none when empty: the command always traces truth) and --truth-samples.
void addTruthOptions(CLI::App& cmd, TruthOptions& truth, const std::string& truthHelp);
/// --up AXIS (y, z, -y, -z, x, -x) into `up`; another value is a CLI error (exit 2).
void addUpOption(CLI::App& cmd, std::optional<geometry::io::UpAxis>& up, const std::string& help);

/// --backend NAME into `backend`: auto (EGL on a GPU, else OSMesa), osmesa, egl, and with `window` also glfw;
/// another value is a CLI error (exit 2).
void addBackendOption(CLI::App& cmd, std::string& backend, bool window);

/// Adds the repeatable --set key=value option for shadow settings (keys from settingsDeclaration()),
/// applied directly to `settings`; for commands without --preset.
void addSettingOption(CLI::App& cmd, geometry::shadow::ShadowSettings& settings);

/// The scene named by options.scene (geometry::resolveScene: a built-in name, a scene file or a
/// model file), seen from options.view when given, with the camera and light overrides applied
/// last. Loads that take longer than half a second show a progress line on stderr (a terminal
/// only). Throws std::invalid_argument (unknown view) or std::runtime_error (the scene does not
/// load), each with a one-line reason.
[[nodiscard]] geometry::scene::Scene loadScene(const RenderOptions& options);
/// loadScene() keeping the whole scene file (its canonical views and paths) around the scene.
[[nodiscard]] geometry::io::SceneFile loadSceneFile(const RenderOptions& options);
/// loadSceneFile() in two steps, for a command that renders one scene from several views: the scene
/// as its file describes it (options.scene and options.up only; throws std::runtime_error), then
/// options.view, camera and light applied to it (throws std::invalid_argument for an unknown view).
[[nodiscard]] geometry::io::SceneFile resolveSceneFile(const RenderOptions& options);
void applyView(geometry::io::SceneFile& file, const RenderOptions& options);

/// Throws std::invalid_argument (one line) when the scene has no light `index` (--light N).
void checkLightIndex(size_t index, const geometry::scene::Scene& scene);

} // namespace app
