#pragma once
// The interactive window: the dashboard in a GLFW window, with the config file (last settings
// and layout) read at start and written when they change and at exit.
#include "dashboard.h"
#include "geometry/shadow/settings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ui {

struct ViewerOptions {
    std::optional<geometry::shadow::ShadowSettings> settings; // from the command line; else the config's last settings
    std::filesystem::path screenshotDir = "screenshots";
    std::filesystem::path configPath; // empty: configDirectory()/dashboard.json
    bool persist = true;              // read and write the config file
    std::vector<std::string> sceneChoices, presetChoices;
    std::string view; // the canonical view opened at
    size_t light = 0; // --light N: the light inspected at start (the scene's, checked when it loaded)
};

/// Runs until the window closes. Returns the process exit code; throws std::runtime_error when
/// no window can be opened.
int runViewer(LoadedScene scene, const ViewerOptions& options);

} // namespace ui
