#pragma once
#include "render_options.h"

namespace app {
/// No command: the GUI when a display exists, else a headless render into options.out.
int runGuiOrHeadless(const RenderOptions& options);
} // namespace app
