#pragma once
#include "render_options.h"

#include <nlohmann/json_fwd.hpp>

namespace app {
struct HeadlessFrame;

/// `shadowscope render`: writes DIR/eye.png, DIR/light.png, DIR/metrics.json; prints the paths.
int runRender(const RenderOptions& options);

/// metrics.json content for a rendered frame.
[[nodiscard]] nlohmann::json frameMetrics(const HeadlessFrame& frame, const RenderOptions& options);
} // namespace app
