#pragma once
// The interactive window: eye view and light view side by side, orbit camera, light control.
#include "geometry/scene.h"
#include "geometry/settings.h"

#include <string>

namespace ui {

struct ViewerOptions {
    geometry::ShadowSettings settings;
    std::string screenshotDir = "out";
};

/// Runs until the window closes. Returns the process exit code; throws std::runtime_error when
/// no window can be opened.
int runViewer(geometry::Scene scene, const ViewerOptions& options);

} // namespace ui
