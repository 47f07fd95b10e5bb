#include "dashboard_setup.h"

#include "app/resources.h"

#include "geometry/scene/builtin_scenes.h"

#include <algorithm>
#include <system_error>

namespace app {

namespace fs = std::filesystem;

namespace {
std::vector<std::string> jsonFiles(const fs::path& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.path().extension() == ".json") out.push_back(entry.path().string());
    std::sort(out.begin(), out.end());
    return out;
}
} // namespace

std::vector<std::string> sceneChoices() {
    std::vector<std::string> out = geometry::scene::builtinSceneNames();
    if (const fs::path r = resourceDirectory(); !r.empty())
        for (auto& f : jsonFiles(r / "scenes")) out.push_back(std::move(f));
    return out;
}

std::vector<std::string> presetChoices() {
    const fs::path r = resourceDirectory();
    return r.empty() ? std::vector<std::string>{} : jsonFiles(r / "presets");
}

ui::LoadedScene loadDashboardScene(const RenderOptions& options) {
    ui::LoadedScene loaded;
    loaded.source = options.scene;
    loaded.file = loadSceneFile(options);
    loaded.truth = std::make_unique<geometry::analysis::GroundTruth>(
        geometry::analysis::GroundTruth::borrowing(loaded.file.scene));
    return loaded;
}

ui::DashboardState initialDashboardState(const ui::LoadedScene& scene, const RenderOptions& options) {
    ui::DashboardState s;
    s.settings[0] = s.settings[1] = options.settings;
    s.camera = ui::OrbitCamera::from(scene.file.scene.camera);
    // Every light of the scene, --light N inspected (checked against the scene when it loaded).
    const auto& lights = scene.file.scene.lights;
    s.lights = lights;
    s.inspectedLight = int(std::min(options.lightIndex, lights.size() - 1));
    s.sun = ui::SunAngles::from(lights[size_t(s.inspectedLight)].direction);
    return s;
}

ui::DashboardOptions dashboardOptions(const RenderOptions& options) {
    ui::DashboardOptions d;
    d.screenshotDir = options.out;
    d.sceneChoices = sceneChoices();
    d.presetChoices = presetChoices();
    d.view = options.view;
    d.up = options.up;
    return d;
}

} // namespace app
