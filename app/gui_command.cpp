#include "gui_command.h"

#include "dashboard_setup.h"
#include "render_command.h"
#include "ui/viewer.h"

#include <cstdlib>
#include <iostream>

namespace app {

static bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (w && *w);
}

int runGuiOrHeadless(const RenderOptions& options) {
    if (!displayAvailable()) {
        std::cout << "no display: rendering " << options.scene << " headless into " << options.out << "/\n";
        RenderOptions headless = options;
        if (headless.backend == "glfw") headless.backend = "auto";
        ExportOptions exports;
        exports.views = {"eye", "light"};
        if (headless.size.width >= 200 && headless.size.height >= 150) exports.views.push_back("dashboard");
        return runRender(headless, exports);
    }
    ui::ViewerOptions v;
    if (options.settingsGiven) v.settings = options.settings;
    v.screenshotDir = options.out;
    v.sceneChoices = sceneChoices();
    v.presetChoices = presetChoices();
    v.view = options.view;
    v.light = options.lightIndex;
    return ui::runViewer(loadDashboardScene(options), v);
}

} // namespace app
