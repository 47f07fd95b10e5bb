#include "gui_command.h"

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
        return runRender(headless);
    }
    geometry::Scene scene = loadScene(options);
    ui::ViewerOptions v;
    v.settings = options.settings;
    v.screenshotDir = options.out;
    return ui::runViewer(std::move(scene), v);
}

} // namespace app
